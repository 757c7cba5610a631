// particleizeMold in 2D (`dimension 2;`): walls behind Physical Curves in the plane z = 0, on the
// side away from the cavity; volumes filling Physical Surfaces.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <regex>
#include <sstream>

#include "core/Error.h"
#include "geometry/MoldParticleization.h"
#include "particles/FieldNames.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

using testing::TemporaryCase;

std::string moldDict2D(double spacing, int layers, const std::string& patches,
                       const std::string& extra = "") {
  std::ostringstream dict;
  dict << "FoamFile { version 2.0; format ascii; class dictionary; object particleizeMoldDict; }\n"
       << "dimension 2;\ngeometry (\"mold.geo\");\nspacing " << spacing << ";\nwallLayers "
       << layers << ";\n"
       << extra << "patches\n{\n"
       << patches << "}\n";
  return dict.str();
}

std::string shellPatch(const std::string& name, const std::string& mode = "shell") {
  return "    " + name + " { cloud mold; type fixedWall; mode " + mode + "; }\n";
}

// A tank W x H with its corner at the origin, open at the top: floor and sides are "walls".
std::string tankGeo(double width, double height) {
  std::ostringstream geo;
  geo << "Point(1) = {0, 0, 0};\nPoint(2) = {" << width << ", 0, 0};\nPoint(3) = {" << width << ", "
      << height << ", 0};\nPoint(4) = {0, " << height << ", 0};\n"
      << "Line(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\nLine(4) = {4, 1};\n"
      << "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n"
      << "Physical Curve(\"walls\") = {1, 2, 4};\nPhysical Surface(\"cavity\") = {1};\n";
  return geo.str();
}

// A circle of radius R about the origin (four arcs) bounding a disk.
std::string circleGeo(double radius, const std::string& groups) {
  std::ostringstream geo;
  geo << "R = " << radius << ";\nPoint(1) = {0, 0, 0};\nPoint(2) = {R, 0, 0};\n"
      << "Point(3) = {0, R, 0};\nPoint(4) = {-R, 0, 0};\nPoint(5) = {0, -R, 0};\n"
      << "Circle(1) = {2, 1, 3};\nCircle(2) = {3, 1, 4};\nCircle(3) = {4, 1, 5};\n"
      << "Circle(4) = {5, 1, 2};\nCurve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n"
      << groups;
  return geo.str();
}

ParticleizedMold particleize(const std::string& geo, const std::string& dict) {
  TemporaryCase mold;
  mold.write("constant/geometry/mold.geo", geo);
  mold.write("system/particleizeMoldDict", dict);
  return particleizeMold(CaseFolder(mold.root()));
}

std::string errorOf(const std::string& geo, const std::string& dict) {
  try {
    particleize(geo, dict);
  } catch (const Error& error) {
    const std::string message = error.what();
    const auto system = message.find("system/particleizeMoldDict");
    return system == std::string::npos ? message : message.substr(system);
  }
  return "no error";
}

double nearestOther(const ParticleCloud& cloud, std::size_t i) {
  double nearest = 1e300;
  for (std::size_t j = 0; j < cloud.size(); ++j) {
    if (j != i)
      nearest = std::min(nearest, double((cloud.positions()[j] - cloud.positions()[i]).norm()));
  }
  return nearest;
}

// Largest distance from a probe point to its nearest particle: the widest hole among the probes.
template <class Inside>
double widestHole(const ParticleCloud& cloud, Eigen::Vector2d lower, Eigen::Vector2d upper,
                  double step, Inside inside) {
  double widest = 0.0;
  for (double x = lower.x(); x <= upper.x() + 1e-12; x += step) {
    for (double y = lower.y(); y <= upper.y() + 1e-12; y += step) {
      if (!inside(x, y)) continue;
      double nearest = 1e300;
      for (const Vector& p : cloud.positions()) {
        nearest = std::min(nearest, std::hypot(double(p.x()) - x, double(p.y()) - y));
      }
      widest = std::max(widest, nearest);
    }
  }
  return widest;
}

