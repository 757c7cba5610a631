// Cell grid and neighbour lists against a brute-force O(N^2) search, in 2D and 3D, with and
// without periodic axes, within one cloud and between two.
#include "particles/NeighbourList.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/Error.h"
#include "particles/CellGrid.h"
#include "particles/ParticleCloud.h"

namespace sphcast {
namespace {

// Real literals, so that the tests build without conversions in the single-precision build too.
constexpr Real operator""_r(long double value) { return static_cast<Real>(value); }

using Pairs = std::vector<std::vector<std::uint32_t>>;

// Uniform random points in [0, size)^3 (z = 0 when flat), plus a cluster of `clustered` points
// within 0.1 radius of one spot, so that some cells are crowded and many empty.
std::vector<Vector> randomPoints(std::size_t count, const Vector& size, std::uint32_t seed,
                                 std::size_t clustered = 0, Real radius = 1) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<Real> unit(0, 1);
  std::vector<Vector> points(count);
  for (auto& x : points) x = Vector(unit(random), unit(random), unit(random)).cwiseProduct(size);
  for (std::size_t k = 0; k < std::min(clustered, count); ++k) {
    points[k] = 0.3_r * size + 0.1_r * radius * Vector(unit(random), unit(random), unit(random));
    if (size[2] == 0) points[k][2] = 0;
  }
  return points;
}

Pairs bruteForce(const std::vector<Vector>& a, const std::vector<Vector>& b, Real radius,
                 const PeriodicBox& box, bool sameCloud) {
  Pairs pairs(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (sameCloud && i == j) continue;
      if (box.separation(a[i], b[j]).squaredNorm() < radius * radius) {
        pairs[i].push_back(std::uint32_t(j));
      }
    }
  }
  return pairs;
}

Pairs sorted(const NeighbourList& list) {
  Pairs pairs(list.particleCount());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto neighbours = list.of(i);
    pairs[i].assign(neighbours.begin(), neighbours.end());
    std::sort(pairs[i].begin(), pairs[i].end());
  }
  return pairs;
}

// The points in the grid's cell order, the grid told so: the search then reads them directly.
std::vector<Vector> inCellOrder(const std::vector<Vector>& x, CellGrid& grid) {
  std::vector<Vector> ordered(x.size());
  const auto& order = grid.sortPermutation();
  for (std::size_t k = 0; k < x.size(); ++k) ordered[k] = x[order[k]];
  grid.adoptCellOrder();
  return ordered;
}

// Checks both searches: through the grid's index (cloud as given) and direct (cloud reordered).
void expectWithinMatchesBruteForce(const std::vector<Vector>& x, Real radius,
                                   const PeriodicBox& box = PeriodicBox()) {
  CellGrid grid(radius, box);
  grid.build(x);
  NeighbourList list;
  list.buildWithin(x, grid);
  EXPECT_EQ(sorted(list), bruteForce(x, x, radius, box, true));
  EXPECT_EQ(list.offsets().size(), x.size() + 1);
  const auto ordered = inCellOrder(x, grid);
  ASSERT_TRUE(grid.inCellOrder());
  list.buildWithin(ordered, grid);
  EXPECT_EQ(sorted(list), bruteForce(ordered, ordered, radius, box, true));
}

void expectBetweenMatchesBruteForce(const std::vector<Vector>& a, const std::vector<Vector>& b,
                                    Real radius, const PeriodicBox& box = PeriodicBox()) {
  CellGrid grid(radius, box);
  grid.build(b);
  NeighbourList list;
  list.buildBetween(a, b, grid);
  EXPECT_EQ(sorted(list), bruteForce(a, b, radius, box, false));
  const auto ordered = inCellOrder(b, grid);
  list.buildBetween(a, ordered, grid);
  EXPECT_EQ(sorted(list), bruteForce(a, ordered, radius, box, false));
}

TEST(NeighbourList, WithinOneCloudMatchesBruteForceIn3D) {
  expectWithinMatchesBruteForce(randomPoints(1500, Vector(5, 4, 3), 1, 200), 0.7_r);
}

