// Packing relaxation of setCastFields on the conical mold: the lattice cut by the slanted wall of
// a shell made by particleizeMold, relaxed with the wall particles as fixed neighbours.
#include "geometry/PackingRelaxation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "geometry/CastFieldsSetup.h"
#include "geometry/MoldParticleization.h"
#include "particles/FieldNames.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

using testing::TemporaryCase;

const std::string header = "FoamFile { version 2.0; format ascii; class dictionary; object x; }\n";
// The conical mold of the tests of particleizeMold: radius 0.03 at the bottom, 0.05 at the top,
// 0.06 high; dx = 5 mm, h = 2.5 dx, so three wall layers.
constexpr double dx = 0.005, h = 0.0125, r1 = 0.03, r2 = 0.05, height = 0.06;

class ConeMold {
 public:
  // wallSurfaces: "1, 2, 3" closes the cone (side, top, bottom); "1, 3" leaves the top open.
  explicit ConeMold(const std::string& wallSurfaces) {
    folder_.write("constant/geometry/cone.geo",
                  "SetFactory(\"OpenCASCADE\");\nCone(1) = {0, 0, 0, 0, 0, 0.06, 0.03, 0.05};\n"
                  "Physical Surface(\"walls\") = {" +
                      wallSurfaces + "};\nPhysical Volume(\"cavity\") = {1};\n");
    folder_.write("system/particleizeMoldDict",
                  header +
                      "geometry (\"cone.geo\");\nspacing 0.005;\nsupportRadius 0.0125;\n"
                      "patches { walls { cloud mold; type fixedWall; } }\n");
    folder_.write("system/sphSchemes", header + "supportRadius 0.0125;\nsoundSpeed 20;\n");
    mold_ = particleizeMold(CaseFolder(folder_.root())).clouds;
    const ParticleCloud& walls = mold_.at(0);
    walls_.positions = walls.positions();
    walls_.volumes = walls.scalarField(field::volume);
  }

  // The metal filling the cone up to fillHeight, relaxed `iterations` times.
  ParticleCloud fill(int iterations, double fillHeight = height) const {
    const double radius = r1 + (r2 - r1) * fillHeight / height;
    folder_.write(
        "system/setCastFieldsDict",
        header +
            "spacing 0.005;\nclouds\n{\n    metal\n    {\n        regions { cone { type cone; "
            "point1 (0 0 0); point2 (0 0 " +
            std::to_string(fillHeight) +
            "); radius1 0.03; "
            "radius2 " +
            std::to_string(radius) + "; } }\n        relaxation { iterations " +
            std::to_string(iterations) + "; }\n    }\n}\n");
    return buildCastClouds(CaseDescription(CaseFolder(folder_.root())), mold_).at(0);
  }

  const FixedNeighbours& walls() const { return walls_; }

  // Closest approach of a particle to a wall particle.
  double closestToWall(const ParticleCloud& metal) const {
    double closest = std::numeric_limits<double>::infinity();
    for (const Vector& x : metal.positions()) {
      for (const Vector& w : walls_.positions)
        closest = std::min(closest, static_cast<double>((x - w).norm()));
    }
    return closest;
  }

 private:
  TemporaryCase folder_;
  std::vector<ParticleCloud> mold_;
  FixedNeighbours walls_;
};

// Whether x lies in the frustum of radius r1 at z = 0 growing to r2 at z = height, up to top.
bool insideCone(const Vector& x, double top) {
  const double z = static_cast<double>(x.z());
  const double radius = r1 + (r2 - r1) * z / height;
  return z >= -1e-12 && z <= top + 1e-12 &&
         std::hypot(static_cast<double>(x.x()), static_cast<double>(x.y())) <= radius * (1 + 1e-9);
}

void print(const char* what, const PackingStatistics& s) {
  std::printf(
      "%s: sigma mean %.4f, deviation %.4f, min %.4f, max %.4f; nearest min %.3f dx, "
      "mean %.3f dx\n",
      what, s.densityMean, s.densityDeviation, s.densityMin, s.densityMax, s.nearestMin / dx,
      s.nearestMean / dx);
}

