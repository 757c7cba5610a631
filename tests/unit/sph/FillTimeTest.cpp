// The fill time (sph/FillTime.h): a block of fluid dropped from rest in a tank touches the floor
// when its bottom row, in free fall, comes within 1.75 spacings of the floor's first wall layer,
// t = sqrt(2 (9.25 dx) / g), all ten particles within 1 % of it; the rows above touch later (the
// impact spreads the block) or not at all, and nothing touches before; on two threads the same
// bits.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "FlowTestCases.h"
#include "particles/Neighbourhood.h"
#include "sph/FillTime.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

constexpr Real dx = 0.01, g = 9.81;
// contact: within 1.75 dx of the floor's first layer (y = -0.5 dx), the bottom row (from
// y = 10.5 dx) below y = 1.25 dx: a free fall of 9.25 dx
const double contact = std::sqrt(2 * 9.25 * dx / g);  // 0.137 s

// The block, 10 x 4 particles, its bottom row at y = 10.5 dx, dropped to 1.2 times the contact.
ParticleCloud dropBlock(int threads) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  auto fluid = testing::fluidBlock2D(10, 4, dx, Vector(10 * dx, 10 * dx, 0), 1000, 1e-3);
  auto& rows = fluid.addIdField("row");
  for (std::size_t i = 0; i < fluid.size(); ++i) rows[i] = std::int64_t(i / 10);
  const auto wall = testing::tankWalls2D(30, 20, dx);
  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = 10 * std::sqrt(g * Real(0.2));
  settings.gravity = Vector(0, -g, 0);
  Neighbourhood neighbourhood(settings.supportRadius, PeriodicBox());
  WeaklyCompressibleFlow flow(settings, fluid, {&wall}, neighbourhood);
  FillTime fillTime(fluid, {&wall});
  neighbourhood.update();
  flow.start();
  fillTime.record(neighbourhood, 0.0);
  for (const Real f : fluid.scalarField(FillTime::field)) EXPECT_EQ(f, -1);
  double t = 0;
  std::string limiter;
  while (t < 1.2 * contact) {
    const double dt = flow.stepLimits(0.25).smallest(limiter);
    flow.kickAndDrift(dt);
    neighbourhood.update();
    t += dt;
    fillTime.record(neighbourhood, t);
    flow.keepClearOfWalls();
    flow.computeRatesAndKick(dt);
  }
  omp_set_num_threads(previous);
  return fluid;
}

TEST(FillTime, ABlockDroppedOnAFloorTouchesItWhenItsBottomRowArrives) {
  const ParticleCloud fluid = dropBlock(1);
  const auto& fill = fluid.scalarField(FillTime::field);
  const auto& row = fluid.idField("row");  // the cloud is reordered along its grid each step
  double firstBottom = 1e9, lastBottom = 0, firstAbove = 1e9;
  std::size_t bottom = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    if (row[i] == 0 && fill[i] >= 0) {
      ++bottom;
      firstBottom = std::min(firstBottom, double(fill[i]));
      lastBottom = std::max(lastBottom, double(fill[i]));
    }
    if (row[i] > 0 && fill[i] >= 0) firstAbove = std::min(firstAbove, double(fill[i]));
  }
  std::printf("bottom row: %zu of 10 touched at %.4f .. %.4f s, free fall to contact %.4f s; "
              "the rows above from %.4f s\n",
              bottom, firstBottom, lastBottom, contact, firstAbove);
  EXPECT_EQ(bottom, 10u);
  EXPECT_NEAR(firstBottom, contact, 0.01 * contact);
  EXPECT_LT(lastBottom, 1.01 * contact);
  EXPECT_GT(firstAbove, lastBottom);
  // the pass over the pairs on two threads: the same bits
  EXPECT_TRUE(dropBlock(2).identicalTo(fluid));
}

}  // namespace
}  // namespace sphcast
