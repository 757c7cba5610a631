// Flat mold walls tilted to the axes get particles on a lattice of their own: layers at
// (k + 1/2) dx behind the face, a square lattice of spacing dx in the face's plane, and no gap or
// clump where faces meet. Checked on a rotated box and on the flat bottom of a tilted cylinder.
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <sstream>

#include "geometry/MoldParticleization.h"
#include "particles/FieldNames.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

using testing::TemporaryCase;

constexpr double dx = 0.01;
const Eigen::Vector3d boxSize(0.1, 0.08, 0.06);  // whole multiples of dx

ParticleizedMold particleize(const std::string& geo) {
  TemporaryCase mold;
  mold.write("constant/geometry/mold.geo", geo);
  std::ostringstream dict;
  dict << "FoamFile { version 2.0; format ascii; class dictionary; object particleizeMoldDict; }\n"
       << "geometry (\"mold.geo\");\nspacing " << dx << ";\nwallLayers 2;\n"
       << "patches\n{\n    walls { cloud mold; type fixedWall; }\n}\n";
  mold.write("system/particleizeMoldDict", dict.str());
  return particleizeMold(CaseFolder(mold.root()));
}

std::string rotatedBoxGeo(const Eigen::Vector3d& axis, double angle) {
  std::ostringstream geo;
  geo.precision(17);
  geo << "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, " << boxSize.x() << ", " << boxSize.y()
      << ", " << boxSize.z() << "};\nRotate {{" << axis.x() << ", " << axis.y() << ", " << axis.z()
      << "}, {0, 0, 0}, " << angle << "} { Volume{1}; }\n"
      << "Physical Surface(\"walls\") = {1, 2, 3, 4, 5};\nPhysical Volume(\"cavity\") = {1};\n";
  return geo.str();
}

// Largest distance from a sample point of the wall to its nearest particle.
double largestGap(const std::vector<Eigen::Vector3d>& particles,
                  const std::vector<Eigen::Vector3d>& wallSamples) {
  double largest = 0.0;
  for (const auto& sample : wallSamples) {
    double nearest = 1e300;
    for (const auto& p : particles) nearest = std::min(nearest, (p - sample).norm());
    largest = std::max(largest, nearest);
  }
  return largest;
}

double closestPairDistance(const std::vector<Eigen::Vector3d>& particles) {
  double closest = 1e300;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    for (std::size_t j = i + 1; j < particles.size(); ++j) {
      closest = std::min(closest, (particles[i] - particles[j]).norm());
    }
  }
  return closest;
}

std::vector<Eigen::Vector3d> positionsOf(const ParticleCloud& cloud) {
  std::vector<Eigen::Vector3d> positions;
  for (const auto& p : cloud.positions()) positions.push_back(p.cast<double>());
  return positions;
}

class RotatedBox : public ::testing::TestWithParam<Eigen::Vector3d> {};

