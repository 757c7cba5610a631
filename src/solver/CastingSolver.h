#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/CaseFolder.h"
#include "core/Log.h"
#include "core/TimeControl.h"
#include "particles/ParticleCloud.h"
#include "post/FunctionObject.h"
#include "solver/BallisticMotion.h"
#include "solver/CaseWriter.h"
#include "solver/FlowSetup.h"
#include "solver/RunHealth.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {

class Dictionary;

// The casting time loop of sphCastFoam. With a flow model in constant/physicsModels the fluid
// cloud runs weakly compressible SPH among the wall clouds; without one the clouds move
// ballistically under constant/g (BallisticMotion). Heat and solidification plug in as later
// passes.
class CastingSolver {
 public:
  // Reads and checks everything the run needs (controlDict, constant/g, the start time's
  // clouds) before anything is written, so bad input never damages results on disk.
  explicit CastingSolver(const CaseFolder& caseFolder);

  // Steps from the start time until endTime or a stop request, writing as controlDict asks.
  void run();

  const std::vector<ParticleCloud>& clouds() const { return clouds_; }

 private:
  void setUpFlow();
  void setUpFunctionObjects(const Dictionary& controlDict);
  ParticleCloud* findCloud(const std::string& name);   // nullptr when absent
  ParticleCloud& cloudNamed(const std::string& name);  // throws, listing the clouds present
  double stableDeltaT(std::string& limiter) const;
  void evolve(double deltaT);
  void writeResults();
  void logStep(bool printBlock);
  void logRereadMessage();
  void logTimeSpent();
  // Why the run must stop after the step just taken, or "" when every check passed; warns in
  // the log about what is bad but not yet fatal.
  std::string checkHealth();
  // Why the run must stop before the next step, from the models' stable step: "" when it is not
  // far below its running mean.
  std::string checkStepCollapse(double stableDeltaT, const std::string& limiter);
  // Writes `good` (the last state that passed every check: the clouds as saved before the step)
  // and stops the run with `what` went wrong.
  [[noreturn]] void stopWithLastGoodState(const TimeState& good, bool restoreSaved,
                                          const std::string& what);

  const CaseFolder& caseFolder_;
  // Repaired before the start time is chosen: a time folder set aside by a killed write must
  // be back in place when latestTime is looked for.
  std::vector<std::string> repairedWrites_;
  TimeControl time_;
  Vector gravity_;
  BallisticMotion motion_;
  FlowSetup flowSetup_;
  std::vector<ParticleCloud> clouds_;        // of the time folders: read, stepped, written
  std::vector<ParticleCloud> staticClouds_;  // of constant/particles: read only
  std::unique_ptr<WeaklyCompressibleFlow> flow_;
  ParticleCloud* fluid_ = nullptr;
  Domain domain_;
  std::unique_ptr<ParticleCloud> lastGoodFluid_;  // the fluid before the step being taken
  HealthSettings health_;
  HealthWarnings warnings_;
  double meanStableDeltaT_ = 0;  // running mean of the models' stable step
  double checkSeconds_ = 0, outputSeconds_ = 0, functionSeconds_ = 0;
  CaseWriter writer_;
  FunctionObjectList functions_;  // of controlDict's `functions`, run after every step
  RunClock clock_;
  long stepsTaken_ = 0;
};

}  // namespace sphcast