TEST(NeighbourList, WithinOneCloudMatchesBruteForceIn2D) {
  const auto x = randomPoints(2000, Vector(6, 5, 0), 2, 300);
  CellGrid grid(0.5_r);
  grid.build(x);
  EXPECT_EQ(grid.cellCounts()[2], 1u) << "a flat cloud needs one layer of cells";
  expectWithinMatchesBruteForce(x, 0.5_r);
}

TEST(NeighbourList, FindsPairsAcrossPeriodicBoundariesIn3D) {
  PeriodicBox box;
  box.setPeriodic(0, 0, 5);
  box.setPeriodic(2, 0, 3);
  expectWithinMatchesBruteForce(randomPoints(1500, Vector(5, 4, 3), 3, 100), 0.7_r, box);
  // every axis periodic, and periods of only 2 and 3 cells
  PeriodicBox tight;
  tight.setPeriodic(0, 0, 1.5_r);
  tight.setPeriodic(1, 0, 2.2_r);
  tight.setPeriodic(2, 0, 3.0_r);
  expectWithinMatchesBruteForce(randomPoints(800, Vector(1.5_r, 2.2_r, 3.0_r), 4), 0.7_r, tight);
}

TEST(NeighbourList, FindsPairsAcrossPeriodicBoundariesIn2D) {
  PeriodicBox box;
  box.setPeriodic(0, -1, 4);  // a channel periodic in x
  auto x = randomPoints(1200, Vector(4, 2, 0), 5, 50);
  for (auto& p : x) p[0] -= 1;
  expectWithinMatchesBruteForce(x, 0.3_r, box);
}

TEST(NeighbourList, HandlesPositionsOutsideThePeriodicRange) {
  PeriodicBox box;
  box.setPeriodic(1, 0, 3);
  auto x = randomPoints(600, Vector(3, 3, 3), 6);
  for (std::size_t i = 0; i < x.size(); i += 3) x[i][1] += (i % 2 ? 3.0_r : -6.0_r);  // unwrapped
  expectWithinMatchesBruteForce(x, 0.6_r, box);
}

TEST(NeighbourList, BetweenTwoCloudsMatchesBruteForce) {
  const auto fluid = randomPoints(900, Vector(4, 4, 4), 7, 100);
  auto wall = randomPoints(700, Vector(6, 6, 6), 8, 50);
  for (auto& p : wall) p -= Vector(1, 1, 1);  // extends beyond the fluid on every side
  expectBetweenMatchesBruteForce(fluid, wall, 0.6_r);
  // query points far outside the wall's grid are clamped into it and find nothing wrong
  auto far = fluid;
  far[0] = Vector(100, -50, 3);
  expectBetweenMatchesBruteForce(far, wall, 0.6_r);
  PeriodicBox box;
  box.setPeriodic(1, -1, 6);
  expectBetweenMatchesBruteForce(fluid, wall, 0.6_r, box);
  const auto flatFluid = randomPoints(500, Vector(3, 3, 0), 9);
  const auto flatWall = randomPoints(400, Vector(4, 4, 0), 10);
  expectBetweenMatchesBruteForce(flatFluid, flatWall, 0.4_r);
}

TEST(NeighbourList, HandlesASingleParticleAndNone) {
  expectWithinMatchesBruteForce({Vector(1, 2, 3)}, 0.5_r);
  expectWithinMatchesBruteForce({}, 0.5_r);
  expectBetweenMatchesBruteForce({}, {Vector(1, 2, 3)}, 0.5_r);
  expectBetweenMatchesBruteForce({Vector(1, 2, 3)}, {}, 0.5_r);
  CellGrid grid(0.5_r);
  grid.build({});
  NeighbourList list;
  list.buildWithin({}, grid);
  EXPECT_EQ(list.particleCount(), 0u);
  EXPECT_EQ(list.pairCount(), 0u);
}

TEST(NeighbourList, KeepsCoincidentParticlesAsNeighbours) {
  expectWithinMatchesBruteForce({Vector(1, 1, 0), Vector(1, 1, 0), Vector(1.2_r, 1, 0)}, 0.5_r);
}