TEST_P(RotatedBox, ShellIsTheFacesOwnLatticeWithExactDistancesAndNormals) {
  const double angle = std::numbers::pi / 6;  // 30 degrees
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(angle, GetParam().normalized()).toRotationMatrix();
  const auto mold = particleize(rotatedBoxGeo(GetParam(), angle));
  const ParticleCloud& cloud = mold.clouds.at(0);
  const auto positions = positionsOf(cloud);

  // In the box's own frame the exact wall is the box [0, boxSize] without its top.
  struct FaceParticle {
    Eigen::Vector3d local;
    int face;  // axis * 2 + side
    int layer;
  };
  std::vector<FaceParticle> behindFaces;
  double worstDistance = 0.0, worstNormal = 0.0, worstLayer = 0.0, worstVolume = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d local = rotation.transpose() * positions[i];
    const Eigen::Vector3d closest = local.cwiseMax(Eigen::Vector3d::Zero()).cwiseMin(boxSize);
    const double distance = (closest - local).norm();
    const Eigen::Vector3d exactNormal = rotation * (closest - local) / distance;
    worstDistance =
        std::max(worstDistance, std::abs(cloud.scalarField(field::wallDistance)[i] - distance));
    worstNormal = std::max(
        worstNormal, (cloud.vectorField(field::normal)[i].cast<double>() - exactNormal).norm());
    Eigen::Index axis = 0;
    if ((closest - local).cwiseAbs().maxCoeff(&axis) > distance - 1e-9 * dx) {  // behind a face
      const double layer = distance / dx - 0.5;
      worstLayer = std::max(worstLayer, std::abs(layer - std::round(layer)));
      worstVolume =
          std::max(worstVolume, std::abs(cloud.scalarField(field::volume)[i] - dx * dx * dx));
      behindFaces.push_back({local, static_cast<int>(axis) * 2 + (local[axis] > 0.0 ? 1 : 0),
                             static_cast<int>(std::lround(layer))});
    }
  }
  EXPECT_LT(worstDistance, 1e-6 * dx);
  EXPECT_LT(worstNormal, 1e-9);
  EXPECT_LT(worstLayer, 1e-6);
  EXPECT_LT(worstVolume, 1e-9 * dx * dx * dx);
  // 2 layers behind faces of 10 x 8, 2 x (10 x 6) and 2 x (8 x 6) spacings.
  EXPECT_EQ(behindFaces.size(), 2u * (80u + 120u + 96u));

  // In-plane nearest neighbour within the same face and layer: the square lattice's dx.
  double nearestLow = 1e300, nearestHigh = 0.0;
  for (const auto& a : behindFaces) {
    double nearest = 1e300;
    for (const auto& b : behindFaces) {
      if (&a == &b || a.face != b.face || a.layer != b.layer) continue;
      nearest = std::min(nearest, (a.local - b.local).norm());
    }
    nearestLow = std::min(nearestLow, nearest);
    nearestHigh = std::max(nearestHigh, nearest);
  }
  EXPECT_NEAR(nearestLow / dx, 1.0, 0.03);
  EXPECT_NEAR(nearestHigh / dx, 1.0, 0.03);

  // No hole: every point of the five walls (sampled every dx/4) within dx of a particle (a
  // perfect lattice dx/2 behind the wall gives sqrt(3)/2 dx = 0.866 dx).
  std::vector<Eigen::Vector3d> samples;
  for (int u = 0; u <= 40; ++u) {
    for (int v = 0; v <= 40; ++v) {
      const double s = u / 40.0, t = v / 40.0;
      const Eigen::Vector3d& L = boxSize;
      for (const Eigen::Vector3d& local :
           {Eigen::Vector3d(s * L.x(), t * L.y(), 0), Eigen::Vector3d(0, s * L.y(), t * L.z()),
            Eigen::Vector3d(L.x(), s * L.y(), t * L.z()), Eigen::Vector3d(s * L.x(), 0, t * L.z()),
            Eigen::Vector3d(s * L.x(), L.y(), t * L.z())}) {
        samples.push_back(rotation * local);
      }
    }
  }
  EXPECT_LT(largestGap(positions, samples), 0.87 * dx);
  // No clump where faces meet: at right angles the lattices of two faces continue into the
  // same corner points, so every pair stays a full spacing apart.
  EXPECT_GT(closestPairDistance(positions), 0.999 * dx);
  // The statistics the tool logs: exactly dx everywhere.
  const auto& spacing = mold.patches.at(0).spacing;
  EXPECT_NEAR(spacing.min / dx, 1.0, 1e-9);
  EXPECT_NEAR(spacing.mean / dx, 1.0, 1e-9);
  EXPECT_NEAR(spacing.max / dx, 1.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(ThirtyDegrees, RotatedBox,
                         ::testing::Values(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 2, 3)),
                         [](const auto& instance) {
                           return instance.param.z() == 1 ? std::string("aboutZ")
                                                          : std::string("aboutOneTwoThree");
                         });

// A pocket with a cross-shaped ditch in its floor (the press mold's cavity in small: 16 x 16 x 4
// spacings, arms 4 wide and 3 deep), shelled on all its walls but the top, with 3 layers: its
// ridges (the ditch's rims, where the material's corner is convex) and its T-shaped side faces
// are where the faces' lattices meet at ties.
std::string crossDitchCavityGeo(bool rotated) {
  std::ostringstream geo;
  geo << "SetFactory(\"OpenCASCADE\");\n"
      << "Box(1) = {-0.008, -0.008, 0, 0.016, 0.016, 0.004};\n"
      << "Box(2) = {-0.008, -0.002, -0.003, 0.016, 0.004, 0.003};\n"
      << "Box(3) = {-0.002, -0.008, -0.003, 0.004, 0.016, 0.003};\n"
      << "BooleanUnion(4) = { Volume{1}; Delete; }{ Volume{2, 3}; Delete; };\n"
      << "top() = Surface In BoundingBox{-1, -1, 0.004 - 1e-6, 1, 1, 0.004 + 1e-6};\n"
      << (rotated ? "Rotate {{1, 2, 3}, {0, 0, 0}, Pi / 6} { Volume{4}; }\n" : "")
      << "all() = Boundary{ Volume{4}; };\nPhysical Surface(\"walls\") = {all()};\n"
      << "Physical Surface(\"walls\") -= {top()};\nPhysical Volume(\"cavity\") = {4};\n";
  return geo.str();
}

