// Recursive coordinate bisection: cuts that depend only on the whole weighted set (not on which
// rank holds what), each subdomain's share of the weight within one point per level, cuts
// between lattice planes, owners inside their boxes, and the halo queries equal to a
// brute-force search over the boxes. Collective: every rank runs every test.
#include "parallel/RecursiveBisection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/Error.h"

namespace sphcast {
namespace {

struct PointSet {
  std::vector<Vector> points;
  std::vector<std::int64_t> weights;
};

// An L-shaped block of lattice points (spacing 1), jittered by up to `jitter` per coordinate,
// weights 4 on every third point (the metal) and 1 elsewhere (the mold): the whole set.
PointSet lShapedSet(double jitter) {
  PointSet set;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shake(-jitter, jitter);
  for (int i = 0; i < 24; ++i) {
    for (int j = 0; j < 18; ++j) {
      for (int k = 0; k < 10; ++k) {
        if (i >= 12 && j >= 9) continue;  // the L's notch
        const Vector x(Real(i + shake(random)), Real(j + shake(random)), Real(k + shake(random)));
        set.weights.push_back(set.points.size() % 3 == 0 ? 4 : 1);
        set.points.push_back(x);
      }
    }
  }
  return set;
}

// This rank's share: every size-th point from its rank on.
PointSet share(const PointSet& all, const Communicator& comm) {
  PointSet mine;
  for (std::size_t i = static_cast<std::size_t>(comm.rank()); i < all.points.size();
       i += static_cast<std::size_t>(comm.size())) {
    mine.points.push_back(all.points[i]);
    mine.weights.push_back(all.weights[i]);
  }
  return mine;
}

bool sameRegions(const RecursiveBisection& a, const RecursiveBisection& b) {
  if (a.parts() != b.parts()) return false;
  for (int p = 0; p < a.parts(); ++p) {
    if (a.region(p).lower != b.region(p).lower || a.region(p).upper != b.region(p).upper) {
      return false;
    }
  }
  return true;
}

TEST(RecursiveBisectionTest, CutsDependOnlyOnTheWholeSetNotOnWhichRankHoldsIt) {
  const Communicator world = Communicator::world();
  const PointSet all = lShapedSet(0.2);
  const PointSet mine = share(all, world);
  for (int parts : {1, 2, 3, 4, 5, 7, 16}) {
    const auto distributed = RecursiveBisection::build(world, mine.points, mine.weights, parts, 3);
    const auto serial =
        RecursiveBisection::build(Communicator::self(), all.points, all.weights, parts, 3);
    EXPECT_TRUE(sameRegions(distributed, serial))
        << parts << " parts: " << distributed.describe() << " against " << serial.describe();
    EXPECT_EQ(distributed.partWeights(), serial.partWeights()) << parts << " parts";
  }
}

TEST(RecursiveBisectionTest, EachSubdomainGetsItsShareWithinOnePointPerLevel) {
  const Communicator world = Communicator::world();
  const PointSet all = lShapedSet(0.2);  // distinct coordinates: a cut can fall between any two
  const PointSet mine = share(all, world);
  std::int64_t total = 0;
  for (std::int64_t w : all.weights) total += w;
  for (int parts : {2, 3, 4, 6, 8}) {
    const auto rcb = RecursiveBisection::build(world, mine.points, mine.weights, parts, 3);
    // the weights by owner, counted here: they must be what the build reports
    std::vector<std::int64_t> counted(static_cast<std::size_t>(parts), 0);
    for (std::size_t i = 0; i < mine.points.size(); ++i) {
      counted[static_cast<std::size_t>(rcb.owner(mine.points[i]))] += mine.weights[i];
    }
    world.sum(counted);
    EXPECT_EQ(counted, rcb.partWeights()) << parts << " parts";
    const int levels = static_cast<int>(std::ceil(std::log2(parts)));
    for (int p = 0; p < parts; ++p) {
      const double ideal = static_cast<double>(total) / parts;
      // each level's cut is off by at most the one point it falls beside (weight <= 4)
      EXPECT_LE(std::abs(static_cast<double>(counted[static_cast<std::size_t>(p)]) - ideal),
                4.0 * levels)
          << "part " << p << " of " << parts;
    }
    EXPECT_LT(rcb.imbalance(), 1.01) << parts << " parts";
  }
}

TEST(RecursiveBisectionTest, CutsFallHalfwayBetweenLatticePlanes) {
  const Communicator world = Communicator::world();
  const PointSet all = lShapedSet(0.0);
  const PointSet mine = share(all, world);
  for (int parts : {2, 3, 4, 5, 8}) {
    const auto rcb = RecursiveBisection::build(world, mine.points, mine.weights, parts, 3);
    for (int p = 0; p < parts; ++p) {
      for (int a = 0; a < 3; ++a) {
        for (double face : {rcb.region(p).lower[a], rcb.region(p).upper[a]}) {
          if (!std::isfinite(face)) continue;
          // planes at integers: a face at k + 1/2
          EXPECT_NEAR(face - std::floor(face), 0.5, 1e-12) << "part " << p << " axis " << a;
        }
      }
    }
  }
}

TEST(RecursiveBisectionTest, TwoDimensionalSetsAreNeverCutAcrossZ) {
  const Communicator world = Communicator::world();
  const PointSet mine = share(lShapedSet(0.2), world);
  const auto rcb = RecursiveBisection::build(world, mine.points, mine.weights, 8, 2);
  for (int p = 0; p < 8; ++p) {
    EXPECT_TRUE(std::isinf(rcb.region(p).lower[2]) && std::isinf(rcb.region(p).upper[2]));
  }
}

TEST(RecursiveBisectionTest, EveryPointLiesInItsOwnersBox) {
  const Communicator world = Communicator::world();
  const PointSet mine = share(lShapedSet(0.2), world);
  const auto rcb = RecursiveBisection::build(world, mine.points, mine.weights, 5, 3);
  const PeriodicBox none;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> anywhere(-40, 60);  // far outside the set too
  for (int n = 0; n < 2000; ++n) {
    const Vector x(Real(anywhere(random)), Real(anywhere(random)), Real(anywhere(random)));
    EXPECT_EQ(rcb.region(rcb.owner(x)).distance(x, none), 0.0);
  }
}

TEST(RecursiveBisectionTest, HaloQueriesEqualABruteForceSearchOverTheBoxes) {
  const Communicator world = Communicator::world();
  const PointSet mine = share(lShapedSet(0.2), world);
  const auto rcb = RecursiveBisection::build(world, mine.points, mine.weights, 7, 3);
  PeriodicBox periodic;
  periodic.setPeriodic(0, -0.5, 24);
  std::mt19937 random(13);
  std::uniform_real_distribution<double> near(-3, 27);
  for (const PeriodicBox& box : {PeriodicBox(), periodic}) {
    for (int n = 0; n < 2000; ++n) {
      const Vector x(Real(near(random)), Real(near(random)), Real(near(random)));
      const double radius = 2.5 + n % 3;
      const int self = rcb.owner(x);
      std::vector<int> found, expected;
      rcb.partsNear(x, radius, box, self, found);
      for (int p = 0; p < rcb.parts(); ++p) {
        if (p != self && rcb.region(p).distance(x, box) < radius) expected.push_back(p);
      }
      ASSERT_EQ(found, expected) << "at (" << x.transpose() << "), radius " << radius;
    }
    for (int p = 0; p < rcb.parts(); ++p) {  // halo partners: a symmetric relation
      for (int q : rcb.neighbours(p, 3.0, box)) {
        const auto back = rcb.neighbours(q, 3.0, box);
        EXPECT_NE(std::find(back.begin(), back.end(), p), back.end()) << p << " and " << q;
      }
    }
  }
  // across the periodic seam at x = -0.5 / 23.5 the first and the last slabs are partners
  EXPECT_GT(rcb.neighbours(rcb.owner(Vector(0, 1, 1)), 1.0, periodic).size(),
            rcb.neighbours(rcb.owner(Vector(0, 1, 1)), 1.0, PeriodicBox()).size());
  // but only near it: the outer subdomains reach to infinity, not beyond the period. Two halves
  // (the cut near x = 9: the L holds more below), and x = 17.5, 6 from the seam at 23.5 and
  // 8 or more from the cut, reaches the lower half only across the seam.
  const auto halves = RecursiveBisection::build(world, mine.points, mine.weights, 2, 3);
  ASSERT_LT(halves.region(0).upper[0], 9.6);
  const Vector x(17.5, 8, 5);
  std::vector<int> found;
  halves.partsNear(x, 5.9, periodic, halves.owner(x), found);
  EXPECT_TRUE(found.empty());
  halves.partsNear(x, 6.1, periodic, halves.owner(x), found);
  EXPECT_EQ(found, std::vector<int>{0});
  found.clear();
  halves.partsNear(x, 6.1, PeriodicBox(), halves.owner(x), found);
  EXPECT_TRUE(found.empty());
}

TEST(RecursiveBisectionTest, MoreSubdomainsThanPointsLeavesSomeEmpty) {
  const Communicator world = Communicator::world();
  std::vector<Vector> points;
  std::vector<std::int64_t> weights;
  if (world.master()) {
    points = {Vector(0, 0, 0), Vector(1, 0, 0), Vector(2, 0, 0)};
    weights = {1, 1, 1};
  }
  const auto rcb = RecursiveBisection::build(world, points, weights, 8, 3);
  std::int64_t total = 0;
  for (std::int64_t w : rcb.partWeights()) total += w;
  EXPECT_EQ(total, 3);
  EXPECT_EQ(rcb.parts(), 8);
}

// OpenFOAM's hierarchical decomposition, n (3 2 1) in order yxz: the set is cut first into two
// slabs along y, each slab into three along x, and never along z (its longest axis here is x,
// which plain bisection would cut first); every part gets its share as bisection's do, and the
// distributed build equals the serial one.
TEST(RecursiveBisectionTest, HierarchicalCutsFollowTheirOrderAndBalanceEachSlab) {
  const Communicator world = Communicator::world();
  const PointSet all = lShapedSet(0.2);
  const PointSet mine = share(all, world);
  const RecursiveBisection::AxisCuts cuts{{3, 2, 1}, {1, 0, 2}};
  const auto hierarchical =
      RecursiveBisection::build(world, mine.points, mine.weights, 6, 3, &cuts);
  const auto serial =
      RecursiveBisection::build(Communicator::self(), all.points, all.weights, 6, 3, &cuts);
  EXPECT_TRUE(sameRegions(hierarchical, serial)) << hierarchical.describe();
  ASSERT_EQ(hierarchical.parts(), 6);
  const double cutY = hierarchical.region(0).upper[1];
  for (int p = 0; p < 6; ++p) {
    const Region& box = hierarchical.region(p);
    EXPECT_TRUE(std::isinf(box.lower[2]) && std::isinf(box.upper[2])) << "part " << p << " cut z";
    // parts 0-2 below the one y cut, 3-5 above it: the y cut is the same plane for all
    EXPECT_EQ(p < 3 ? box.upper[1] : box.lower[1], cutY) << "part " << p;
  }
  EXPECT_EQ(hierarchical.describe().substr(0, 2), "y ") << hierarchical.describe();
  EXPECT_LT(hierarchical.imbalance(), 1.01) << hierarchical.describe();
  // counts that do not multiply to the parts
  EXPECT_THROW(RecursiveBisection::build(world, mine.points, mine.weights, 4, 3, &cuts), Error);
}

TEST(RecursiveBisectionTest, BadArgumentsAreErrors) {
  const Communicator world = Communicator::world();
  const std::vector<Vector> points{Vector(0, 0, 0)};
  EXPECT_THROW(RecursiveBisection::build(world, points, {1}, 0, 3), Error);
  EXPECT_THROW(RecursiveBisection::build(world, points, {-1}, 2, 3), Error);
  EXPECT_THROW(RecursiveBisection::build(world, points, {}, 2, 3), Error);
}

}  // namespace
}  // namespace sphcast