TEST(MoldParticleization2D, TankWallsAreTheLatticeWithClosedCorners) {
  const double dx = 0.01, width = 0.2, height = 0.1;
  const int layers = 3;
  const auto mold =
      particleize(tankGeo(width, height), moldDict2D(dx, layers, shellPatch("walls")));
  ASSERT_EQ(mold.clouds.size(), 1u);
  const ParticleCloud& cloud = mold.clouds[0];
  // floor 20 x 3, sides 2 x 10 x 3, two corner squares 3 x 3
  EXPECT_EQ(cloud.size(), 20u * 3 + 2 * 10 * 3 + 2 * 9);
  const auto& normal = cloud.vectorField(field::normal);
  const auto& wallDistance = cloud.scalarField(field::wallDistance);
  const auto& volume = cloud.scalarField(field::volume);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = cloud.positions()[i].cast<double>();
    SCOPED_TRACE("particle at (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")");
    EXPECT_EQ(p.z(), 0.0);
    // On the lattice ((i + 1/2) dx, (j + 1/2) dx), which setCastFields fills the tank on.
    EXPECT_NEAR(p.x() / dx - 0.5, std::round(p.x() / dx - 0.5), 1e-9);
    EXPECT_NEAR(p.y() / dx - 0.5, std::round(p.y() / dx - 0.5), 1e-9);
    EXPECT_NEAR(nearestOther(cloud, i), dx, 1e-12);  // exactly dx apart, no doubles
    EXPECT_DOUBLE_EQ(double(volume[i]), dx * dx);
    // The nearest point of the walls, and the normal from there into the tank.
    const Eigen::Vector3d wallPoint(std::clamp(p.x(), 0.0, width), std::max(p.y(), 0.0), 0.0);
    const Eigen::Vector3d towardsWall = wallPoint - p;
    EXPECT_NEAR(double(wallDistance[i]), towardsWall.norm(), 1e-12);
    EXPECT_NEAR((normal[i].cast<double>() - towardsWall.normalized()).norm(), 0.0, 1e-12);
    // Layers: (k + 1/2) dx behind a straight side, k < 3.
    EXPECT_LT(std::max(-p.y(), std::max(-p.x(), p.x() - width)), layers * dx);
  }
  // No hole: every point of the band behind floor and sides, corners included, lies within
  // dx / sqrt(2) (the lattice's) of a particle.
  const double band = layers * dx;
  const double hole =
      widestHole(cloud, {-band, -band}, {width + band, height}, dx / 7,
                 [&](double x, double y) { return x <= 0 || x >= width || y <= 0; });
  std::printf("2D tank: %zu particles, widest hole %.4f dx\n", cloud.size(), hole / dx);
  EXPECT_LE(hole, dx / std::sqrt(2.0) + 1e-9);
}

TEST(MoldParticleization2D, CircleLayersFollowTheCurveAtArcLengthSpacing) {
  const double dx = 0.005, radius = 0.05;  // R = 10 dx
  const int layers = 3;
  const auto mold = particleize(
      circleGeo(radius,
                "Physical Curve(\"walls\") = {1, 2, 3, 4};\nPhysical Surface(\"cavity\") = {1};\n"),
      moldDict2D(dx, layers, shellPatch("walls")));
  const ParticleCloud& cloud = mold.clouds[0];
  const auto& normal = cloud.vectorField(field::normal);
  const auto& wallDistance = cloud.scalarField(field::wallDistance);
  const auto& volume = cloud.scalarField(field::volume);
  std::size_t expected = 0;
  double ringArea = 0.0;
  for (int k = 0; k < layers; ++k) {
    // four arcs of a quarter each, round(length / dx) particles on each
    expected += 4 * static_cast<std::size_t>(
                        std::lround((radius + (k + 0.5) * dx) * std::numbers::pi / 2 / dx));
  }
  ringArea = std::numbers::pi * (std::pow(radius + layers * dx, 2) - radius * radius);
  EXPECT_EQ(cloud.size(), expected);
  double smallest = 1e300, largest = 0.0, volumeSum = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = cloud.positions()[i].cast<double>();
    const double r = p.norm();
    const double depth = r - radius;
    const double layer = std::round(depth / dx - 0.5);
    // On its layer (k + 1/2) dx outside the circle, within the chords' sag (1e-4 dx).
    EXPECT_NEAR(depth, (layer + 0.5) * dx, 1e-3 * dx);
    EXPECT_NEAR(double(wallDistance[i]), depth, 1e-3 * dx);
    EXPECT_LT((normal[i].cast<double>() + p / r).norm(), 1e-6);  // radial, into the circle
    // Neighbours along the layer: arc-length spacing length / round(length / dx).
    double along = 1e300;
    for (std::size_t j = 0; j < cloud.size(); ++j) {
      const Eigen::Vector3d q = cloud.positions()[j].cast<double>();
      if (j != i && std::abs(q.norm() - r) < 0.25 * dx) along = std::min(along, (q - p).norm());
    }
    smallest = std::min(smallest, along);
    largest = std::max(largest, along);
    volumeSum += double(volume[i]);
  }
  std::printf(
      "2D circle R = 10 dx: %zu particles, spacing along the layers %.4f .. %.4f dx, "
      "volumes %.5f of the ring's area\n",
      cloud.size(), smallest / dx, largest / dx, volumeSum / ringArea);
  // Spacing within 4 %: 16 .. 26 particles per quarter arc, the chord slightly below the arc.
  EXPECT_GT(smallest, 0.96 * dx);
  EXPECT_LT(largest, 1.04 * dx);
  EXPECT_NEAR(volumeSum / ringArea, 1.0, 1e-3);
  const double band = radius + layers * dx;
  const double hole =
      widestHole(cloud, {-band, -band}, {band, band}, dx / 5, [&](double x, double y) {
        const double r = std::hypot(x, y);
        return r >= radius && r <= band;
      });
  std::printf("    widest hole in the ring %.4f dx\n", hole / dx);
  EXPECT_LT(hole, 0.75 * dx);
}