TEST(NeighbourList, IsIdenticalForOneAndTwoThreads) {
  PeriodicBox box;
  box.setPeriodic(0, 0, 6);
  // above the size from which the grid's loops run in parallel too
  const auto x = randomPoints(40000, Vector(6, 5, 4), 11, 4000);
  CellGrid grid(0.3_r, box);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  grid.build(x);
  const auto permutation1 = grid.sortPermutation();
  NeighbourList one;
  one.buildWithin(x, grid);
  omp_set_num_threads(2);
  grid.build(x);
  NeighbourList two;
  two.buildWithin(x, grid);
  omp_set_num_threads(threads);
  EXPECT_EQ(grid.sortPermutation(), permutation1);
  EXPECT_EQ(one.offsets(), two.offsets());
  EXPECT_EQ(one.neighbours(), two.neighbours());
}

TEST(CellGrid, SortPermutationIsAPermutationOrderedByCell) {
  const auto x = randomPoints(5000, Vector(5, 4, 3), 12, 500);
  CellGrid grid(0.35_r);
  grid.build(x);
  const auto& order = grid.sortPermutation();
  ASSERT_EQ(order.size(), x.size());
  std::vector<bool> seen(x.size(), false);
  for (const std::size_t i : order) {
    ASSERT_LT(i, x.size());
    EXPECT_FALSE(seen[i]) << "index " << i << " twice";
    seen[i] = true;
  }
  for (std::size_t k = 1; k < order.size(); ++k) {
    const auto previous = grid.cellIndex(grid.cellCoordinates(x[order[k - 1]]));
    const auto current = grid.cellIndex(grid.cellCoordinates(x[order[k]]));
    ASSERT_LE(previous, current);
    if (previous == current) {
      EXPECT_LT(order[k - 1], order[k]) << "stable within a cell";
    }
  }
}

TEST(CellGrid, ReorderedCloudGivesTheSameNeighbourhoods) {
  ParticleCloud cloud("metal");
  cloud.resize(3000);
  auto& id = cloud.addIdField("id");
  const auto x = randomPoints(3000, Vector(4, 4, 4), 13, 300);
  for (std::size_t i = 0; i < x.size(); ++i) cloud.positions()[i] = x[i], id[i] = std::int64_t(i);
  CellGrid grid(0.5_r);
  grid.build(cloud.positions());
  cloud.reorder(grid.sortPermutation());
  grid.adoptCellOrder();
  for (std::size_t k = 0; k < cloud.size(); ++k) {
    EXPECT_EQ(grid.particlesByCell()[k], k);
    EXPECT_EQ(grid.cellOfParticle(k), grid.cellIndex(grid.cellCoordinates(cloud.positions()[k])));
  }
  grid.build(cloud.positions());  // a rebuild finds the cloud still in cell order
  EXPECT_TRUE(grid.inCellOrder());
  NeighbourList reordered;
  reordered.buildWithin(cloud.positions(), grid);
  const Pairs expected = bruteForce(x, x, 0.5_r, PeriodicBox(), true);
  for (std::size_t k = 0; k < cloud.size(); ++k) {
    std::vector<std::uint32_t> original;
    for (const std::uint32_t j : reordered.of(k)) original.push_back(std::uint32_t(id[j]));
    std::sort(original.begin(), original.end());
    EXPECT_EQ(original, expected[std::size_t(id[k])]);
    EXPECT_TRUE(std::is_sorted(reordered.of(k).begin(), reordered.of(k).end()))
        << "a reordered cloud's neighbours come in increasing index";
  }
}

TEST(CellGrid, RebuildReusesItsBuffers) {
  const auto x = randomPoints(4000, Vector(4, 4, 4), 14);
  auto denser = x;
  for (auto& p : denser) p *= 0.99_r;  // every pair of x is a pair here
  CellGrid grid(0.5_r);
  grid.build(denser);
  NeighbourList list;
  list.buildWithin(denser, grid);
  const auto* neighbours = list.neighbours().data();
  const auto* byCell = grid.particlesByCell().data();
  const std::size_t bytes = list.memoryBytes();
  for (int step = 0; step < 2; ++step) {  // later steps need no more room
    grid.build(x);
    list.buildWithin(x, grid);
  }
  EXPECT_EQ(list.neighbours().data(), neighbours);
  EXPECT_EQ(grid.particlesByCell().data(), byCell);
  EXPECT_EQ(list.memoryBytes(), bytes);
}

