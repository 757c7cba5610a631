// Every OpenMP pass of the flow step (wall pressure, correction, rates, wall clearance,
// integration, step limits, the neighbour lists' blocks) gives the same bits on one thread as on
// two: the loops gather (each particle writes only its own values) and the reductions are max
// and min. The CI runs every other test on one thread, so this is where two threads are
// exercised. (The cell grid's light loops run on one thread below 32,768 particles: the
// neighbour-search benchmarks and tests cover them.)
#include <omp.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "FlowTestCases.h"
#include "particles/FieldNames.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

struct Scheme {
  std::string densityScheme;
  bool kernelCorrection;
  bool dualCriteria = false;  // advection steps of acoustic sub-steps (kickDriftKick: maxCo 0.25)
  bool incompressible = false;  // flow { model incompressible; }
};

// A 2D dam break (a = 15 dx) run for `steps` steps on `threads` threads; the column is released
// against the far wall at 1 m/s so that the wall clearance acts within the steps taken.
ParticleCloud runDamBreak(int threads, const Scheme& scheme, int steps, std::size_t& corrected) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  const Real dx = 0.005;
  auto fluid = testing::fluidBlock2D(15, 30, dx, Vector::Zero(), 1000, 1e-3);
  for (Vector& u : fluid.vectorField(field::U)) u = Vector(1.0, 0, 0);
  auto wall = testing::tankWalls2D(24, 40, dx);
  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = 20;
  settings.gravity = Vector(0, -9.81, 0);
  settings.densityScheme = scheme.densityScheme;
  settings.kernelCorrection = scheme.kernelCorrection;
  settings.dualCriteria = scheme.dualCriteria;
  settings.incompressible = scheme.incompressible;
  WeaklyCompressibleFlow flow(settings, fluid, {&wall});
  std::string limiter;
  corrected = 0;
  for (int step = 0; step < steps; ++step) {
    flow.step(flow.stepLimits(0.25).smallest(limiter));
    corrected += flow.lastWallClearance().corrected;
  }
  omp_set_num_threads(previous);
  std::printf("    %s%s%s%s, %d thread(s): %zu particle corrections by the wall clearance\n",
              scheme.densityScheme.c_str(), scheme.kernelCorrection ? " + correction" : "",
              scheme.dualCriteria ? ", dualCriteria" : "",
              scheme.incompressible ? ", incompressible" : "", threads, corrected);
  return fluid;
}

void expectSameBits(const ParticleCloud& one, const ParticleCloud& two) {
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one.positions()[i], two.positions()[i]) << "particle " << i;
  }
  for (const char* name : {"U", "acceleration"}) {
    for (std::size_t i = 0; i < one.size(); ++i) {
      ASSERT_EQ(one.vectorField(name)[i], two.vectorField(name)[i]) << name << " of " << i;
    }
  }
  for (const char* name : {"rho", "p", "densityRate"}) {
    for (std::size_t i = 0; i < one.size(); ++i) {
      ASSERT_EQ(one.scalarField(name)[i], two.scalarField(name)[i]) << name << " of " << i;
    }
  }
}

TEST(FlowThreadCount, OneAndTwoThreadsGiveTheSameBitsForEveryScheme) {
  for (const Scheme& scheme :
       {Scheme{"riemann", false}, Scheme{"riemann", true}, Scheme{"standard", false},
        Scheme{"deltaSPH", false}, Scheme{"riemann", false, true}, Scheme{"riemann", true, true},
        Scheme{"riemann", false, false, true}}) {
    SCOPED_TRACE(scheme.densityScheme);
    std::size_t correctedOne = 0, correctedTwo = 0;
    expectSameBits(runDamBreak(1, scheme, 200, correctedOne),
                   runDamBreak(2, scheme, 200, correctedTwo));
    EXPECT_EQ(correctedOne, correctedTwo);
    // the plain means let the front reach the wall: the clearance pass is exercised
    if (scheme.densityScheme == "standard") {
      EXPECT_GT(correctedOne, 0u);
    }
  }
}

}  // namespace
}  // namespace sphcast
