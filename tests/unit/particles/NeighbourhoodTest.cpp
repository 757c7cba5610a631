// The neighbourhood the models of a step share: one list per requested pair of clouds, equal to
// a brute-force search; a moving cloud re-binned and reordered (its fields with it) at each
// rebuild, a fixed one never reordered; lists with a skin reused, and still equal to a
// brute-force search, until particles may have closed in by the skin, or a cloud's layout
// changed; a list nobody asked for is an error naming the clouds.
#include "particles/Neighbourhood.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/Error.h"

namespace sphcast {
namespace {

ParticleCloud randomCloud(const std::string& name, std::size_t count, std::uint32_t seed) {
  ParticleCloud cloud(name);
  cloud.resize(count);
  auto& label = cloud.addScalarField("label");  // follows its particle through reorders
  std::mt19937 random(seed);
  std::uniform_real_distribution<Real> unit(0, 1);
  for (std::size_t i = 0; i < count; ++i) {
    cloud.positions()[i] = Vector(unit(random), unit(random), unit(random));
    label[i] = static_cast<Real>(i);
  }
  return cloud;
}

// The sorted neighbours in b of particle i of a, by brute force (the minimum image on the box's
// periodic axes; none by default).
std::vector<std::uint32_t> bruteForce(const ParticleCloud& a, std::size_t i, const ParticleCloud& b,
                                      Real radius, const PeriodicBox& box) {
  std::vector<std::uint32_t> found;
  for (std::size_t j = 0; j < b.size(); ++j) {
    if (&a == &b && i == j) continue;
    if (box.separation(a.positions()[i], b.positions()[j]).norm() < radius) {
      found.push_back(static_cast<std::uint32_t>(j));
    }
  }
  return found;
}

void expectBruteForce(const Neighbourhood& neighbourhood, const ParticleCloud& a,
                      const ParticleCloud& b, const PeriodicBox& box = PeriodicBox()) {
  const NeighbourList& list = neighbourhood.pairs(a, b);
  ASSERT_EQ(list.particleCount(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::vector<std::uint32_t> got(list.of(i).begin(), list.of(i).end());
    std::sort(got.begin(), got.end());
    ASSERT_EQ(got, bruteForce(a, i, b, neighbourhood.radius(), box))
        << a.name() << " particle " << i << " among " << b.name();
  }
}

TEST(NeighbourhoodTest, SharedListsMatchABruteForceSearchAfterEveryUpdate) {
  ParticleCloud metal = randomCloud("metal", 600, 1);
  ParticleCloud mold = randomCloud("mold", 400, 2);
  const std::vector<Vector> moldBefore = mold.positions();
  const Real h = Real(0.15);
  Neighbourhood neighbourhood(h, PeriodicBox());
  neighbourhood.addCloud(metal, Neighbourhood::Motion::moving);
  neighbourhood.addFixedCloud(mold);
  // two models asking for overlapping pairs: one list each
  for (int model = 0; model < 2; ++model) {
    neighbourhood.requestPairs(metal, metal);
    neighbourhood.requestPairs(metal, mold);
    neighbourhood.requestPairs(mold, metal);
  }
  neighbourhood.requestPairs(mold, mold);
  neighbourhood.update();
  std::mt19937 random(3);
  std::uniform_real_distribution<Real> step(-0.05, 0.05);
  for (int update = 0; update < 3; ++update) {
    expectBruteForce(neighbourhood, metal, metal);
    expectBruteForce(neighbourhood, metal, mold);
    expectBruteForce(neighbourhood, mold, metal);
    expectBruteForce(neighbourhood, mold, mold);
    // the metal moves; its labels must follow its particles through the reorder
    std::vector<Vector> labelled(metal.size());
    for (std::size_t i = 0; i < metal.size(); ++i) {
      metal.positions()[i] += Vector(step(random), step(random), step(random));
      labelled[static_cast<std::size_t>(metal.scalarField("label")[i])] = metal.positions()[i];
    }
    neighbourhood.update();
    for (std::size_t i = 0; i < metal.size(); ++i) {
      ASSERT_EQ(metal.positions()[i],
                labelled[static_cast<std::size_t>(metal.scalarField("label")[i])]);
    }
  }
  EXPECT_EQ(mold.positions(), moldBefore) << "a fixed cloud is never reordered";
  EXPECT_TRUE(neighbourhood.grid(metal).inCellOrder());
}

TEST(NeighbourhoodTest, AListNobodyAskedForIsAnError) {
  ParticleCloud metal = randomCloud("metal", 10, 1);
  ParticleCloud mold = randomCloud("mold", 10, 2);
  Neighbourhood neighbourhood(Real(0.2), PeriodicBox());
  neighbourhood.addCloud(metal, Neighbourhood::Motion::moving);
  neighbourhood.addFixedCloud(mold);
  neighbourhood.requestPairs(metal, mold);
  neighbourhood.update();
  try {
    neighbourhood.pairs(mold, metal);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("'mold' among cloud 'metal' were never requested"),
              std::string::npos)
        << error.what();
  }
  ParticleCloud stranger = randomCloud("stranger", 5, 3);
  EXPECT_THROW(neighbourhood.requestPairs(metal, stranger), Error);
}

// A rigid cloud (a body's mold): registered fixed by one model and rigid by another, it keeps
// its order, and its lists follow it when it moves, as a brute-force search finds them; its own
// list is that of its first binning (a rigid motion keeps every distance).
TEST(NeighbourhoodTest, RigidCloudListsFollowItWhenItMoves) {
  ParticleCloud metal = randomCloud("metal", 300, 3);
  ParticleCloud punch = randomCloud("punch", 200, 4);
  ParticleCloud mold = randomCloud("mold", 200, 5);
  const Real h = Real(0.15);
  Neighbourhood neighbourhood(h, PeriodicBox{});
  neighbourhood.addCloud(metal, Neighbourhood::Motion::moving);
  neighbourhood.addFixedCloud(punch);
  neighbourhood.addCloud(punch, Neighbourhood::Motion::rigid);  // upgraded
  neighbourhood.addFixedCloud(mold);
  neighbourhood.requestPairs(metal, punch);
  neighbourhood.requestPairs(punch, mold);
  neighbourhood.requestPairs(punch, punch);
  const std::vector<Real> labels = punch.scalarField("label");
  for (int step = 0; step < 3; ++step) {
    neighbourhood.update();
    expectBruteForce(neighbourhood, metal, punch);
    expectBruteForce(neighbourhood, punch, mold);
    expectBruteForce(neighbourhood, punch, punch);
    EXPECT_EQ(punch.scalarField("label"), labels);  // never reordered
    for (Vector& x : punch.positions()) x += Vector(0.07, -0.05, 0.02);  // a rigid move
  }
}

// Many small steps of a moving cloud (part of it still, as held frozen metal) beside a fixed and
// a rigid one, in a box periodic in x or not (a list within a cloud then finds its changed rows
// from the particles that moved, not from every row's neighbours): after every update each list
// is the brute-force one, whether it was searched, filtered, or its rows kept where nothing
// moved; most updates only filter; a particle added (a pour) or a non-finite position rebuilds.
void expectListsExactWhileReused(bool periodicX) {
  ParticleCloud metal = randomCloud("metal", 500, 6);
  ParticleCloud punch = randomCloud("punch", 150, 7);
  ParticleCloud mold = randomCloud("mold", 200, 8);
  for (Vector& x : punch.positions()) x[2] += Real(0.8);  // above, coming down
  PeriodicBox box;
  if (periodicX) box.setPeriodic(0, 0, 1);
  const Real h = Real(0.15), skin = Real(0.03);
  Neighbourhood neighbourhood(h, box, skin);
  EXPECT_EQ(neighbourhood.skin(), skin);
  neighbourhood.addCloud(metal, Neighbourhood::Motion::moving);
  neighbourhood.addCloud(punch, Neighbourhood::Motion::rigid);
  neighbourhood.addFixedCloud(mold);
  neighbourhood.requestPairs(metal, metal);
  neighbourhood.requestPairs(metal, mold);
  neighbourhood.requestPairs(mold, metal);
  neighbourhood.requestPairs(metal, punch);
  neighbourhood.requestPairs(punch, punch);
  // each metal particle at its own constant velocity: head-on pairs close in as fast as the
  // displacement test allows for, so a laxer test fails here
  std::mt19937 random(9);
  std::normal_distribution<Real> normal;
  std::vector<Vector> velocity(metal.size());
  for (std::size_t i = 0; i < metal.size(); ++i) {
    // a still region (frozen metal, held): its rows keep their pairs without a distance
    velocity[i] = metal.positions()[i].y() < Real(0.4)
                      ? Vector::Zero()
                      : Vector(Real(0.003) * Vector(normal(random), normal(random), normal(random))
                                                 .normalized());
  }
  const auto expectAll = [&](int update) {
    SCOPED_TRACE("update " + std::to_string(update));
    expectBruteForce(neighbourhood, metal, metal, box);
    expectBruteForce(neighbourhood, metal, mold, box);
    expectBruteForce(neighbourhood, mold, metal, box);
    expectBruteForce(neighbourhood, metal, punch, box);
    expectBruteForce(neighbourhood, punch, punch, box);
  };
  constexpr int updates = 60;
  for (int update = 0; update < updates; ++update) {
    neighbourhood.update();
    expectAll(update);
    if (::testing::Test::HasFatalFailure()) return;
    for (std::size_t i = 0; i < metal.size(); ++i) {
      // across the periodic face (when periodic): a jump of a whole period
      metal.positions()[i] = box.wrap(metal.positions()[i] + velocity[i]);
    }
    // the punch comes down, then rests (its lists only filtered, then not even that)
    if (update < updates / 2) {
      for (Vector& x : punch.positions()) x[2] -= Real(0.004);
    }
  }
  EXPECT_GT(neighbourhood.reuseCount(), neighbourhood.rebuildCount());
  EXPECT_GT(neighbourhood.rebuildCount(), 1u);

  // a pour: a particle added lands in the lists at once
  const std::size_t rebuildsBefore = neighbourhood.rebuildCount();
  ParticleCloud poured = metal;
  poured.resize(1);
  poured.positions()[0] = metal.positions()[0] + Vector(Real(0.01), 0, 0);
  metal.append(poured);
  neighbourhood.update();
  EXPECT_EQ(neighbourhood.rebuildCount(), rebuildsBefore + 1);
  expectAll(updates);
  // a position gone bad is not filtered away: the rebuild reports it
  metal.positions()[3][1] = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_THROW(neighbourhood.update(), Error);
}

TEST(NeighbourhoodTest, ListsWithASkinStayExactWhileReused) { expectListsExactWhileReused(false); }

TEST(NeighbourhoodTest, ListsWithASkinStayExactWhileReusedAcrossAPeriodicFace) {
  expectListsExactWhileReused(true);
}

// A skin that a periodic axis cannot hold (period <= 2 (h + s)) is cut to fit.
TEST(NeighbourhoodTest, ASkinIsCutToFitAPeriodicBox) {
  PeriodicBox box;
  box.setPeriodic(1, 0, Real(0.5));
  const Neighbourhood neighbourhood(Real(0.15), box, Real(0.15));
  EXPECT_NEAR(neighbourhood.skin(), 0.99 * 0.25 - 0.15, 1e-12);
  EXPECT_THROW(Neighbourhood(Real(0.15), PeriodicBox(), Real(-0.01)), Error);
}

}  // namespace
}  // namespace sphcast
