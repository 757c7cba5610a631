// particleizeMold on small gmsh geometries written in the tests: a box, a cylinder and a cone
// (frustum), each an OpenCASCADE volume whose walls (all faces but the open top) are the patch.
#include "geometry/MoldParticleization.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <sstream>

#include "core/dictionary/SourceLocation.h"
#include "particles/FieldNames.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

using testing::TemporaryCase;

std::string moldDict(double spacing, int layers, const std::string& mode = "shell",
                     const std::string& patch = "walls", const std::string& extra = "") {
  std::ostringstream dict;
  dict << "FoamFile { version 2.0; format ascii; class dictionary; object particleizeMoldDict; }\n"
       << "geometry (\"mold.geo\");\nspacing " << spacing << ";\nwallLayers " << layers << ";\n"
       << extra << "patches\n{\n    " << patch << " { cloud mold; type fixedWall; mode " << mode
       << "; }\n}\n";
  return dict.str();
}

// An OCC solid `shape` (e.g. "Box(1) = {...};") whose surfaces but the top are "walls".
std::string moldGeo(const std::string& shape, const std::string& wallSurfaces) {
  return "SetFactory(\"OpenCASCADE\");\n" + shape + "\nPhysical Surface(\"walls\") = {" +
         wallSurfaces + "};\nPhysical Volume(\"cavity\") = {1};\n";
}

ParticleizedMold particleize(const std::string& geo, const std::string& dict) {
  TemporaryCase mold;
  mold.write("constant/geometry/mold.geo", geo);
  mold.write("system/particleizeMoldDict", dict);
  return particleizeMold(CaseFolder(mold.root()));
}

double angleDegrees(const Vector& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.cast<double>().normalized().dot(b.normalized()), -1.0, 1.0)) *
         180.0 / std::numbers::pi;
}

// Largest distance from a point of the wall (sampled every dx/5) to its nearest wall particle.
double largestGap(const ParticleCloud& cloud, const std::vector<Eigen::Vector3d>& wallSamples) {
  double largest = 0.0;
  for (const auto& sample : wallSamples) {
    double nearest = 1e300;
    for (const auto& p : cloud.positions())
      nearest = std::min(nearest, (p.cast<double>() - sample).norm());
    largest = std::max(largest, nearest);
  }
  return largest;
}

// Samples of a surface given by a parametrisation on [0,1]^2.
std::vector<Eigen::Vector3d> sampleSurface(
    const std::function<Eigen::Vector3d(double, double)>& surface, int count) {
  std::vector<Eigen::Vector3d> samples;
  for (int i = 0; i <= count; ++i) {
    for (int j = 0; j <= count; ++j)
      samples.push_back(surface(i / double(count), j / double(count)));
  }
  return samples;
}

// Coverage threshold: on a perfect lattice with the first layer dx/2 behind the wall, a wall
// point is at most sqrt(1/4 + 1/2) dx = 0.866 dx from a particle; 1.0 dx leaves no hole a
// particle of the size of the spacing could pass.
constexpr double coverageLimit = 1.0;

TEST(MoldParticleization, BoxShellIsTheLatticeWithExactWallDistanceAndNormals) {
  const double dx = 0.01;
  const auto mold =
      particleize(moldGeo("Box(1) = {0, 0, 0, 0.1, 0.1, 0.1};", "1, 2, 3, 4, 5"), moldDict(dx, 2));
  ASSERT_EQ(mold.clouds.size(), 1u);
  const ParticleCloud& cloud = mold.clouds[0];
  ASSERT_GT(cloud.size(), 0u);
  const Eigen::Vector3d lower(0, 0, 0), upper(0.1, 0.1, 0.1);
  double worstDistance = 0.0, worstAngle = 0.0;
  std::size_t onFlatWalls = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = cloud.positions()[i].cast<double>();
    const Eigen::Vector3d closest = p.cwiseMax(lower).cwiseMin(upper);
    worstDistance = std::max(
        worstDistance, std::abs(cloud.scalarField(field::wallDistance)[i] - (closest - p).norm()));
    worstAngle =
        std::max(worstAngle, angleDegrees(cloud.vectorField(field::normal)[i], closest - p));
    EXPECT_LE(p.z(), 0.1);  // the shell ends flush with the open top
    // Behind a face (not an edge): exactly on the lattice, at (k + 1/2) dx.
    if ((p - closest).cwiseAbs().maxCoeff() == (p - closest).norm()) {
      ++onFlatWalls;
      const double layer = cloud.scalarField(field::wallDistance)[i] / dx - 0.5;
      EXPECT_NEAR(layer, std::round(layer), 1e-9);
      EXPECT_NEAR(cloud.scalarField(field::volume)[i], dx * dx * dx, 0.05 * dx * dx * dx);
    }
  }
  EXPECT_LT(worstDistance, 1e-9 * dx);
  EXPECT_LT(worstAngle, 1e-6);
  EXPECT_EQ(onFlatWalls, 2u * (5u * 100u));  // 2 layers, 5 faces of 10 x 10
  const auto bottom =
      sampleSurface([](double u, double v) { return Eigen::Vector3d(0.1 * u, 0.1 * v, 0); }, 50);
  const auto side =
      sampleSurface([](double u, double v) { return Eigen::Vector3d(0, 0.1 * u, 0.1 * v); }, 50);
  EXPECT_LT(largestGap(cloud, bottom), 0.87 * dx);
  EXPECT_LT(largestGap(cloud, side), 0.87 * dx);
  const auto& spacing = mold.patches[0].spacing;
  EXPECT_GE(spacing.min, 0.75 * dx - 1e-12);
  EXPECT_LE(spacing.max, dx + 1e-12);
}

