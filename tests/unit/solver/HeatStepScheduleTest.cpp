// When the heat steps while a flow steps (solver/HeatStepSchedule.h).
#include "solver/HeatStepSchedule.h"

#include <gtest/gtest.h>

namespace sphcast {
namespace {

TEST(HeatStepSchedule, EveryStepMakesEachFlowStepAHeatStepOfItsLength) {
  HeatStepSchedule schedule(true);
  int asked = 0;
  for (const double deltaT : {1e-5, 2e-5, 3e-5}) {
    EXPECT_TRUE(schedule.stepsAfter(deltaT, false, [&] { return ++asked, 1.0; }));
    EXPECT_EQ(schedule.deltaT(), deltaT);
  }
  EXPECT_EQ(asked, 0);  // the heat's own limit is the step's, taken by the solver
}

// The flow's steps add up to a tenth of the heat's stable step (asked once per heat step), and
// the heat then takes their sum; a write takes what is pending however short.
TEST(HeatStepSchedule, AutoTakesTheFlowStepsSumOnceItReachesATenthOfTheHeatsStableStep) {
  HeatStepSchedule schedule(false);
  int asked = 0;
  const auto stable = [&] { return ++asked, 1.0; };  // a tenth: 0.1
  EXPECT_FALSE(schedule.stepsAfter(0.03, false, stable));
  EXPECT_FALSE(schedule.stepsAfter(0.03, false, stable));
  EXPECT_FALSE(schedule.stepsAfter(0.03, false, stable));
  EXPECT_TRUE(schedule.stepsAfter(0.03, false, stable));
  EXPECT_DOUBLE_EQ(schedule.deltaT(), 0.12);
  EXPECT_EQ(asked, 1);
  EXPECT_FALSE(schedule.stepsAfter(0.02, false, stable));
  EXPECT_TRUE(schedule.stepsAfter(0.02, true, stable));  // a write: nothing stays pending
  EXPECT_DOUBLE_EQ(schedule.deltaT(), 0.04);
  EXPECT_EQ(asked, 2);
  EXPECT_EQ(schedule.takePending(), 0.0);
}

// A flush (a stop between heat steps, the cooling mode's start) takes the pending time as a
// heat step of its own; the next heat step still falls due at the limit asked before.
TEST(HeatStepSchedule, APendingFlushIsAHeatStepApartAndKeepsTheDueLimit) {
  HeatStepSchedule schedule(false);
  int asked = 0;
  const auto stable = [&] { return ++asked, 1.0; };
  EXPECT_FALSE(schedule.stepsAfter(0.05, false, stable));
  const double pending = schedule.takePending();
  EXPECT_DOUBLE_EQ(pending, 0.05);
  schedule.stepApart(pending);
  schedule.countStep();
  EXPECT_DOUBLE_EQ(schedule.deltaT(), 0.05);
  EXPECT_EQ(schedule.steps(), 1);
  EXPECT_FALSE(schedule.stepsAfter(0.05, false, stable));
  EXPECT_TRUE(schedule.stepsAfter(0.05, false, stable));
  EXPECT_DOUBLE_EQ(schedule.deltaT(), 0.1);
  EXPECT_EQ(asked, 1);
}

}  // namespace
}  // namespace sphcast
