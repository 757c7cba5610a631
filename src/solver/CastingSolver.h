#pragma once

#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bodies/BodySetup.h"
#include "bodies/BodyWallContact.h"
#include "bodies/RigidBody.h"
#include "case/CaseDescription.h"
#include "core/CaseFolder.h"
#include "core/Log.h"
#include "core/TimeControl.h"
#include "inlets/InletSetup.h"
#include "inlets/PouringInlet.h"
#include "io/CaseWriter.h"
#include "io/TimeFolders.h"
#include "parallel/Communicator.h"
#include "parallel/DomainDecomposition.h"
#include "particles/ParticleCloud.h"
#include "post/FunctionObject.h"
#include "solidification/SolidificationSetup.h"
#include "solver/BallisticMotion.h"
#include "solver/CastingModels.h"
#include "solver/HeatStepSchedule.h"
#include "solver/RunMonitor.h"
#include "sph/FlowSetup.h"
#include "surface/SurfaceTensionSetup.h"
#include "thermal/HeatSetup.h"

namespace sphcast {

class Dictionary;

// The casting time loop of sphCastFoam: builds the models constant/physicsModels names over one
// shared neighbourhood, and steps them (evolve() spells out the order of the passes). With a
// flow model the fluid cloud runs weakly compressible SPH among the wall clouds, some of which
// may move as the rigid bodies of constant/dynamicBodies, and the pouring inlets of
// constant/inlets feed the fluid; with
// heatTransfer the heat clouds carry the energy equation (17), with or without a flow (without
// one the particles stay where they are); with neither, the clouds move ballistically under
// constant/g (BallisticMotion).
class CastingSolver {
 public:
  // Reads and checks everything the run needs (controlDict, constant/g, the start time's
  // clouds) before anything is written, so bad input never damages results on disk. With a
  // communicator of more than one rank (-parallel) the run is decomposed by
  // system/decomposeParDict, each rank stepping the particles of its subdomain.
  explicit CastingSolver(const CaseFolder& caseFolder,
                         const Communicator& comm = Communicator::self());

  // Steps from the start time until endTime or a stop request, writing as controlDict asks.
  void run();

  const std::vector<ParticleCloud>& clouds() const { return clouds_; }

 private:
  void loadHeatClouds();
  // What a decomposed run cannot run yet, as an Error naming the entry (before any output).
  void checkParallelSupport() const;
  void setUpNeighbourhood();
  void decompose();
  // The search of a step: the decomposition's (migration, halos) or the neighbourhood's own.
  void searchNeighbours(CloudOrder order, bool rebuild);
  void setUpFlow();
  void loadBodyClouds();  // CastingSolverBodies.cpp
  void setUpBodies();
  void setUpHeat();
  void setUpSolidification();
  void setUpRheology();
  void recordCriticalGradients();
  void startModels();
  void setUpFunctionObjects(const Dictionary& controlDict);
  ParticleCloud* findCloud(const std::string& name);   // nullptr when absent
  ParticleCloud& cloudNamed(const std::string& name);  // throws, listing the clouds present
  double stableDeltaT(std::string& limiter) const;
  FlowStepLimits flowStepLimits(double maxCo) const;
  void evolve(double deltaT);
  void searchAndKeepClear(double deltaT, bool lastOfStep);
  void setUpInlets();  // CastingSolverInlets.cpp
  // <time>/uniform/dynamicBodies and uniform/inlets, as the case has them
  std::vector<UniformFile> uniformStateFiles(const std::string& timeName) const;
  void updateCoolingMode();
  double coolingMaxCo() const;  // the cooling mode's flow steps' Courant number
  void evolveCooling(double deltaT);
  void flowFirstKickAndDrift(double deltaT);
  void flowAdvectionStep(double deltaT);  // dualCriteria's, in place of the kicks
  // The metal outside the domain spilled (MetalSpill.h): logged, and spillStop_ set when the
  // spill passes healthChecks' maxSpilledFraction. heatKickPending: a heat step's first kick
  // with rates that include the spilled metal is still to come (firstHeatKick books it).
  void spillMetalOutside(bool heatKickPending);
  void firstHeatKick(double deltaT);
  void flowRatesAndSecondKick(double deltaT);
  void flushPendingHeat();
  void heatStepInPlace(double deltaT);
  void finishHeatStep();
  void writeResults();
  void logRereadMessage();
  // "cloud" and "cloud.field" of every cloud, sorted: what a time folder of them holds.
  static std::vector<std::string> fieldInventory(const std::vector<ParticleCloud>& clouds);
  // Writes `good` (the last state that passed every check: the clouds as saved before the step)
  // and stops the run with `what` went wrong.
  [[noreturn]] void stopWithLastGoodState(const TimeState& good, bool restoreSaved,
                                          const std::string& what);

  const CaseFolder& caseFolder_;
  Communicator comm_;
  bool parallel_;  // more than one rank
  // Repaired before the start time is chosen: a time folder set aside by a killed write must
  // be back in place when latestTime is looked for.
  std::vector<std::string> repairedWrites_;
  TimeControl time_;
  CaseDescription description_;  // the case's files read once, and the clouds' roles
  Vector gravity_;               // constant/g, else zero (a case that only conducts heat)
  BallisticMotion motion_;
  FlowSetup flowSetup_;
  HeatSetup heatSetup_;
  SurfaceTensionSetup surfaceTensionSetup_;
  SolidificationSetup solidificationSetup_;
  BodySetup bodySetup_;
  InletSetup inletSetup_;
  std::vector<ParticleCloud> clouds_;        // of the time folders: read, stepped, written
  std::vector<ParticleCloud> staticClouds_;  // of constant/particles: read only
  CastingModels models_;                     // built from the case, stepped by evolve()
  bool exposedAreaRestored_ = false;         // read with a restart's clouds
  Domain domain_;
  std::string spillStop_;       // why the spill stops the run (empty: it does not)
  double spilledHeatRate_ = 0;  // sum m du/dt of metal spilled since the last heat rates (W)
  // The clouds before the step being taken (those that change: the fluid, the heat clouds)
  std::vector<ParticleCloud> lastGood_;
  std::vector<ParticleCloud*> evolving_;
  HeatStepSchedule heatSchedule_;  // when the heat steps while a flow steps
  // Cooling to the end (solidificationSetup_.cooling): steps of the heat's length, each with a
  // few flow steps; a fluid cloud attribute (coolingMode) too, so a restart goes on alike.
  bool cooling_ = false;
  RunMonitor monitor_;  // health, log, progress, the account of skipped work
  CaseWriter writer_;
  FunctionObjectList functions_;  // of controlDict's `functions`, run after every step
};

}  // namespace sphcast
