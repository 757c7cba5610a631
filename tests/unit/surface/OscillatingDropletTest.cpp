// The n = 2 oscillation of a free droplet under the surface-energy model against Lamb (the case,
// oscillatingDroplet, and its physics are in SurfaceEnergyCases.h). One check, the n = 2 period
// at 30 particles across in 2D; the rest are studies (their results in doc/validation.md §2.3),
// surfaceTensionStudy's energy-oscillating-drop and energy-static-drop
// (tests/studies/SurfaceTensionStudy.cpp), run by hand.

#include <gtest/gtest.h>

#include <iostream>

#include "SurfaceEnergyCases.h"

namespace sphcast {
namespace {

using testing::DropletResult;
using testing::DropletSetup;
using testing::oscillatingDroplet;

// The calibrated R_d against Lamb: a 2D drop of 30 particles across oscillates in mode n = 2
// with a period within 15 % of his (measured: -2.6 %; with the lattice face's R_d +47 %). The
// tension of a relaxed surface scatters with the arrangement of its particles by about 15 %
// (doc/physics.md §10.1), and the period with the square root of it.
TEST(OscillatingDroplet, PeriodWithinFifteenPercentOfLambsAtThirtyAcross) {
  DropletSetup setup;
  setup.dimension = 2;
  setup.across = 30;
  setup.amplitude = 0.1;
  const DropletResult r = oscillatingDroplet(setup);
  std::cout << r << std::endl;
  EXPECT_NEAR(r.period / r.lambPeriod, 1.0, 0.15);
  EXPECT_LT(r.largestDensityDeviation, 0.01);
}

}  // namespace
}  // namespace sphcast