TEST(MoldParticleization2D, RightAngledObstacleCornersHoldNoDoublesAndNoHoles) {
  // A square block inside a tank, its walls the patch: the layers go into the block, where
  // they meet at the four re-entrant corners of the cavity.
  const double dx = 0.01;
  const std::string geo =
      "Point(1) = {0, 0, 0};\nPoint(2) = {0.3, 0, 0};\nPoint(3) = {0.3, 0.2, 0};\n"
      "Point(4) = {0, 0.2, 0};\nPoint(5) = {0.1, 0.05, 0};\nPoint(6) = {0.2, 0.05, 0};\n"
      "Point(7) = {0.2, 0.15, 0};\nPoint(8) = {0.1, 0.15, 0};\n"
      "Line(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\nLine(4) = {4, 1};\n"
      "Line(5) = {5, 6};\nLine(6) = {6, 7};\nLine(7) = {7, 8};\nLine(8) = {8, 5};\n"
      "Curve Loop(1) = {1, 2, 3, 4};\nCurve Loop(2) = {5, 6, 7, 8};\n"
      "Plane Surface(1) = {1, 2};\nPhysical Curve(\"block\") = {5, 6, 7, 8};\n"
      "Physical Surface(\"water\") = {1};\n";
  const auto mold = particleize(geo, moldDict2D(dx, 3, shellPatch("block")));
  const ParticleCloud& cloud = mold.clouds[0];
  // The block is 10 x 10 dx: its outer three rings, 100 - 4 x 4.
  EXPECT_EQ(cloud.size(), 84u);
  for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_NEAR(nearestOther(cloud, i), dx, 1e-12);
}

// Distance from (x, y) to the segment a-b.
double segmentDistance(Eigen::Vector2d p, Eigen::Vector2d a, Eigen::Vector2d b) {
  const double s = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (a + s * (b - a) - p).norm();
}