TEST(CellGrid, RejectsNonFinitePositionsWithAMessage) {
  auto x = randomPoints(100, Vector(1, 1, 1), 15);
  x[42][1] = std::numeric_limits<Real>::quiet_NaN();
  x[77][0] = std::numeric_limits<Real>::infinity();
  CellGrid grid(0.2_r);
  try {
    grid.build(x);
    FAIL() << "no error for a NaN position";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("2 particle(s)"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("particle 42"), std::string::npos) << error.what();
  }
  CellGrid good(0.2_r);
  good.build(randomPoints(10, Vector(1, 1, 1), 16));
  NeighbourList list;
  EXPECT_THROW(list.buildBetween(x, randomPoints(10, Vector(1, 1, 1), 16), good), Error);
}

TEST(CellGrid, RejectsAbsurdCellCounts) {
  std::vector<Vector> x = {Vector(0, 0, 0), Vector(1e6_r, 1e6_r, 1e6_r)};  // one particle flew away
  CellGrid grid(0.01_r);
  try {
    grid.build(x);
    FAIL() << "no error for 1e24 cells";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("maxCellCount"), std::string::npos) << error.what();
  }
  CellGrid limited(0.1_r, PeriodicBox(), 1000);
  EXPECT_THROW(limited.build({Vector(0, 0, 0), Vector(2, 2, 2)}), Error);  // 21^3 cells
  EXPECT_NO_THROW(limited.build({Vector(0, 0, 0), Vector(0.5_r, 0.5_r, 0.5_r)}));
}

TEST(CellGrid, RejectsPeriodsOfTwoRadiiOrLess) {
  PeriodicBox box;
  box.setPeriodic(0, 0, 1.0_r);
  EXPECT_THROW(CellGrid(0.5_r, box), Error);
  EXPECT_NO_THROW(CellGrid(0.49_r, box));
  EXPECT_THROW(box.setPeriodic(3, 0, 1), Error);
  EXPECT_THROW(box.setPeriodic(1, 0, -1), Error);
  EXPECT_THROW(CellGrid(0.0_r), Error);
}

TEST(CellGrid, FixedDomainClampsOutsideParticlesAndStillFindsAllPairs) {
  const auto x = randomPoints(1000, Vector(4, 4, 4), 17, 100);
  CellGrid grid(0.5_r);
  grid.setDomain(Vector(1, 1, 1), Vector(3, 3, 3));
  grid.build(x);
  EXPECT_EQ(grid.cellCount(), 4u * 4u * 4u);  // floor(2 / (0.5 (1 + 1e-6))) + 1 per axis
  NeighbourList list;
  list.buildWithin(x, grid);
  EXPECT_EQ(sorted(list), bruteForce(x, x, 0.5_r, PeriodicBox(), true));
}

TEST(PeriodicBox, SeparationIsTheMinimumImage) {
  PeriodicBox box;
  box.setPeriodic(0, 0, 10);
  const Real tolerance = 100 * std::numeric_limits<Real>::epsilon();
  const Vector d = box.separation(Vector(0.5_r, 0, 0), Vector(9.5_r, 3, 0));
  EXPECT_NEAR(d[0], 1.0_r, tolerance);
  EXPECT_NEAR(d[1], -3.0_r, tolerance);
  EXPECT_NEAR(box.wrap(Vector(-0.5_r, 7, 1))[0], 9.5_r, tolerance);
  EXPECT_NEAR(box.wrap(Vector(23, 7, 1))[0], 3.0_r, tolerance);
  EXPECT_EQ(PeriodicBox().separation(Vector(1, 2, 3), Vector(3, 2, 1)), Vector(-2, 0, 2));
}

}  // namespace
}  // namespace sphcast
