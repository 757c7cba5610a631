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
#include "solver/ParticleCheck.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {

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
  void setUpFunctionObjects();
  ParticleCloud* findCloud(const std::string& name);   // nullptr when absent
  ParticleCloud& cloudNamed(const std::string& name);  // throws, listing the clouds present
  double stableDeltaT(std::string& limiter) const;
  void evolve(double deltaT);
  void writeResults();
  void logStep(bool printBlock);
  void logRereadMessage();
  void stopIfParticlesWentBad(const TimeState& before);

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
  CaseWriter writer_;
  FunctionObjectList functions_;  // of controlDict's `functions`, run after every step
  RunClock clock_;
  long stepsTaken_ = 0;
};

}  // namespace sphcast