TEST(MoldParticleization, CylinderShellCoversTheCurvedWallWithExactNormals) {
  const double dx = 0.005, radius = 0.05, height = 0.06;
  const auto mold =
      particleize(moldGeo("Cylinder(1) = {0, 0, 0, 0, 0, 0.06, 0.05};", "1, 3"), moldDict(dx, 2));
  const ParticleCloud& cloud = mold.clouds.at(0);
  double worstDistance = 0.0, worstAngle = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = cloud.positions()[i].cast<double>();
    const double r = std::hypot(p.x(), p.y());
    if (p.z() < 0.0 || r < radius) continue;  // behind the side wall only
    worstDistance =
        std::max(worstDistance, std::abs(cloud.scalarField(field::wallDistance)[i] - (r - radius)));
    worstAngle = std::max(worstAngle, angleDegrees(cloud.vectorField(field::normal)[i],
                                                   Eigen::Vector3d(-p.x(), -p.y(), 0)));
  }
  EXPECT_LT(worstDistance, 0.01 * dx);
  EXPECT_LT(worstAngle, 2.0);
  const auto side = sampleSurface(
      [&](double u, double v) {
        const double angle = 2 * std::numbers::pi * u;
        return Eigen::Vector3d(radius * std::cos(angle), radius * std::sin(angle), height * v);
      },
      60);
  const auto bottom = sampleSurface(
      [&](double u, double v) {
        const double angle = 2 * std::numbers::pi * u;
        return Eigen::Vector3d(radius * v * std::cos(angle), radius * v * std::sin(angle), 0);
      },
      40);
  EXPECT_LT(largestGap(cloud, side), coverageLimit * dx);
  EXPECT_LT(largestGap(cloud, bottom), coverageLimit * dx);
  EXPECT_GE(mold.patches[0].spacing.min, 0.75 * dx - 1e-12);
}

TEST(MoldParticleization, ConeShellFollowsTheSlantedWall) {
  // A frustum widening upwards, as the conical mold: radius 0.03 at the bottom, 0.05 at the top.
  const double dx = 0.005, r1 = 0.03, r2 = 0.05, height = 0.06;
  const auto mold =
      particleize(moldGeo("Cone(1) = {0, 0, 0, 0, 0, 0.06, 0.03, 0.05};", "1, 3"), moldDict(dx, 2));
  const ParticleCloud& cloud = mold.clouds.at(0);
  // The side wall in the (r, z) half-plane: from (r1, 0) to (r2, height).
  const Eigen::Vector2d a(r1, 0), b(r2, height);
  const Eigen::Vector2d along = (b - a).normalized(), inward(-along.y(), along.x());
  double worstDistance = 0.0, worstAngle = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = cloud.positions()[i].cast<double>();
    const double r = std::hypot(p.x(), p.y());
    const Eigen::Vector2d q(r, p.z());
    const double t = (q - a).dot(along);
    if (t <= 0.0 || t >= (b - a).norm() || (q - a).dot(inward) > 0) continue;  // side only
    worstDistance = std::max(
        worstDistance, std::abs(cloud.scalarField(field::wallDistance)[i] + (q - a).dot(inward)));
    const Eigen::Vector3d exact(inward.x() * p.x() / r, inward.x() * p.y() / r, inward.y());
    worstAngle = std::max(worstAngle, angleDegrees(cloud.vectorField(field::normal)[i], exact));
  }
  EXPECT_LT(worstDistance, 0.01 * dx);
  EXPECT_LT(worstAngle, 2.0);
  const auto side = sampleSurface(
      [&](double u, double v) {
        const double angle = 2 * std::numbers::pi * u, radius = r1 + (r2 - r1) * v;
        return Eigen::Vector3d(radius * std::cos(angle), radius * std::sin(angle), height * v);
      },
      60);
  EXPECT_LT(largestGap(cloud, side), coverageLimit * dx);
  EXPECT_GE(mold.patches[0].spacing.min, 0.75 * dx - 1e-12);
  // A few particles where the shell is cut flush at the open rim have their nearest neighbour
  // farther than dx (coverage of the wall, checked above, is what keeps fluid in).
  EXPECT_LE(mold.patches[0].spacing.max, 1.6 * dx);
}

