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
        wall.position.emplace_back((i + Real(0.5)) * dx, (j + Real(0.5)) * dx,
                                   -(layer + Real(0.5)) * dx);
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

// A block of nx x ny x nz lattice cells from the origin, filled with particles as
// particleizeMold fills a volume: each particle's normal out through its nearest face (the first
// in x, y, z order on ties) and its depth behind that face.
TestWall filledBox(int nx, int ny, int nz) {
  TestWall wall;
  const Vector upper(nx * dx, ny * dx, nz * dx);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      for (int k = 0; k < nz; ++k) {
        const Vector p((i + Real(0.5)) * dx, (j + Real(0.5)) * dx, (k + Real(0.5)) * dx);
        const Vector toLower = p, toUpper = upper - p;
        Real depth = toLower.x();
        Vector normal(-1, 0, 0);
        for (int a = 0; a < 3; ++a) {
          if (toLower[a] < depth) depth = toLower[a], normal = -Vector::Unit(a);
          if (toUpper[a] < depth) depth = toUpper[a], normal = Vector::Unit(a);
        }
        wall.position.push_back(p);
        wall.normal.push_back(normal);
        wall.depth.push_back(depth);
      }
    }
  }
  return wall;
}

TEST(WallSurfaceDistance, FlatWallGivesTheExactHeightAboveTheSurface) {
  TestWall wall = flatFloor();
  const std::vector<Vector> fluid{
      {0.001, 0.002, 0.4 * dx}, {0.013, -0.02, -0.3 * dx}, {0.0, 0.0, 2.2 * dx}};
  const auto views = wall.views(fluid);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const WallSurfaceDistance d = wallSurfaceDistance(fluid[i], i, views, PeriodicBox{}, dx);
    ASSERT_TRUE(d.found);
    EXPECT_NEAR(d.distance, fluid[i].z(), 1e-12);
    EXPECT_NEAR(d.normal.z(), 1.0, 1e-12);
  }
}

// Inside a circle of radius R the estimate is the true R - |x| to within (0.75 dx)^2 / (2 R),
// never below it.
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
    EXPECT_NEAR(d.distance, exact, 0.5625 * dx * dx / (2 * radius))
        << "at gap " << exact / dx << " dx";
    EXPECT_GE(d.distance, exact - 1e-12);  // inside a circle every tangent plane lies beyond
  }
}

// The concave corner of a tank (floor z = 0, wall x = 0, three layers each, the fluid in x > 0,
// z > 0): the distance is the one to the nearer wall, so the clearance keeps a particle off both;
// a particle pressed into the corner, behind both, reads its distance to the edge.
TEST(WallSurfaceDistance, ConcaveCornerGivesTheNearerWall) {
  TestWall wall;
  for (int layer = 0; layer < 3; ++layer) {
    const Real depth = (layer + Real(0.5)) * dx;
    for (int a = 0; a < 8; ++a) {
      for (int j = -4; j < 4; ++j) {
        const Real along = (a + Real(0.5)) * dx, y = (j + Real(0.5)) * dx;
        wall.position.emplace_back(along, y, -depth);  // floor
        wall.normal.emplace_back(0, 0, 1);
        wall.depth.push_back(depth);
        wall.position.emplace_back(-depth, y, along);  // wall
        wall.normal.emplace_back(1, 0, 0);
        wall.depth.push_back(depth);
      }
    }
  }
  // the corner behind the junction, as particleizeMold fills it: normal towards the edge x = z = 0,
  // depth the distance to it (the feet on the edge)
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      for (int j = -4; j < 4; ++j) {
        const Vector x(-(a + Real(0.5)) * dx, (j + Real(0.5)) * dx, -(b + Real(0.5)) * dx);
        const Vector toEdge(-x.x(), 0, -x.z());
        wall.position.push_back(x);
        wall.normal.push_back(toEdge.normalized());
        wall.depth.push_back(toEdge.norm());
      }
    }
  }
  const std::vector<Vector> fluid{{0.1 * dx, 0.2 * dx, 0.3 * dx},
                                  {0.3 * dx, -0.1 * dx, 0.1 * dx},
                                  {0.2 * dx, 0.0, 0.2 * dx},
                                  {-0.2 * dx, 0.3 * dx, 1.5 * dx},    // behind the wall
                                  {-0.2 * dx, 0.1 * dx, -0.1 * dx}};  // into the corner
  // the last: behind both faces, past the end of each one's rows, over the corner's feet; still
  // in the body (the open rim rule, OverAShellsOpenRimIsNotBehindTheFace, must not take it out):
  // as deep as its distance to the edge, sqrt(0.05) dx, to within 0.02 dx (the corner's planes
  // through the edge are tangent to the cylinder around it)
  const std::vector<Real> exact{0.1 * dx, 0.1 * dx, 0.2 * dx, -0.2 * dx,
                                Real(-std::sqrt(0.05)) * dx};
  const std::vector<Real> tolerance{1e-12, 1e-12, 1e-12, 1e-12, 0.02 * dx};
  const auto views = wall.views(fluid);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const WallSurfaceDistance d = wallSurfaceDistance(fluid[i], i, views, PeriodicBox{}, dx);
    ASSERT_TRUE(d.found) << "fluid point " << i;
    EXPECT_NEAR(d.distance, exact[i], tolerance[i]) << "fluid point " << i;
  }
}

