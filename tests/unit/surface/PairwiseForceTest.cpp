// The pairwise force (surface/PairwiseForce.h): what its construction promises on the lattice
// its constants are summed over: a flat face in balance (the held pressure cancels the
// cohesion's virial, so a column feels no net force and the bulk's pressure stays 0), a wall
// that attracts like the liquid is no face and one that attracts nothing is a free face, and
// momentum kept on any arrangement, the same bits on one and two threads. Its drops, against
// the continuum surface force's cases, are studies (surfaceTensionStudy's drops with
// --model pairwiseForce, tests/studies/SurfaceTensionStudy.cpp; doc/validation.md §2.4).

#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include "SurfaceTensionTestCases.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "sph/FlowTestCases.h"
#include "surface/PairwiseForce.h"

namespace sphcast {
namespace {

constexpr Real sigma = 0.07;

// The model's acceleration on the fluid among the walls, in a neighbourhood periodic along the
// axes given over [lower, upper).
std::vector<Vector> acceleration(int dimension, Real dx, ParticleCloud& fluid,
                                 std::vector<const ParticleCloud*> walls, const Vector& lower,
                                 const Vector& upper, std::array<bool, 3> periodicAxes,
                                 std::optional<Real> cosTheta = std::nullopt) {
  PeriodicBox box;
  for (int axis = 0; axis < 3; ++axis) {
    if (periodicAxes[axis]) box.setPeriodic(axis, lower[axis], upper[axis] - lower[axis]);
  }
  Neighbourhood neighbourhood(3 * dx, box);
  neighbourhood.addCloud(fluid, Neighbourhood::Motion::moving);
  for (const ParticleCloud* wall : walls) neighbourhood.addFixedCloud(*wall);
  SurfaceTensionSettings settings = testing::tensionSettings(dimension, 3 * dx, dx, sigma);
  settings.cosContactAngle = cosTheta;
  PairwiseForce tension(settings, fluid, walls, neighbourhood);
  neighbourhood.update();
  auto& a = fluid.vectorField(field::acceleration);
  std::fill(a.begin(), a.end(), Vector::Zero());
  tension.addAcceleration();
  return a;
}

double largestNorm(const std::vector<Vector>& a) {
  double largest = 0;
  for (const Vector& v : a) largest = std::max(largest, static_cast<double>(v.norm()));
  return largest;
}

// A slab of 12 rows, periodic along it: its face rows are pulled and pushed (the cohesion and
// the held pressure act at different depths), but the forces on each column's half add up to 0
// (a held pressure 1 % off leaves 1 % of the cohesion's pressure times the face's area), and
// farther than h from the faces no particle feels anything.
TEST(PairwiseForce, AFlatFaceIsInBalanceAndTheBulkFeelsNothing) {
  for (const int dimension : {2, 3}) {
    const Real dx = 0.001, thick = 12 * dx, width = 8 * dx;
    const Vector lower(0, 0, 0), upper(width, thick + 6 * dx, dimension == 3 ? width : 0);
    ParticleCloud fluid = testing::latticeFluid(
        dimension, dx, lower, upper, [&](const Vector& x) { return x[1] < thick; }, 1000, 0);
    const std::vector<Vector> a =
        acceleration(dimension, dx, fluid, {}, lower, upper, {true, false, dimension == 3});
    const double scale = largestNorm(a);
    ASSERT_GT(scale, 0) << dimension << "D";
    double upperHalf = 0, absolute = 0;
    const auto& x = fluid.positions();
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (x[i][1] > 3 * dx && x[i][1] < thick - 3 * dx) {
        EXPECT_LT(a[i].norm(), 1e-9 * scale) << dimension << "D, y = " << x[i][1] / dx << " dx";
      }
      if (x[i][1] > thick / 2) {
        upperHalf += a[i][1];
        absolute += std::abs(a[i][1]);
      }
    }
    EXPECT_LT(std::abs(upperHalf), 1e-9 * absolute) << dimension << "D";
  }
}

// A block of 8 rows on a wall of three layers continuing its lattice, periodic along it: a wall
// attracting with the liquid's strength (theta 0) is no face, its bottom rows feel nothing; one
// attracting nothing (180) is a free face, its two rows pulled as the top's, mirrored.
TEST(PairwiseForce, AWallAttractingAsTheLiquidIsNoFaceAndOneAttractingNothingAFreeFace) {
  const Real dx = 0.001, width = 12 * dx;
  const Vector lower(0, 0, 0), upper(width, 8 * dx, 0);
  ParticleCloud wall = testing::emptyWall();
  testing::addWallCells(
      wall, 0, 12, -3, 0, dx, Vector::Zero(), [](int, int) { return Vector(0, 1, 0); },
      [dx](int, int row) { return (-row - Real(0.5)) * dx; });
  std::map<int, double> rowOf;
  for (const Real cosTheta : {Real(1), Real(-1)}) {
    ParticleCloud fluid = testing::latticeFluid(
        2, dx, lower, upper, [](const Vector&) { return true; }, 1000, 0);
    const std::vector<Vector> a =
        acceleration(2, dx, fluid, {&wall}, lower, upper, {true, false, false}, cosTheta);
    const double scale = largestNorm(a);
    ASSERT_GT(scale, 0);
    const auto& x = fluid.positions();
    for (std::size_t i = 0; i < x.size(); ++i) {
      const int row = static_cast<int>(std::floor(x[i][1] / dx));  // 0 at the wall, 7 on top
      EXPECT_LT(std::abs(a[i][0]), 1e-9 * scale);
      // a particle sees two rows either side (h = 3 dx): rows 2 to 5 have all their neighbours
      if ((row >= 2 && row <= 5) || (cosTheta > 0 && row < 2)) {
        EXPECT_LT(a[i].norm(), 1e-9 * scale) << "row " << row;
      }
      rowOf[row] = a[i][1];
    }
    if (cosTheta < 0) {
      for (int row = 0; row < 2; ++row) {
        EXPECT_NEAR(rowOf[row], -rowOf[7 - row], 1e-9 * scale) << "row " << row;
        EXPECT_GT(std::abs(rowOf[row]), 1e-3 * scale) << "row " << row;
      }
    }
  }
}

// A drop of jittered lattice particles: the forces add up to 0 (momentum kept), and one and two
// threads give the same bits.
TEST(PairwiseForce, MomentumIsKeptAndTwoThreadsGiveTheSameBits) {
  const Real dx = 0.001, radius = 10 * dx;
  const Vector reach = Vector::Constant(radius + dx);
  std::vector<std::vector<Vector>> runs;
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    ParticleCloud fluid = testing::latticeFluid(
        2, dx, -reach, reach, [&](const Vector& x) { return x.norm() < radius; }, 1000, 0,
        Real(0.2));
    runs.push_back(acceleration(2, dx, fluid, {}, -reach, reach, {false, false, false}));
  }
  omp_set_num_threads(2);
  Vector sum = Vector::Zero();
  double absolute = 0;
  for (const Vector& a : runs[0]) {  // every particle carries the same mass
    sum += a;
    absolute += a.norm();
  }
  EXPECT_LT(sum.norm(), 1e-12 * absolute);
  ASSERT_EQ(runs[0].size(), runs[1].size());
  for (std::size_t i = 0; i < runs[0].size(); ++i) EXPECT_EQ(runs[0][i], runs[1][i]) << i;
}

}  // namespace
}  // namespace sphcast
