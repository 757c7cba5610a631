// sphCastFoam's time loop: the step's length, the flow and heat steps, the cooling mode, the
// writes, the stop with the last good state (construction and set-up: CastingSolverSetup.cpp;
// the log and the health checks: RunMonitor.cpp).
#include "solver/CastingSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <ostream>
#include <sstream>
#include <utility>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "solver/MetalSpill.h"

namespace sphcast {

// The flow's limits over every rank (each the smallest), so that all take the same step.
FlowStepLimits CastingSolver::flowStepLimits(double maxCo) const {
  // the cooling mode's flow steps are kick-drift-kick's (evolveCooling); the incompressible
  // flow's are always its own (stepLimits takes that)
  FlowStepLimits limits =
      models_.flow->stepLimits(maxCo, flowSetup_.settings.stepsBeforeSearch() && !cooling_);
  if (!parallel_) return limits;
  std::vector<double> each{limits.acoustic,     limits.viscous,     limits.bodyForce,
                           limits.acceleration, limits.densityRate, limits.forceModel,
                           limits.advection};
  comm_.min(each);
  return {each[0], each[1], each[2], each[3], each[4], each[5], limits.forceModelName, each[6]};
}

double CastingSolver::stableDeltaT(std::string& limiter) const {
  if (cooling_) {  // the flow takes its own steps within (evolveCooling)
    const double heat = models_.energy->stableDeltaT(limiter);
    limiter += " (cooling)";
    return heat;
  }
  if (models_.flow || models_.energy) {
    double stable = std::numeric_limits<double>::infinity();
    if (models_.flow) stable = flowStepLimits(time_.settings().maxCo).smallest(limiter);
    if (!models_.movingMolds.empty()) {
      stable =
          models_.movingMolds.limitStep(stable, models_.fluid->attributes().at("spacing"), limiter);
    }
    // with a flow and `interval auto` the heat takes steps of its own (HeatStepSchedule)
    if (models_.energy && heatSchedule_.everyStep()) {
      std::string heatLimiter;
      const double heat = models_.energy->stableDeltaT(heatLimiter);
      if (heat < stable) {
        stable = heat;
        limiter = heatLimiter;
      }
    }
    return stable;
  }
  limiter = "maxCo on particle travel";
  double stable = std::numeric_limits<double>::max();
  for (const ParticleCloud& cloud : clouds_) {
    if (cloud.hasVectorField(field::U)) {
      stable = std::min(stable, motion_.stableDeltaT(cloud, time_.settings().maxCo));
    }
  }
  return stable;
}

// One step: the models' passes over one neighbourhood search, kick-drift-kick (doc/design.md
// §4.1). A heat step, when the schedule makes this one, wraps the flow's search and rates.
void CastingSolver::evolve(double deltaT) {
  if (cooling_) {
    evolveCooling(deltaT);
    return;
  }
  if (!models_.flow && !models_.energy) {
    for (ParticleCloud& cloud : clouds_) {
      if (cloud.hasVectorField(field::U)) motion_.step(cloud, deltaT);
    }
    return;
  }
  const bool heatThisStep =
      models_.energy &&
      heatSchedule_.stepsAfter(deltaT, time_.writeTime() || time_.progress() >= 1, [&] {
        std::string limiter;
        return models_.energy->stableDeltaT(limiter);
      });
  const bool beforeSearch = models_.flow && flowSetup_.settings.stepsBeforeSearch();
  if (beforeSearch) {
    flowAdvectionStep(deltaT);
  } else if (models_.flow) {
    flowFirstKickAndDrift(deltaT);
  }
  if (heatThisStep)
    addWallTime(monitor_.times().heat, [&] { firstHeatKick(heatSchedule_.deltaT()); });
  // before the search places it; after the heat's first kick, the spilled metal leaves with the
  // heat that kick gave it, and the rates computed next are without it
  if (models_.flow) spillMetalOutside(!heatThisStep);
  // the search at the new positions (nothing moves without a flow), the quantities models share
  if (models_.flow) searchAndKeepClear(deltaT, true);
  if (heatThisStep && models_.flow && models_.exposedArea) {
    addWallTime(monitor_.times().heat, [&] { models_.exposedArea->compute(); });
  }
  if (models_.flow && !beforeSearch) flowRatesAndSecondKick(deltaT);
  if (heatThisStep) {
    addWallTime(monitor_.times().heat, [&] { finishHeatStep(); });
    heatSchedule_.countStep();
  }
}

// The first half of a flow step: the fluid's and the bodies' first kicks with the rates of the
// current state and their drift, then the metal the inlets pour.
void CastingSolver::flowFirstKickAndDrift(double deltaT) {
  models_.flow->kickAndDrift(deltaT);
  models_.movingMolds.drift(deltaT, time_.value());
  models_.pouringInlets.pour(time_.value(), models_.decomposition.get());
}

// dualCriteria's flow step: the rheology's viscosity, the advection step's acoustic sub-steps
// with the bodies moved and kicked and the inlets' buffers held in each, then the metal the
// inlets pour (the incompressible step likewise, with one solve of the pressure). The search
// follows.
void CastingSolver::flowAdvectionStep(double deltaT) {
  if (models_.rheology) models_.rheology->update(deltaT);
  // the time at a sub-step's end (the last one's is the step's, to the bit)
  const double end = time_.value();
  auto at = [end, deltaT](double elapsed) {
    return elapsed < deltaT ? end - (deltaT - elapsed) : end;
  };
  WeaklyCompressibleFlow::SubStepHooks hooks;
  if (!models_.movingMolds.empty()) {
    hooks.drift = [&](double dt, double elapsed) { models_.movingMolds.drift(dt, at(elapsed)); };
  }
  hooks.kick = [&](double dt, double elapsed) {
    models_.movingMolds.kick(dt, at(elapsed));
    models_.pouringInlets.holdBuffers();
  };
  if (!models_.movingMolds.empty()) {  // the incompressible step's coupling
    hooks.predict = [&](const ParticleCloud& wall, const Vector& force, const Vector& torque,
                        double dt, std::vector<Vector>& velocity) {
      return models_.movingMolds.predictVelocities(wall, force, torque, dt, end, velocity);
    };
  }
  models_.flow->advectionStep(deltaT, hooks);
  models_.pouringInlets.pour(time_.value(), models_.decomposition.get());
}

// The heat step's first kick, with the rates of the last heat step. Those rates hold what the
// metal spilled since then exchanged with the rest: the heat their kick would have given it
// leaves with it, booked as spilled, so that the books close.
void CastingSolver::firstHeatKick(double deltaT) {
  models_.energy->halfKick(deltaT);
  if (spilledHeatRate_ != 0) {
    models_.fluid->attributes()["heatLost.spilled"] += 0.5 * deltaT * spilledHeatRate_;
    spilledHeatRate_ = 0;
  }
}

void CastingSolver::spillMetalOutside(bool heatKickPending) {
  const Spill spill = addWallTime(monitor_.times().checks, [&] {  // a check's pass over the metal
    return spillOutside(*models_.fluid, domain_, models_.decomposition.get(), comm_);
  });
  if (spill.particles == 0) return;
  if (heatKickPending) spilledHeatRate_ += spill.heatRate;
  const double fraction = spilledFraction(*models_.fluid, comm_);
  const double limit = monitor_.healthSettings().maxSpilledFraction;
  std::ostringstream message;
  message.precision(4);
  message << spill.particles << " particle(s) of cloud '" << models_.fluid->name()
          << "' left the domain and were spilled"
          << (spill.first.empty() ? "" : " (the first, " + spill.first + ")") << "; spilled in all "
          << models_.fluid->attributes().at("spilledParticles") << " particles, "
          << models_.fluid->attributes().at("spilledMass") << " kg, " << 100 * fraction
          << " % of its mass";
  if (fraction > limit) {
    message << ", above healthChecks maxSpilledFraction " << 100 * limit
            << " %: the mold leaks, or the case spills more than it allows";
    spillStop_ = message.str();
  } else if (comm_.master() && monitor_.warnings().shouldPrint("fluid spilled", fraction)) {
    warning("time " + time_.timeName() + ": " + message.str());
  }
}

// The second half, after the search: the rheology's viscosity, the rates at the new positions
// and the second kicks, the inlets' buffers held.
void CastingSolver::flowRatesAndSecondKick(double deltaT) {
  if (models_.rheology) models_.rheology->update(deltaT);  // the viscosity the rates take
  models_.flow->computeRatesAndKick(deltaT);
  models_.movingMolds.kick(deltaT, time_.value());
  models_.pouringInlets.holdBuffers();
}

// The second half of a heat step: the rates at the new state, the second kick, and the
// solidification that follows the new u.
void CastingSolver::finishHeatStep() {
  models_.energy->computeRates();
  models_.energy->halfKick(heatSchedule_.deltaT());
  if (models_.solidification) {
    models_.solidification->update(time_.value(), heatSchedule_.deltaT());
    recordCriticalGradients();
  }
}

// A whole heat step of deltaT with the particles where they are: the first kick, the exposed
// area, and finishHeatStep.
void CastingSolver::heatStepInPlace(double deltaT) {
  heatSchedule_.stepApart(deltaT);
  addWallTime(monitor_.times().heat, [&] {
    firstHeatKick(deltaT);
    if (models_.exposedArea) models_.exposedArea->compute();
    finishHeatStep();
  });
  heatSchedule_.countStep();
}

// The search at the new positions, the fluid's first wall contacts, the bodies kept out of the
// other molds, and the wall clearance with its impulse on the bodies.
// A state that will be written is searched afresh, after the clearance moved what it moves,
// and without a reorder (the clearance's impulses are per particle): a restart from it searches
// the same positions in the same order and goes on bit for bit.
void CastingSolver::searchAndKeepClear(double deltaT, bool lastOfStep) {
  const bool written = lastOfStep && (time_.writeTime() || time_.progress() >= 1);
  addWallTime(monitor_.times().search, [&] { searchNeighbours(CloudOrder::byCell, false); });
  if (models_.fillTime) models_.fillTime->record(*models_.neighbourhood, time_.value());
  if (!models_.movingMolds.empty()) {
    models_.movingMolds.keepOutOfMolds(
        static_cast<Real>(models_.fluid->attributes().at("spacing")));
  }
  models_.flow->keepClearOfWalls();
  if (written) {
    addWallTime(monitor_.times().search, [&] { searchNeighbours(CloudOrder::keep, true); });
  }
  models_.movingMolds.pushByClearance(deltaT, time_.value());
}

// A stop between heat steps (stopAt writeNow) writes the heat brought up to the time written.
void CastingSolver::flushPendingHeat() {
  if (!models_.energy) return;
  if (const double pending = heatSchedule_.takePending(); pending != 0) heatStepInPlace(pending);
}

// Once the melt is still, the heat sets the pace (doc/physics.md §10.5): a step of the
// heat's stable length with the particles where they are, then flowStepsPerHeatStep flow steps
// of the acoustic length, in which the melt answers the rho_s the heat step changed (shrinkage
// feeding). The flow's time thus runs heat step / (n acoustic steps) times slower than the heat's:
// right for a melt that creeps, wrong for one that moves (updateCoolingMode leaves the mode then).
void CastingSolver::evolveCooling(double deltaT) {
  heatStepInPlace(deltaT);
  for (int k = 0; k < solidificationSetup_.cooling->flowStepsPerHeatStep; ++k) {
    std::string limiter;
    FlowStepLimits limits = flowStepLimits(coolingMaxCo());
    const double flowDeltaT = limits.smallest(limiter);
    if (!(flowDeltaT > 0) || !std::isfinite(flowDeltaT)) {
      std::ostringstream problem;
      problem << "the flow's stable step (" << limiter << ") is " << flowDeltaT;
      throw Error(problem.str());
    }
    if (k == 0) {  // the steps controlDict's maxCo would take instead, for logWorkSkipped
      limits.acoustic *= time_.settings().maxCo / coolingMaxCo();  // the limit scales with maxCo
      std::string without;
      monitor_.counts().flowStepsWithoutCooling += deltaT / limits.smallest(without);
    }
    const bool beforeSearch = flowSetup_.settings.incompressible;  // its only step
    if (beforeSearch) {
      flowAdvectionStep(flowDeltaT);
    } else {
      flowFirstKickAndDrift(flowDeltaT);
    }
    spillMetalOutside(true);  // the next heat step's first kick takes the rates with them
    searchAndKeepClear(flowDeltaT, k + 1 == solidificationSetup_.cooling->flowStepsPerHeatStep);
    if (!beforeSearch) flowRatesAndSecondKick(flowDeltaT);
    ++monitor_.counts().flowSubSteps;
    monitor_.counts().lastFlowSubStep = flowDeltaT;
  }
}

double CastingSolver::coolingMaxCo() const {
  const double own = solidificationSetup_.cooling ? solidificationSetup_.cooling->maxCo : 0;
  return own > 0 ? own : time_.settings().maxCo;
}

// Enters the cooling mode when the melt is still (max|U| below stillSpeed), leaves it when the
// melt moves fast (above movingSpeed: a collapse), at the start of a step: the decision depends
// on the state only (and the mode, which the fluid carries as an attribute), so a restart takes
// the same one.
void CastingSolver::updateCoolingMode() {
  if (!models_.solidification || !solidificationSetup_.cooling) return;
  const CoolingAcceleration& cooling = *solidificationSetup_.cooling;
  double fastest = 0;
  std::int64_t moving = 0;  // the melt's particles at stillSpeed or faster
  const auto& velocity = models_.fluid->vectorField(field::U);
  for (std::size_t i = 0; i < models_.fluid->ownedSize(); ++i) {
    const double speed = static_cast<double>(velocity[i].norm());
    fastest = std::max(fastest, speed);
    if (speed >= cooling.stillSpeed) ++moving;
  }
  // metal still being poured, or none yet, is not a still melt (measured: crossDitchPress
  // entered the mode at t = 0 with its cloud empty, and its ladle fell 0.012 s behind)
  const std::int64_t melt = comm_.sum(static_cast<std::int64_t>(models_.fluid->ownedSize()));
  moving = comm_.sum(moving);
  bool pouring = melt == 0;
  pouring = pouring || models_.pouringInlets.pouring(time_.value());
  // The bodies: the mode's slowed flow time would slow a body's motion hundreds of times, so a
  // body driven by its table keeps the mode off, and one let go (it is held through the step in
  // which its release time falls, and free from the next) ends it: within the last step, or
  // twice the time a free fall takes to reach stillSpeed (one resting on something stays below
  // it; one falling is faster by then, and its speed counts with the melt's).
  const double g = gravity_.norm();
  const double settle = g > 0 ? 2 * cooling.stillSpeed / g : 0;
  const double window = std::max(settle, time_.state().deltaT * (1 + 1e-9));
  std::string bodyMoves;
  double fastestBody = 0;
  for (const auto& body : models_.movingMolds.bodies()) {
    for (const Vector& v : body->cloud().vectorField(field::U)) {
      fastestBody = std::max(fastestBody, static_cast<double>(v.norm()));
    }
    if (body->driven(time_.value())) bodyMoves = "body " + body->settings().name + " is driven";
    if (body->letGoWithin(time_.value(), window)) {
      bodyMoves = "body " + body->settings().name + " was let go";
    }
  }
  fastest = comm_.max(std::max(fastest, fastestBody));  // every rank's: all decide alike
  fastestBody = comm_.max(fastestBody);
  // still: no more of the melt at stillSpeed than stillFraction allows (0: none, max|U| below
  // it), and the bodies slower
  const bool still = moving <= static_cast<std::int64_t>(cooling.stillFraction * double(melt)) &&
                     fastestBody < cooling.stillSpeed;
  const bool wasCooling = cooling_;
  if (!cooling_ && still && !pouring && bodyMoves.empty()) cooling_ = true;
  if (cooling_ && (fastest > cooling.movingSpeed || !bodyMoves.empty())) cooling_ = false;
  if (cooling_ == wasCooling) return;
  models_.fluid->attributes()["coolingMode"] = cooling_ ? 1 : 0;
  monitor_.restartStepWatch();  // the steps change length by design
  if (cooling_) {
    flushPendingHeat();
    info() << "Cooling from time " << time_.timeName() << ": the melt is still (max|U| " << fastest
           << " m/s, " << moving << " of " << melt << " particles at " << cooling.stillSpeed
           << " m/s or faster): steps of the heat's length, each "
           << "followed by " << cooling.flowStepsPerHeatStep << " acoustic flow steps (maxCo "
           << coolingMaxCo() << ")\n\n";
  } else {
    info() << "Cooling paused at time " << time_.timeName() << ": ";
    if (!bodyMoves.empty()) {
      info() << bodyMoves;
    } else {
      info() << "the melt moves (max|U| " << fastest << " m/s > " << cooling.movingSpeed << ")";
    }
    info() << ": every step acoustic again\n\n";
  }
}

void CastingSolver::writeResults() {
  std::vector<const ParticleCloud*> written;
  for (const ParticleCloud& cloud : clouds_) written.push_back(&cloud);
  writer_.setPurgeWrite(time_.settings().purgeWrite);
  writer_.write(time_.state(), written, uniformStateFiles(time_.timeName()));
  info() << "Writing time " << time_.timeName() << std::endl;
}

void CastingSolver::run() {
  info() << "Starting time loop\n\n";
  functions_.execute(time_.state(), false);
  while (time_.run()) {
    logRereadMessage();
    updateCoolingMode();
    std::string limiter;
    const double stable = stableDeltaT(limiter);
    const std::string collapse = time_.settings().adjustTimeStep
                                     ? monitor_.checkStepCollapse(stable, limiter)
                                     : std::string();
    if (!collapse.empty()) {
      stopWithLastGoodState(time_.state(), false, collapse);  // this state passed every check
    }
    time_.adjustDeltaT(stable, limiter);
    if (!time_.settings().adjustTimeStep && (models_.flow || models_.energy) &&
        time_.deltaT() > stable && comm_.master() &&
        monitor_.warnings().shouldPrint("a fixed deltaT above the stable step",
                                        time_.deltaT() / stable)) {
      std::ostringstream message;
      message.precision(4);
      message << "time " << time_.timeName() << ": the fixed deltaT " << time_.deltaT() << " s is "
              << time_.deltaT() / stable << " times the stable step " << stable << " s (" << limiter
              << "); set adjustTimeStep yes, or a smaller deltaT";
      warning(message.str());
    }
    const TimeState before = time_.state();
    // reuses their storage: no allocation per step
    for (std::size_t c = 0; c < evolving_.size(); ++c) lastGood_[c] = *evolving_[c];
    models_.movingMolds.saveState();
    models_.pouringInlets.saveState();
    time_.advance();
    ++monitor_.counts().steps;
    // A step that throws (a far-flung particle the cell grid cannot place, memory exhausted)
    // stops the run the same way as a failed check: with the last good state written.
    // In a parallel run the other ranks would wait for the failed one inside the step: the
    // error ends every rank (runApplication), and the last written time is the good state.
    std::string failure;
    try {
      evolve(time_.deltaT());
    } catch (const std::bad_alloc&) {
      if (parallel_) throw;
      failure = "the step ran out of memory";
    } catch (const std::exception& error) {
      if (parallel_) throw;
      failure = std::string("the step failed: ") + error.what();
    }
    if (failure.empty()) failure = std::exchange(spillStop_, std::string());
    if (failure.empty())
      failure = addWallTime(monitor_.times().checks,
                            [&] { return monitor_.checkHealth(clouds_, domain_); });
    // what one rank found stops them all, with its message
    if (parallel_) failure = comm_.firstNonEmpty(failure);
    if (!failure.empty()) stopWithLastGoodState(before, true, failure);
    if (solidificationSetup_.endWhenSolid && models_.solidification->allSolid(comm_)) {
      time_.requestStop("the casting is solid (endWhenSolid)");
    }
    const bool printBlock =
        monitor_.counts().steps % time_.settings().logInterval == 0 || time_.writeTime();
    monitor_.logStep(printBlock, cooling_);
    if (time_.writeTime()) addWallTime(monitor_.times().output, [&] { writeResults(); });
    addWallTime(monitor_.times().functions,
                [&] { functions_.execute(time_.state(), time_.writeTime()); });
  }
  logRereadMessage();
  info() << "Stopping: " << time_.stopReason() << " at time " << time_.timeName() << '\n';
  if (time_.finalWriteWanted()) {
    flushPendingHeat();
    addWallTime(monitor_.times().output, [&] { writeResults(); });
  }
  monitor_.logTimeSpent();
  monitor_.logWorkSkipped();
  if (models_.decomposition) {  // collective: every rank takes part, rank 0 prints
    const std::string decomposed = models_.decomposition->describe();
    info() << "Decomposition at the end: " << models_.decomposition->rebalances()
           << " re-balances; " << decomposed << '\n';
  }
  info() << monitor_.clock().timesLine() << "\n\nEnd\n\n";
}

// Every rank of a parallel run stops here alike (the failure is shared before), so the errors
// are CollectiveErrors: rank 0 prints them.
void CastingSolver::stopWithLastGoodState(const TimeState& good, bool restoreSaved,
                                          const std::string& what) {
  const std::string badTime = time_.timeName();
  const long badIndex = time_.timeIndex();
  monitor_.logTimeSpent();
  const std::string failure =
      "at time " + badTime + " (step " + std::to_string(badIndex) + "): " + what + ". ";
  // Only the models keep the state before the step; ballistic clouds have nothing to go back
  // to.
  if (restoreSaved && evolving_.empty()) {
    throw CollectiveError(failure +
                          "Nothing is written: the last written time is the last good state.");
  }
  // The start time is on disk as it was read: rewriting it would store the rates of this run's
  // settings in it, and a rerun with other settings would start from them.
  if (good.name == time_.startTimeName()) {
    throw CollectiveError(failure + "The last good state is the start time " + good.name +
                          ", left as it was; change maxCo, deltaT or soundSpeed and run again.");
  }
  if (restoreSaved) {
    for (std::size_t c = 0; c < evolving_.size(); ++c) *evolving_[c] = lastGood_[c];
    models_.movingMolds.restoreState(good.value);
    models_.pouringInlets.restoreState();
  }
  std::vector<const ParticleCloud*> written;
  for (const ParticleCloud& cloud : clouds_) written.push_back(&cloud);
  writer_.write(good, written, uniformStateFiles(good.name));
  throw CollectiveError(
      failure + "The last good state, time " + good.name +
      ", is written (it passed every check); restart from it with a smaller maxCo or "
      "deltaT, a larger soundSpeed, or look for a gap in the walls there.");
}

void CastingSolver::logRereadMessage() {
  const std::string message = time_.takeRereadMessage();
  if (!message.empty()) info() << message << "\n\n";
}

}  // namespace sphcast