TEST(RotatedMold, RotatingAMoldWithRidgesRotatesItsParticles) {
  const double spacing = 0.001;
  const auto particleizeCavity = [&](bool rotated) {
    TemporaryCase mold;
    mold.write("constant/geometry/mold.geo", crossDitchCavityGeo(rotated));
    std::ostringstream dict;
    dict
        << "FoamFile { version 2.0; format ascii; class dictionary; object particleizeMoldDict; }\n"
        << "geometry (\"mold.geo\");\nspacing " << spacing << ";\nwallLayers 3;\n"
        << "patches\n{\n    walls { cloud mold; type fixedWall; }\n}\n";
    mold.write("system/particleizeMoldDict", dict.str());
    return particleizeMold(CaseFolder(mold.root()));
  };
  const auto aligned = particleizeCavity(false);
  const auto rotated = particleizeCavity(true);
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(std::numbers::pi / 6, Eigen::Vector3d(1, 2, 3).normalized())
          .toRotationMatrix();
  const auto alignedPositions = positionsOf(aligned.clouds.at(0));
  auto rotatedBack = positionsOf(rotated.clouds.at(0));
  for (auto& p : rotatedBack) p = rotation.transpose() * p;
  ASSERT_GT(alignedPositions.size(), 1000u);
  EXPECT_EQ(rotatedBack.size(), alignedPositions.size());
  // Every particle of the rotated mold, turned back, is one of the aligned mold's.
  double worst = 0.0;
  for (const auto& p : rotatedBack) {
    double nearest = 1e300;
    for (const auto& q : alignedPositions) nearest = std::min(nearest, (p - q).norm());
    worst = std::max(worst, nearest);
  }
  EXPECT_LT(worst, 1e-6 * spacing);
  for (const auto* mold : {&aligned, &rotated}) {
    const auto& statistics = mold->patches.at(0).spacing;
    EXPECT_NEAR(statistics.min / spacing, 1.0, 1e-9);
    EXPECT_NEAR(statistics.max / spacing, 1.0, 1e-9);
  }
}

TEST(TiltedCylinder, FlatBottomIsASquareLatticeOfItsOwn) {
  // Axis tilted 30 degrees from z: radius 0.05, length 0.06; walls: side and the bottom disc.
  const double radius = 0.05, length = 0.06, tilt = std::numbers::pi / 6;
  const Eigen::Vector3d axis(std::sin(tilt), 0, std::cos(tilt));
  std::ostringstream geo;
  geo.precision(17);
  geo << "SetFactory(\"OpenCASCADE\");\nCylinder(1) = {0, 0, 0, " << length * axis.x() << ", 0, "
      << length * axis.z() << ", " << radius << "};\n"
      << "Physical Surface(\"walls\") = {1, 3};\nPhysical Volume(\"cavity\") = {1};\n";
  const auto mold = particleize(geo.str());
  const ParticleCloud& cloud = mold.clouds.at(0);
  const auto positions = positionsOf(cloud);
  std::vector<Eigen::Vector3d> bottom;  // particles straight behind the bottom disc
  double worstDistance = 0.0, worstNormal = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d& p = positions[i];
    const double along = p.dot(axis);
    if (along >= 0.0 || (p - along * axis).norm() > radius) continue;
    worstDistance =
        std::max(worstDistance, std::abs(cloud.scalarField(field::wallDistance)[i] + along));
    worstNormal =
        std::max(worstNormal, (cloud.vectorField(field::normal)[i].cast<double>() - axis).norm());
    const double layer = -along / dx - 0.5;
    EXPECT_NEAR(layer, std::round(layer), 1e-6);
    if (std::round(layer) == 0.0) bottom.push_back(p);
  }
  EXPECT_LT(worstDistance, 1e-6 * dx);
  EXPECT_LT(worstNormal, 1e-9);
  // A disc of radius 5 dx holds about pi 25 = 79 lattice points.
  EXPECT_NEAR(static_cast<double>(bottom.size()), std::numbers::pi * 25.0, 8.0);
  double nearestLow = 1e300, nearestHigh = 0.0;
  for (const auto& a : bottom) {
    double nearest = 1e300;
    for (const auto& b : bottom) {
      if (&a != &b) nearest = std::min(nearest, (a - b).norm());
    }
    nearestLow = std::min(nearestLow, nearest);
    nearestHigh = std::max(nearestHigh, nearest);
  }
  EXPECT_NEAR(nearestLow / dx, 1.0, 1e-6);
  EXPECT_NEAR(nearestHigh / dx, 1.0, 1e-6);
  // Coverage of the bottom and the side, and no clump where the disc meets the side.
  const Eigen::Vector3d u = Eigen::Vector3d::UnitY(), v = axis.cross(u);
  std::vector<Eigen::Vector3d> bottomSamples, sideSamples;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 40; ++j) {
      const double angle = 2 * std::numbers::pi * i / 40.0, r = radius * j / 40.0;
      bottomSamples.push_back(r * (std::cos(angle) * u + std::sin(angle) * v));
      sideSamples.push_back(radius * (std::cos(angle) * u + std::sin(angle) * v) +
                            length * j / 40.0 * axis);
    }
  }
  EXPECT_LT(largestGap(positions, bottomSamples), 0.87 * dx);
  EXPECT_LT(largestGap(positions, sideSamples), dx);
  EXPECT_GT(closestPairDistance(positions), 0.5 * dx);
}

}  // namespace
}  // namespace sphcast
