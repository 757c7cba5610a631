#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/Log.h"
#include "core/TimeControl.h"
#include "parallel/Communicator.h"
#include "particles/Domain.h"
#include "solidification/SolidificationSetup.h"
#include "solver/CastingModels.h"
#include "solver/HeatStepSchedule.h"
#include "solver/RunHealth.h"
#include "sph/FlowSetup.h"
#include "thermal/HeatSetup.h"

namespace sphcast {

// What a run has counted since its start, for the log and the account of skipped work.
struct RunCounts {
  long steps = 0;                      // steps taken
  long flowSubSteps = 0;               // the cooling mode's flow steps
  double lastFlowSubStep = 0;          // s, the last of them
  double flowStepsWithoutCooling = 0;  // the flow steps controlDict's maxCo would have taken
};

// Wall seconds spent in the parts of the run that are not a model's own timing.
struct RunTimes {
  double search = 0;     // neighbour searches (the step's and the written state's)
  double heat = 0;       // heat steps
  double checks = 0;     // the health checks
  double output = 0;     // time folders written
  double functions = 0;  // function objects
};

// The run's monitor: the health checks after each step, the log's block at a printed step and
// its account at the end (time spent, work skipped), the progress with its estimate of the end.
// It reads the models and never changes them; the solver stops the run on what it finds.
class RunMonitor {
 public:
  RunMonitor(const CastingModels& models, const TimeControl& time, const Communicator& comm,
             const HeatStepSchedule& heatSchedule, const FlowSetup& flow, const HeatSetup& heat,
             const SolidificationSetup& solidification);

  // controlDict's healthChecks (HealthSettings::read).
  void setHealthSettings(const HealthSettings& settings) { health_ = settings; }
  const HealthSettings& healthSettings() const { return health_; }

  // Why the run must stop after the step just taken, or "" when every check passed; warns in
  // the log about what is bad but not yet fatal. `clouds` are every cloud of the run.
  std::string checkHealth(const std::vector<ParticleCloud>& clouds, const Domain& domain);
  // Why the run must stop before a step whose models' stable length is `stable`, or "".
  std::string checkStepCollapse(double stable, const std::string& limiter) {
    return stepCollapse_.check(stable, limiter, health_.minDeltaTFraction);
  }
  // The steps change length by design (the cooling mode starts or stops).
  void restartStepWatch() { stepCollapse_.restart(); }
  HealthWarnings& warnings() { return warnings_; }

  // The block of a printed step; `cooling`: the run is in the cooling mode.
  void logStep(bool printBlock, bool cooling);
  // The solidification's line (at the start, and in a printed step's block).
  void logSolidification(bool cooling);
  void logTimeSpent();
  void logWorkSkipped();
  const RunClock& clock() const { return clock_; }

  RunCounts& counts() { return counts_; }
  RunTimes& times() { return times_; }

 private:
  void logHeat(bool cooling);
  std::string checkTemperatures() const;
  // The wall seconds to all solid when the run ends on it (endWhenSolid), for the ETA.
  std::optional<std::pair<double, std::string>> solidEnd() const;

  const CastingModels& models_;
  const TimeControl& time_;
  Communicator comm_;
  const HeatStepSchedule& heatSchedule_;
  const FlowSetup& flow_;
  const HeatSetup& heat_;
  const SolidificationSetup& solidification_;
  HealthSettings health_;
  HealthWarnings warnings_;
  StepCollapseWatch stepCollapse_;    // the models' stable step against its running mean
  CompletionEstimate solidEstimate_;  // the wall time to all solid, for the ETA (endWhenSolid)
  RunClock clock_;
  RunCounts counts_;
  RunTimes times_;
};

}  // namespace sphcast