TEST(MoldParticleization2D, SlantedCornersAreClosedWithoutCrowding) {
  // A trapezoid tank, wider at the top, open there: the floor meets the sides at 120 degrees
  // inside the cavity (the layers part by 60 degrees: arcs fill the wedge). A ridge on the
  // floor, 45 degrees each side, has convex corners of 135 degrees at its foot and a re-entrant
  // one at its top (the layers of its two sides overlap there and are thinned).
  const double dx = 0.01;
  const std::string geo =
      "Point(1) = {0, 0, 0};\nPoint(2) = {0.1, 0, 0};\nPoint(3) = {0.15, 0.05, 0};\n"
      "Point(4) = {0.2, 0, 0};\nPoint(5) = {0.3, 0, 0};\nPoint(6) = {0.3 + 0.2 / Sqrt(3), 0.2, "
      "0};\n"
      "Point(7) = {-0.2 / Sqrt(3), 0.2, 0};\n"
      "Line(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\nLine(4) = {4, 5};\n"
      "Line(5) = {5, 6};\nLine(6) = {6, 7};\nLine(7) = {7, 1};\n"
      "Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7};\nPlane Surface(1) = {1};\n"
      "Physical Curve(\"walls\") = {1, 2, 3, 4, 5, 7};\nPhysical Surface(\"cavity\") = {1};\n";
  const int layers = 3;
  const auto mold = particleize(geo, moldDict2D(dx, layers, shellPatch("walls")));
  const ParticleCloud& cloud = mold.clouds[0];
  double closest = 1e300;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    closest = std::min(closest, nearestOther(cloud, i));
  const std::vector<Eigen::Vector2d> corners = {
      {-0.2 / std::sqrt(3.0), 0.2},     {0, 0}, {0.1, 0}, {0.15, 0.05}, {0.2, 0}, {0.3, 0},
      {0.3 + 0.2 / std::sqrt(3.0), 0.2}};
  const double band = layers * dx;
  // The probes: outside the cavity, within the layers' depth of the walls (the open top's
  // corners left out: the layers end flush there).
  const double hole = widestHole(cloud, {-0.2, -band}, {0.5, 0.2}, dx / 7, [&](double x, double y) {
    const Eigen::Vector2d p(x, y);
    double wall = 1e300;
    for (std::size_t c = 0; c + 1 < corners.size(); ++c) {
      wall = std::min(wall, segmentDistance(p, corners[c], corners[c + 1]));
    }
    const bool inside = y > 0 && y < 0.2 && x > -y / std::sqrt(3.0) &&
                        x < 0.3 + y / std::sqrt(3.0) &&
                        !(y < 0.05 && std::abs(x - 0.15) < 0.05 - y);  // the cavity
    return !inside && wall <= band - 0.5 * dx && y < 0.2 - band;
  });
  std::printf(
      "2D trapezoid with a notch: %zu particles, closest pair %.3f dx, widest hole %.3f dx\n",
      cloud.size(), closest / dx, hole / dx);
  EXPECT_GE(closest, 0.5 * dx);
  EXPECT_LE(hole, dx);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    EXPECT_NEAR(cloud.vectorField(field::normal)[i].norm(), 1.0, 1e-12);
    EXPECT_GT(cloud.scalarField(field::wallDistance)[i], 0.0);
    EXPECT_LT(cloud.scalarField(field::wallDistance)[i], band);
  }
}

TEST(MoldParticleization2D, VolumeModeFillsADiskWithItsArea) {
  const double dx = 0.005, radius = 0.05;
  const auto mold = particleize(circleGeo(radius, "Physical Surface(\"disk\") = {1};\n"),
                                moldDict2D(dx, 3, shellPatch("disk", "volume")));
  const ParticleCloud& cloud = mold.clouds[0];
  const double area = std::numbers::pi * radius * radius;
  EXPECT_NEAR(double(cloud.size()) * dx * dx / area, 1.0, 0.02);
  double volumeSum = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    volumeSum += double(cloud.scalarField(field::volume)[i]);
    const Eigen::Vector3d p = cloud.positions()[i].cast<double>();
    EXPECT_LT(p.norm(), radius);
    EXPECT_NEAR(double(cloud.scalarField(field::wallDistance)[i]), radius - p.norm(), 1e-4 * dx);
  }
  EXPECT_NEAR(volumeSum / area, 1.0, 1e-4);  // the area shared among the particles
}

// The .geo meshed in 1D by gmsh (lines of at most maxLine) and saved as MSH 4.1, which holds
// the elements of the physical groups only (not the tank's open top).
ParticleizedMold particleizeMsh(const std::string& geo, double maxLine, const std::string& dict) {
  TemporaryCase mold;
  mold.write("constant/geometry/mold.geo", geo);
  const std::string msh = (mold.root() / "constant/geometry/mold.msh").string();
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open((mold.root() / "constant/geometry/mold.geo").string());
  gmsh::option::setNumber("Mesh.MeshSizeMax", maxLine);
  gmsh::model::mesh::generate(1);
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::write(msh);
  gmsh::finalize();
  std::filesystem::remove(mold.root() / "constant/geometry/mold.geo");
  mold.write("system/particleizeMoldDict",
             std::regex_replace(dict, std::regex("mold\\.geo"), "mold.msh"));
  return particleizeMold(CaseFolder(mold.root()));
}