// A block obstacle, filled with particles as particleizeMold fills a volume (every particle's
// normal and depth to the nearest face), the fluid outside it: beside a face near a convex edge,
// and above a body only three spacings thick, whose inner particles face sideways. The distance
// is the one to the nearest face, or none where the edge's particles all face the other way
// (measured before: the smallest plane distance over the wall particles within dx put a
// particle above the obstacle of SPHERIC Test 2 4 dx behind a wall); never one behind a wall.
TEST(WallSurfaceDistance, ConvexEdgesAndThinFilledBodiesGiveTheDistanceToTheNearestFace) {
  const Vector lower(0, 0, 0), upper(3 * dx, 8 * dx, 8 * dx);  // a plate 3 dx thick
  TestWall wall = filledBox(3, 8, 8);
  // exact distances outside the box: the Euclidean distance to it
  auto outside = [&](const Vector& x) { return (x.cwiseMax(lower).cwiseMin(upper) - x).norm(); };
  const std::vector<Vector> fluid{
      {3.3 * dx, 4.1 * dx, 7.8 * dx},    // beside the +x face, 0.2 dx below the top edge
      {1.5 * dx, 4.0 * dx, 8.3 * dx},    // above the middle of the plate's top
      {0.2 * dx, 4.0 * dx, 8.25 * dx},   // above the top, next to the -x edge
      {-0.4 * dx, 2.0 * dx, 3.0 * dx},   // in front of the -x face
      // off the +x-top and -x-top edges, nearest the edge itself (0.25 and 0.28 dx away; the
      // planes read 0.2 and 0.15, 0.2 and 0.2): read as the wedge behind both faces
      {3.2 * dx, 4.5 * dx, 8.15 * dx},
      {-0.2 * dx, 6.5 * dx, 8.2 * dx}};
  const auto views = wall.views(fluid);
  const std::vector<bool> mustFind{true, true, false, true, true, true};
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const WallSurfaceDistance d = wallSurfaceDistance(fluid[i], i, views, PeriodicBox{}, dx);
    if (mustFind[i]) {
      ASSERT_TRUE(d.found) << "fluid point " << i;
    }
    if (d.found) {
      EXPECT_NEAR(d.distance, outside(fluid[i]), 1e-12) << "fluid point " << i;
    }
  }
}

// Just inside a filled block's convex edge and corner (the block is the intersection of its
// faces' half-spaces, so a point inside lies as deep as the nearest face): a particle of a
// stream poured past the corner where a ditch's arm meets the pocket floor, 0.0001 dx through
// the arm's side, was read 0.6 dx behind the floor's plane and stopped the run
// (tutorials/crossDitchPress at dx = 3 mm). The depth must be the nearest face's, and the normal
// that face's, so that the clearance moves the particle out through it.
TEST(WallSurfaceDistance, InsideAConvexEdgeOrCornerTheNearestFaceGivesTheDepth) {
  TestWall wall = filledBox(8, 8, 8);
  struct Probe {
    Vector x;
    Real depth;  // behind the nearest face
    int axis;    // that face's normal: +axis
  };
  const std::vector<Probe> probes{
      {{7.9999 * dx, 4.2 * dx, 7.4 * dx}, 0.0001 * dx, 0},  // edge x-z: 0.6 dx under the top
      {{7.7 * dx, 4.0 * dx, 7.95 * dx}, 0.05 * dx, 2},      // edge x-z: 0.3 dx behind the side
      {{7.9 * dx, 7.6 * dx, 7.8 * dx}, 0.1 * dx, 0},        // the corner, three faces
      {{7.85 * dx, 7.97 * dx, 7.5 * dx}, 0.03 * dx, 1}};    // the corner, the y face nearest
  std::vector<Vector> fluid;
  for (const Probe& probe : probes) fluid.push_back(probe.x);
  const auto views = wall.views(fluid);
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const WallSurfaceDistance d = wallSurfaceDistance(fluid[i], i, views, PeriodicBox{}, dx);
    ASSERT_TRUE(d.found) << "probe " << i;
    EXPECT_NEAR(d.distance, -probes[i].depth, 1e-12) << "probe " << i;
    EXPECT_NEAR(d.normal[probes[i].axis], 1.0, 1e-12) << "probe " << i;
  }
}