TEST(MoldParticleization, VolumeModeFillsTheExactVolumeWithinOnePercent) {
  const double dx = 0.004;
  const auto cylinder = particleize(moldGeo("Cylinder(1) = {0, 0, 0, 0, 0, 0.06, 0.05};", "1"),
                                    moldDict(dx, 2, "volume", "cavity"));
  double filled = 0.0;
  for (const Real v : cylinder.clouds.at(0).scalarField(field::volume)) filled += v;
  const double exact = std::numbers::pi * 0.05 * 0.05 * 0.06;
  EXPECT_NEAR(filled / exact, 1.0, 0.01);
  // The lattice itself (count x dx^3) is within 2% on a radius of 12.5 dx.
  EXPECT_NEAR(static_cast<double>(cylinder.clouds.at(0).size()) * dx * dx * dx / exact, 1.0, 0.02);
  const auto cone = particleize(moldGeo("Cone(1) = {0, 0, 0, 0, 0, 0.06, 0.03, 0.05};", "1"),
                                moldDict(dx, 2, "volume", "cavity"));
  filled = 0.0;
  for (const Real v : cone.clouds.at(0).scalarField(field::volume)) filled += v;
  const double exactCone = std::numbers::pi * 0.06 / 3 * (0.03 * 0.03 + 0.03 * 0.05 + 0.05 * 0.05);
  EXPECT_NEAR(filled / exactCone, 1.0, 0.01);
  for (const Real d : cone.clouds.at(0).scalarField(field::wallDistance)) EXPECT_GT(d, 0.0);
}

// The message of the Error particleizeMold throws.
std::string errorOf(const std::string& geo, const std::string& dict, bool withGeometry = true) {
  TemporaryCase mold;
  if (withGeometry) mold.write("constant/geometry/mold.geo", geo);
  mold.write("system/particleizeMoldDict", dict);
  try {
    particleizeMold(CaseFolder(mold.root()));
  } catch (const Error& error) {
    const std::string message = error.what();
    // Drop the temporary folder's path before "system/particleizeMoldDict".
    const auto system = message.find("system/particleizeMoldDict");
    return system == std::string::npos ? message : message.substr(system);
  }
  return "no error";
}

const std::string boxGeo = moldGeo("Box(1) = {0, 0, 0, 0.1, 0.1, 0.1};", "1, 2, 3, 4, 5");

TEST(MoldParticleization, MissingGeometryFileIsNamed) {
  const std::string message = errorOf(boxGeo, moldDict(0.01, 2), false);
  EXPECT_NE(message.find("system/particleizeMoldDict:2:"), std::string::npos) << message;
  EXPECT_NE(message.find("constant/geometry/mold.geo' does not exist"), std::string::npos)
      << message;
}

TEST(MoldParticleization, AbsentPhysicalGroupListsThoseThatArePresent) {
  EXPECT_EQ(errorOf(boxGeo, moldDict(0.01, 2, "shell", "lowerMold")),
            "system/particleizeMoldDict:7:5: patch 'lowerMold' is not a physical group of the "
            "geometry; the groups present are ( walls cavity )");
}

TEST(MoldParticleization, VolumeModeOnASurfaceGroupIsRefused) {
  const std::string message = errorOf(boxGeo, moldDict(0.01, 2, "volume"));
  EXPECT_EQ(message.substr(0, message.find(" but ")),
            "system/particleizeMoldDict:7:5: patch 'walls' has mode volume,");
  EXPECT_NE(message.find("is not a volume (dimension 2)"), std::string::npos) << message;
}

TEST(MoldParticleization, SpacingBeyondMaxParticlesIsRefused) {
  const std::string message =
      errorOf(boxGeo, moldDict(0.001, 2, "shell", "walls", "maxParticles 1000;\n"));
  EXPECT_EQ(message.substr(0, message.find(" would make")),
            "system/particleizeMoldDict:3:1: spacing 0.001 m")
      << message;
  EXPECT_NE(message.find("more than maxParticles 1000 (raise maxParticles in particleizeMoldDict "
                         "if you mean it); nothing was written"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace sphcast