TEST(MoldParticleization2D, MshCurvesGiveTheParticlesOfTheGeo) {
  const double dx = 0.01;
  const std::string dict = moldDict2D(dx, 3, shellPatch("walls"));
  const auto fromGeo = particleize(tankGeo(0.2, 0.1), dict).clouds[0];
  const auto fromMsh = particleizeMsh(tankGeo(0.2, 0.1), 0.03, dict).clouds[0];
  ASSERT_EQ(fromMsh.size(), fromGeo.size());
  std::vector<std::array<double, 2>> a, b;
  for (const Vector& p : fromGeo.positions()) a.push_back({double(p.x()), double(p.y())});
  for (const Vector& p : fromMsh.positions()) b.push_back({double(p.x()), double(p.y())});
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i][0], b[i][0], 1e-12);
    EXPECT_NEAR(a[i][1], b[i][1], 1e-12);
  }
  // A circle meshed with lines of dx/8: its layers within the chords' sag, (dx/8)^2 / (8 R).
  const double radius = 0.05, smallDx = 0.005;
  const auto circle = particleizeMsh(circleGeo(radius,
                                               "Physical Curve(\"walls\") = {1, 2, 3, 4};\n"
                                               "Physical Surface(\"cavity\") = {1};\n"),
                                     smallDx / 8, moldDict2D(smallDx, 3, shellPatch("walls")))
                          .clouds[0];
  const auto circleFromGeo = particleize(circleGeo(radius,
                                                   "Physical Curve(\"walls\") = {1, 2, 3, 4};\n"
                                                   "Physical Surface(\"cavity\") = {1};\n"),
                                         moldDict2D(smallDx, 3, shellPatch("walls")))
                                 .clouds[0];
  EXPECT_EQ(circle.size(), circleFromGeo.size());
  for (std::size_t i = 0; i < circle.size(); ++i) {
    const double depth = double(circle.positions()[i].norm()) - radius;
    EXPECT_NEAR(depth / smallDx - 0.5, std::round(depth / smallDx - 0.5), 1e-3);
    EXPECT_NEAR(double(circle.scalarField(field::wallDistance)[i]), depth, 1e-3 * smallDx);
  }
}

const std::string tank = tankGeo(0.2, 0.1);

TEST(MoldParticleization2D, AbsentPhysicalGroupListsThoseThatArePresent) {
  EXPECT_EQ(errorOf(tank, moldDict2D(0.01, 3, shellPatch("floor"))),
            "system/particleizeMoldDict:8:5: patch 'floor' is not a physical group of the "
            "geometry; the groups present are ( walls cavity )");
}

TEST(MoldParticleization2D, ShellModeOnASurfaceGroupIsRefused) {
  const std::string message = errorOf(tank, moldDict2D(0.01, 3, shellPatch("cavity")));
  EXPECT_EQ(message.substr(0, message.find(" but ")),
            "system/particleizeMoldDict:8:5: patch 'cavity' has mode shell,");
  EXPECT_NE(message.find("is not a curve (dimension 2); use mode volume"), std::string::npos)
      << message;
}

TEST(MoldParticleization2D, AbsentCavityListsTheGroups) {
  EXPECT_EQ(errorOf(tank, moldDict2D(0.01, 3, shellPatch("walls"), "cavity water;\n")),
            "system/particleizeMoldDict:6:1: cavity 'water' is not a physical surface of the "
            "geometry; the groups present are ( walls cavity )");
}

TEST(MoldParticleization2D, SpacingBeyondMaxParticlesIsRefused) {
  // 0.4 m of walls, 3 layers at dx = 1 mm: 1,200 particles.
  const std::string message =
      errorOf(tank, moldDict2D(0.001, 3, shellPatch("walls"), "maxParticles 1000;\n"));
  EXPECT_EQ(message,
            "system/particleizeMoldDict:4:1: spacing 0.001 m would make about 1200 mold "
            "particles, more than maxParticles 1000 (raise maxParticles in "
            "particleizeMoldDict if you mean it); nothing was written");
}

TEST(MoldParticleization2D, ThreeDimensionalCaseRefusesCurveGroups) {
  const std::string dict = std::regex_replace(moldDict2D(0.01, 3, shellPatch("walls")),
                                              std::regex("dimension 2;\n"), "");
  const std::string message = errorOf(tank, dict);
  EXPECT_NE(message.find("is not a surface (dimension 1); is the case 2D (dimension 2)?"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace sphcast
