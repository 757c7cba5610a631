// The wall clearance (sph/WallClearance.h) and the surface estimate it rests on
// (particles/WallSurfaceDistance.h), against walls whose surface is known exactly.
#include "sph/WallClearance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "particles/CellGrid.h"
#include "particles/NeighbourList.h"

namespace sphcast {
namespace {

constexpr Real dx = 0.01;
constexpr Real h = 3 * dx;

// Wall particles with their normals and depths, and the neighbour list of some fluid points.
struct TestWall {
  std::vector<Vector> position, normal;
  std::vector<Real> depth;
  NeighbourList list;
  std::vector<WallSurfaceView> views(const std::vector<Vector>& fluid) {
    CellGrid grid(h);
    grid.build(position);
    list.buildBetween(fluid, position, grid);
    return {{position, normal, depth, &list}};
  }
};

// Three layers behind the plane z = 0 (the fluid above it), on the lattice.
TestWall flatFloor() {
  TestWall wall;
  for (int layer = 0; layer < 3; ++layer) {
    for (int i = -8; i <= 8; ++i) {
      for (int j = -8; j <= 8; ++j) {
        wall.position.emplace_back((i + Real(0.5)) * dx, (j + Real(0.5)) * dx, -(layer + Real(0.5)) * dx);
        wall.normal.emplace_back(0, 0, 1);
        wall.depth.push_back((layer + Real(0.5)) * dx);
      }
    }
  }
  return wall;
}

// Three layers outside a circle of radius R in the x-y plane (a 2D pipe, fluid inside), spaced
// dx along each layer, as particleizeMold lays them.
TestWall circle(Real radius) {
  TestWall wall;
  for (int layer = 0; layer < 3; ++layer) {
    const Real r = radius + (layer + Real(0.5)) * dx;
    const int count = static_cast<int>(std::round(2 * std::numbers::pi * r / dx));
    for (int k = 0; k < count; ++k) {
      const Real angle = 2 * std::numbers::pi * k / count;
      const Vector outward(std::cos(angle), std::sin(angle), 0);
      wall.position.push_back(r * outward);
      wall.normal.push_back(-outward);
      wall.depth.push_back((layer + Real(0.5)) * dx);
    }
  }
  return wall;
}

TEST(WallSurfaceDistance, FlatWallGivesTheExactHeightAboveTheSurface) {
  TestWall wall = flatFloor();
  const std::vector<Vector> fluid{{0.001, 0.002, 0.4 * dx}, {0.013, -0.02, -0.3 * dx},
                                  {0.0, 0.0, 2.2 * dx}};
  const auto views = wall.views(fluid);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const WallSurfaceDistance d = wallSurfaceDistance(fluid[i], i, views, PeriodicBox{}, dx);
    ASSERT_TRUE(d.found);
    EXPECT_NEAR(d.distance, fluid[i].z(), 1e-12);
    EXPECT_NEAR(d.normal.z(), 1.0, 1e-12);
  }
}

// Inside a circle of radius R the estimate is the true R - |x| to within s^2 / (2 R), s <= dx
// the lateral offset of the wall particle whose plane is taken: 0.05 dx at R = 10 dx.
TEST(WallSurfaceDistance, CurvedWallErrsByLessThanTheCurvatureBound) {
  const Real radius = 10 * dx;
  TestWall wall = circle(radius);
  std::vector<Vector> fluid;
  for (int k = 0; k < 50; ++k) {
    const Real angle = 0.1237 * k;
    const Real gap = (-0.2 + 0.01 * k) * dx;  // behind the surface to in front of it
    fluid.push_back((radius - gap) * Vector(std::cos(angle), std::sin(angle), 0));
  }
  const auto views = wall.views(fluid);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const WallSurfaceDistance d = wallSurfaceDistance(fluid[i], i, views, PeriodicBox{}, dx);
    ASSERT_TRUE(d.found);
    const Real exact = radius - fluid[i].norm();
    EXPECT_NEAR(d.distance, exact, dx * dx / (2 * radius)) << "at gap " << exact / dx << " dx";
    EXPECT_GE(d.distance, exact - 1e-12);  // inside a circle every tangent plane lies beyond
  }
}

TEST(WallClearance, MovesCloseParticlesBackAndStopsTheirApproachOnly) {
  TestWall wall = flatFloor();
  std::vector<Vector> x{{0.0, 0.0, -0.2 * dx},   // behind the surface
                        {0.01, 0.0, 0.1 * dx},   // in front, too close
                        {0.02, 0.0, 0.6 * dx}};  // clear
  std::vector<Vector> v{{1.0, 0.5, -2.0}, {0.3, 0.0, 0.4}, {0.0, 0.0, -1.0}};
  const auto views = wall.views(x);
  const WallClearanceReport report = enforceWallClearance(x, v, views, PeriodicBox{}, dx, 0.25 * dx);
  EXPECT_EQ(report.corrected, 2u);
  EXPECT_EQ(report.beyondSurface, 1u);
  EXPECT_NEAR(report.deepest, 0.2 * dx, 1e-12);
  EXPECT_EQ(report.deepestParticle, 0u);
  EXPECT_NEAR(x[0].z(), 0.25 * dx, 1e-12);
  EXPECT_NEAR(x[1].z(), 0.25 * dx, 1e-12);
  EXPECT_DOUBLE_EQ(x[2].z(), 0.6 * dx);
  EXPECT_EQ(v[0], Vector(1.0, 0.5, 0.0));  // the approach removed, the slide kept
  EXPECT_EQ(v[1], Vector(0.3, 0.0, 0.4));  // leaving the wall already: untouched
  EXPECT_EQ(v[2], Vector(0.0, 0.0, -1.0));
}

}  // namespace
}  // namespace sphcast
