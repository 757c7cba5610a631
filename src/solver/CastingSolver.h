#pragma once

#include <vector>

#include "core/CaseFolder.h"
#include "core/Log.h"
#include "core/TimeControl.h"
#include "particles/ParticleCloud.h"
#include "solver/BallisticMotion.h"
#include "solver/CaseWriter.h"

namespace sphcast {

// The casting time loop of sphCastFoam. For now the clouds move ballistically under constant/g
// (BallisticMotion); the SPH flow, heat and solidification models plug in as later passes.
class CastingSolver {
 public:
  // Reads and checks everything the run needs (controlDict, constant/g, the start time's
  // clouds) before anything is written, so bad input never damages results on disk.
  explicit CastingSolver(const CaseFolder& caseFolder);

  // Steps from the start time until endTime or a stop request, writing as controlDict asks.
  void run();

  const std::vector<ParticleCloud>& clouds() const { return clouds_; }

 private:
  double stableDeltaT() const;
  void evolve(double deltaT);
  void writeResults();
  void logStep(bool printBlock);
  void logRereadMessage();

  const CaseFolder& caseFolder_;
  TimeControl time_;
  BallisticMotion motion_;
  std::vector<ParticleCloud> clouds_;
  CaseWriter writer_;
  RunClock clock_;
  long stepsTaken_ = 0;
};

}  // namespace sphcast