// A shell one particle thick (the obstacle of SPHERIC Test 2 at dx = 0.05 m is one: its
// particles at depth dx/2 behind each face, each face on its own lattice), fluid beside one face
// just past the end of its rows, where only the far face's patches lie under it, 3.2 dx behind
// their plane. That plane must not count (measured: the dam break stopped, "2.9 dx behind a wall
// surface"); the fluid beside the face's rows is 0.04 dx in front of it.
TEST(WallSurfaceDistance, TheFarFaceOfAThinShellDoesNotCount) {
  TestWall wall;
  // the faces x = 0 (normal -x, rows at y = j dx) and x = 3.2 dx (normal +x, rows at
  // y = (j + 1/2) dx) of a plate, one layer each
  for (int j = 0; j < 6; ++j) {
    for (int k = 0; k < 6; ++k) {
      const Real z = (k + Real(0.5)) * dx;
      wall.position.emplace_back(Real(0.5) * dx, j * dx, z);
      wall.normal.emplace_back(-1, 0, 0);
      wall.depth.push_back(Real(0.5) * dx);
      wall.position.emplace_back(Real(2.7) * dx, (j + Real(0.5)) * dx, z);
      wall.normal.emplace_back(1, 0, 0);
      wall.depth.push_back(Real(0.5) * dx);
    }
  }
  const std::vector<Vector> fluid{{3.24 * dx, 2.0 * dx, 3.0 * dx},    // beside the +x face
                                  {3.24 * dx, -0.3 * dx, 3.0 * dx}};  // past its rows' end
  const auto views = wall.views(fluid);
  const WallSurfaceDistance beside = wallSurfaceDistance(fluid[0], 0, views, PeriodicBox{}, dx);
  ASSERT_TRUE(beside.found);
  EXPECT_NEAR(beside.distance, 0.04 * dx, 1e-12);
  EXPECT_NEAR(beside.normal.x(), 1.0, 1e-12);
  const WallSurfaceDistance pastTheEnd = wallSurfaceDistance(fluid[1], 1, views, PeriodicBox{}, dx);
  EXPECT_FALSE(pastTheEnd.found) << "taken " << pastTheEnd.distance / dx << " dx in front";
}

// The rim of a shell open at the top (a tank's side: three layers behind the face y = 0, rows up
// to z = 9.5 dx, the wall's top at 10 dx, no face particleized above it). Metal flowing over
// the rim lies behind the face's plane but above the wall, not in it: measured, a particle of a
// pour overflowing the coarse hydrostatic tank 0.23 dx above the rim was read 0.93 dx behind
// the side and stopped the run. Behind the face below the rim, at the top row's cell corners
// and in the middle of the face, the depth stays the plane's.
TEST(WallSurfaceDistance, OverAShellsOpenRimIsNotBehindTheFace) {
  TestWall wall;
  for (int layer = 0; layer < 3; ++layer) {
    for (int i = -5; i <= 5; ++i) {
      for (int k = 0; k < 10; ++k) {
        wall.position.emplace_back(i * dx, -(layer + Real(0.5)) * dx, (k + Real(0.5)) * dx);
        wall.normal.emplace_back(0, 1, 0);
        wall.depth.push_back((layer + Real(0.5)) * dx);
      }
    }
  }
  const std::vector<Vector> overTheRim{{0.17 * dx, -0.93 * dx, 10.23 * dx},
                                       {0.45 * dx, -0.3 * dx, 10.05 * dx},
                                       {0.0, -0.6 * dx, 10.6 * dx}};
  const std::vector<Vector> inTheWall{{0.1 * dx, -0.3 * dx, 9.9 * dx},
                                      {0.4 * dx, -0.3 * dx, 9.9 * dx},
                                      {0.5 * dx, -0.45 * dx, 9.5 * dx},
                                      {0.5 * dx, -0.2 * dx, 5.0 * dx}};
  std::vector<Vector> fluid = overTheRim;
  fluid.insert(fluid.end(), inTheWall.begin(), inTheWall.end());
  const auto views = wall.views(fluid);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const WallSurfaceDistance d = wallSurfaceDistance(fluid[i], i, views, PeriodicBox{}, dx);
    if (i < overTheRim.size()) {
      EXPECT_TRUE(!d.found || d.distance >= 0)
          << "over the rim, point " << i << " read " << d.distance / dx << " dx behind the face";
    } else {
      ASSERT_TRUE(d.found) << "point " << i;
      EXPECT_NEAR(d.distance, fluid[i].y(), 1e-12) << "point " << i;
      EXPECT_NEAR(d.normal.y(), 1.0, 1e-12);
    }
  }
}

TEST(WallClearance, MovesCloseParticlesBackAndStopsTheirApproachOnly) {
  TestWall wall = flatFloor();
  std::vector<Vector> x{{0.0, 0.0, -0.2 * dx},   // behind the surface
                        {0.01, 0.0, 0.1 * dx},   // in front, too close
                        {0.02, 0.0, 0.6 * dx}};  // clear
  std::vector<Vector> v{{1.0, 0.5, -2.0}, {0.3, 0.0, 0.4}, {0.0, 0.0, -1.0}};
  const auto views = wall.views(x);
  const WallClearanceReport report =
      enforceWallClearance(x, v, views, PeriodicBox{}, dx, 0.25 * dx);
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
