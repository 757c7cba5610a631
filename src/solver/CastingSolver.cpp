// sphCastFoam's time loop: the step's length, the flow and heat steps, the cooling mode, the
// writes (construction and set-up: CastingSolverSetup.cpp; the log: CastingSolverLog.cpp; the
// health checks: CastingSolverHealth.cpp).
#include "solver/CastingSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <ostream>
#include <sstream>

#include "core/Error.h"
#include "particles/FieldNames.h"

namespace sphcast {

// The flow's limits over every rank (each the smallest), so that all take the same step.
FlowStepLimits CastingSolver::flowStepLimits(double maxCo) const {
  FlowStepLimits limits = flow_->stepLimits(maxCo);
  if (!parallel_) return limits;
  std::vector<double> each{limits.acoustic,     limits.viscous,     limits.bodyForce,
                           limits.acceleration, limits.densityRate, limits.forceModel};
  comm_.min(each);
  return {each[0], each[1], each[2], each[3], each[4], each[5], limits.forceModelName};
}

double CastingSolver::stableDeltaT(std::string& limiter) const {
  if (cooling_) {  // the flow takes its own steps within (evolveCooling)
    const double heat = energy_->stableDeltaT(limiter);
    limiter += " (cooling)";
    return heat;
  }
  if (flow_ || energy_) {
    double stable = std::numeric_limits<double>::infinity();
    if (flow_) stable = flowStepLimits(time_.settings().maxCo).smallest(limiter);
    if (!movingMolds_.empty()) {
      stable = movingMolds_.limitStep(stable, fluid_->attributes().at("spacing"), limiter);
    }
    // with a flow and `interval auto` the heat takes steps of its own (HeatStepSchedule)
    if (energy_ && heatSchedule_.everyStep()) {
      std::string heatLimiter;
      const double heat = energy_->stableDeltaT(heatLimiter);
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
  if (!flow_ && !energy_) {
    for (ParticleCloud& cloud : clouds_) {
      if (cloud.hasVectorField(field::U)) motion_.step(cloud, deltaT);
    }
    return;
  }
  const bool heatThisStep =
      energy_ && heatSchedule_.stepsAfter(deltaT, time_.writeTime() || time_.progress() >= 1, [&] {
        std::string limiter;
        return energy_->stableDeltaT(limiter);
      });
  if (flow_) flowFirstKickAndDrift(deltaT);
  if (heatThisStep) addWallTime(heatSeconds_, [&] { energy_->halfKick(heatSchedule_.deltaT()); });
  // the search at the new positions (nothing moves without a flow), the quantities models share
  if (flow_) searchAndKeepClear(deltaT, true);
  if (heatThisStep && flow_ && exposedArea_) {
    addWallTime(heatSeconds_, [&] { exposedArea_->compute(); });
  }
  if (flow_) flowRatesAndSecondKick(deltaT);
  if (heatThisStep) {
    addWallTime(heatSeconds_, [&] { finishHeatStep(); });
    heatSchedule_.countStep();
  }
}

// The first half of a flow step: the fluid's and the bodies' first kicks with the rates of the
// current state and their drift, then the metal the inlets pour.
void CastingSolver::flowFirstKickAndDrift(double deltaT) {
  flow_->kickAndDrift(deltaT);
  movingMolds_.drift(deltaT, time_.value());
  pouringInlets_.pour(time_.value(), decomposition_.get());
}

// The second half, after the search: the rates at the new positions and the second kicks, the
// inlets' buffers held.
void CastingSolver::flowRatesAndSecondKick(double deltaT) {
  flow_->computeRatesAndKick(deltaT);
  movingMolds_.kick(deltaT, time_.value());
  pouringInlets_.holdBuffers();
}

// The second half of a heat step: the rates at the new state, the second kick, and the
// solidification that follows the new u.
void CastingSolver::finishHeatStep() {
  energy_->computeRates();
  energy_->halfKick(heatSchedule_.deltaT());
  if (solidification_) {
    solidification_->update(time_.value(), heatSchedule_.deltaT());
    recordCriticalGradients();
  }
}

// A whole heat step of deltaT with the particles where they are: the first kick, the exposed
// area, and finishHeatStep.
void CastingSolver::heatStepInPlace(double deltaT) {
  heatSchedule_.stepApart(deltaT);
  addWallTime(heatSeconds_, [&] {
    energy_->halfKick(deltaT);
    if (exposedArea_) exposedArea_->compute();
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
  addWallTime(searchSeconds_, [&] { searchNeighbours(CloudOrder::byCell, false); });
  if (fillTime_) fillTime_->record(*neighbourhood_, time_.value());
  if (!movingMolds_.empty()) {
    movingMolds_.keepOutOfMolds(static_cast<Real>(fluid_->attributes().at("spacing")));
  }
  flow_->keepClearOfWalls();
  if (written) {
    addWallTime(searchSeconds_, [&] { searchNeighbours(CloudOrder::keep, true); });
  }
  movingMolds_.pushByClearance(deltaT, time_.value());
}

// A stop between heat steps (stopAt writeNow) writes the heat brought up to the time written.
void CastingSolver::flushPendingHeat() {
  if (!energy_) return;
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
      flowStepsWithoutCooling_ += deltaT / limits.smallest(without);
    }
    flowFirstKickAndDrift(flowDeltaT);
    searchAndKeepClear(flowDeltaT, k + 1 == solidificationSetup_.cooling->flowStepsPerHeatStep);
    flowRatesAndSecondKick(flowDeltaT);
    ++flowSubSteps_;
    lastFlowSubStep_ = flowDeltaT;
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
  if (!solidification_ || !solidificationSetup_.cooling) return;
  const CoolingAcceleration& cooling = *solidificationSetup_.cooling;
  double fastest = 0;
  const auto& velocity = fluid_->vectorField(field::U);
  for (std::size_t i = 0; i < fluid_->ownedSize(); ++i) {
    fastest = std::max(fastest, static_cast<double>(velocity[i].norm()));
  }
  // metal still being poured, or none yet, is not a still melt (measured: crossDitchPress
  // entered the mode at t = 0 with its cloud empty, and its ladle fell 0.012 s behind)
  bool pouring = comm_.sum(static_cast<std::int64_t>(fluid_->ownedSize())) == 0;
  pouring = pouring || pouringInlets_.pouring(time_.value());
  // The bodies: the mode's slowed flow time would slow a body's motion hundreds of times, so a
  // body driven by its table keeps the mode off, and one let go (it is held through the step in
  // which its release time falls, and free from the next) ends it: within the last step, or
  // twice the time a free fall takes to reach stillSpeed (one resting on something stays below
  // it; one falling is faster by then, and its speed counts with the melt's).
  const double g = gravity_.norm();
  const double settle = g > 0 ? 2 * cooling.stillSpeed / g : 0;
  const double window = std::max(settle, time_.state().deltaT * (1 + 1e-9));
  std::string bodyMoves;
  for (const auto& body : movingMolds_.bodies()) {
    for (const Vector& v : body->cloud().vectorField(field::U)) {
      fastest = std::max(fastest, static_cast<double>(v.norm()));
    }
    if (body->driven(time_.value())) bodyMoves = "body " + body->settings().name + " is driven";
    if (body->letGoWithin(time_.value(), window)) {
      bodyMoves = "body " + body->settings().name + " was let go";
    }
  }
  fastest = comm_.max(fastest);  // every rank's melt: all decide alike
  const bool wasCooling = cooling_;
  if (!cooling_ && fastest < cooling.stillSpeed && !pouring && bodyMoves.empty()) cooling_ = true;
  if (cooling_ && (fastest > cooling.movingSpeed || !bodyMoves.empty())) cooling_ = false;
  if (cooling_ == wasCooling) return;
  fluid_->attributes()["coolingMode"] = cooling_ ? 1 : 0;
  stepCollapse_.restart();  // the steps change length by design
  if (cooling_) {
    flushPendingHeat();
    info() << "Cooling from time " << time_.timeName() << ": the melt is still (max|U| " << fastest
           << " m/s < " << cooling.stillSpeed << "): steps of the heat's length, each "
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
    const std::string collapse =
        time_.settings().adjustTimeStep
            ? stepCollapse_.check(stable, limiter, health_.minDeltaTFraction)
            : std::string();
    if (!collapse.empty()) {
      stopWithLastGoodState(time_.state(), false, collapse);  // this state passed every check
    }
    time_.adjustDeltaT(stable, limiter);
    if (!time_.settings().adjustTimeStep && (flow_ || energy_) && time_.deltaT() > stable &&
        comm_.master() &&
        warnings_.shouldPrint("a fixed deltaT above the stable step", time_.deltaT() / stable)) {
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
    movingMolds_.saveState();
    pouringInlets_.saveState();
    time_.advance();
    ++stepsTaken_;
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
    if (failure.empty()) failure = addWallTime(checkSeconds_, [&] { return checkHealth(); });
    // what one rank found stops them all, with its message
    if (parallel_) failure = comm_.firstNonEmpty(failure);
    if (!failure.empty()) stopWithLastGoodState(before, true, failure);
    if (solidificationSetup_.endWhenSolid && solidification_->allSolid(comm_)) {
      time_.requestStop("the casting is solid (endWhenSolid)");
    }
    const bool printBlock = stepsTaken_ % time_.settings().logInterval == 0 || time_.writeTime();
    logStep(printBlock);
    if (time_.writeTime()) addWallTime(outputSeconds_, [&] { writeResults(); });
    addWallTime(functionSeconds_, [&] { functions_.execute(time_.state(), time_.writeTime()); });
  }
  logRereadMessage();
  info() << "Stopping: " << time_.stopReason() << " at time " << time_.timeName() << '\n';
  if (time_.finalWriteWanted()) {
    flushPendingHeat();
    addWallTime(outputSeconds_, [&] { writeResults(); });
  }
  logTimeSpent();
  logWorkSkipped();
  if (decomposition_) {  // collective: every rank takes part, rank 0 prints
    const std::string decomposed = decomposition_->describe();
    info() << "Decomposition at the end: " << decomposition_->rebalances() << " re-balances; "
           << decomposed << '\n';
  }
  info() << clock_.timesLine() << "\n\nEnd\n\n";
}

}  // namespace sphcast