TEST(PackingRelaxation, EvensOutTheLatticeCutByTheConeWithoutLeavingIt) {
  // A closed cone: every metal particle has a complete kernel of metal and wall particles, so
  // sigma = sum V W would be 1 everywhere for a perfect packing.
  const ConeMold mold("1, 2, 3");
  const ParticleCloud lattice = mold.fill(0);
  const ParticleCloud relaxed = mold.fill(200);
  ASSERT_EQ(relaxed.size(), lattice.size());
  const auto before = packingStatistics(lattice.positions(), mold.walls(), dx, h);
  const auto after = packingStatistics(relaxed.positions(), mold.walls(), dx, h);
  print("cone lattice", before);
  print("cone relaxed", after);
  EXPECT_LT(after.densityDeviation, before.densityDeviation / 3.0);  // measured 0.0288 -> 0.0048
  EXPECT_GE(after.nearestMin, 0.75 * dx * (1.0 - 1e-9));             // no closer than wallClearance
  EXPECT_GT(after.densityMin, before.densityMin);
  EXPECT_LT(after.densityMax, before.densityMax);
  for (const Vector& x : relaxed.positions()) EXPECT_TRUE(insideCone(x, height)) << x.transpose();
  EXPECT_GE(mold.closestToWall(relaxed), 0.75 * dx);
}

TEST(PackingRelaxation, KeepsTheFreeSurfaceWhereTheFillPutIt) {
  // An open cone filled to 2/3 of its height: the top of the metal is a free surface, held by
  // the lattice continued above it; it must not swell into the empty half of its kernels (with
  // nothing above it, the background pressure would push the top layers up until the region's
  // boundary stopped them, leaving the surface layer crowded against it).
  const ConeMold mold("1, 3");
  const double fillHeight = 0.04;
  const ParticleCloud lattice = mold.fill(0, fillHeight);
  const ParticleCloud relaxed = mold.fill(200, fillHeight);
  ASSERT_EQ(relaxed.size(), lattice.size());
  double topBefore = 0.0;
  for (const Vector& x : lattice.positions())
    topBefore = std::max(topBefore, static_cast<double>(x.z()));
  // The surface layer: its mean height, and how many of it rose, by how much.
  int count = 0;
  auto surfaceLayer = [&](const ParticleCloud& cloud, double& meanHeight, double& highest,
                          int& risen) {
    double sum = 0.0;
    count = 0;
    highest = 0.0;
    risen = 0;
    for (const Vector& x : cloud.positions()) {
      const double z = static_cast<double>(x.z());
      highest = std::max(highest, z);
      if (z > topBefore + 0.1 * dx) ++risen;
      if (z < topBefore - 0.5 * dx) continue;
      sum += z;
      ++count;
    }
    meanHeight = sum / count;
  };
  double meanBefore = 0.0, meanAfter = 0.0, highestBefore = 0.0, highestAfter = 0.0;
  int risenBefore = 0, risenAfter = 0;
  surfaceLayer(lattice, meanBefore, highestBefore, risenBefore);
  surfaceLayer(relaxed, meanAfter, highestAfter, risenAfter);
  std::printf(
      "free surface: layer mean height %.5f m before, %.5f m after; highest %.5f m, "
      "%d of the %d in the surface layer above the lattice's top layer + dx/10\n",
      meanBefore, meanAfter, highestAfter, risenAfter, count);
  // Where the surface meets the slanted wall, the lattice left gaps that the relaxation fills:
  // a few particles there rise, by dx/2 at most (the region's top); the surface as a whole
  // stays (measured: mean +0.016 dx; 18 of the 216 surface particles rose, the highest by
  // 0.28 dx).
  EXPECT_EQ(risenBefore, 0);
  EXPECT_NEAR(meanAfter, meanBefore, 0.05 * dx);
  EXPECT_LT(risenAfter, 40);
  EXPECT_LE(highestAfter, fillHeight + 1e-12);  // the region's top: nothing leaves it
  for (const Vector& x : relaxed.positions())
    EXPECT_TRUE(insideCone(x, fillHeight)) << x.transpose();
  EXPECT_GE(mold.closestToWall(relaxed), 0.75 * dx);
  // Below the surface's kernel the packing evens out as in the closed cone.
  auto deep = [&](const ParticleCloud& cloud) {
    std::vector<Vector> kept;
    for (const Vector& x : cloud.positions()) {
      if (static_cast<double>(x.z()) < topBefore - h) kept.push_back(x);
    }
    return kept;
  };
  FixedNeighbours withMetalAbove = mold.walls();
  for (const Vector& x : relaxed.positions()) {
    if (static_cast<double>(x.z()) >= topBefore - h) {
      withMetalAbove.positions.push_back(x);
      withMetalAbove.volumes.push_back(dx * dx * dx);
    }
  }
  const auto after = packingStatistics(deep(relaxed), withMetalAbove, dx, h);
  print("open cone, below the surface, relaxed", after);
  EXPECT_LT(after.densityDeviation, 0.01);  // measured 0.0039 (whole lattice fill: 0.028)
  EXPECT_GE(after.nearestMin, 0.75 * dx * (1.0 - 1e-9));  // no closer than wallClearance
}

}  // namespace
}  // namespace sphcast
