// What the solver prints at each printed step and at the end (OpenFOAM's log style).
#include "particles/FieldNames.h"
#include "solver/CastingSolver.h"

#include <sys/resource.h>

#include <algorithm>
#include <limits>
#include <ostream>
#include <sstream>

namespace sphcast {

void CastingSolver::logStep(bool printBlock) {
  if (!printBlock) return;
  info() << "deltaT = " << time_.deltaT() << "  (" << time_.deltaTLimiter() << ")\n"
         << "Time = " << time_.timeName() << "\n\n";
  if (flow_) {
    const FluidSummary summary = summarizeFluid(*fluid_, comm_);
    const FlowSettings& settings = flowSetup_.settings;
    const double spacing = fluid_->attributes().at("spacing");
    const double courant = (static_cast<double>(settings.soundSpeed) + summary.largestSpeed) *
                           time_.deltaT() / spacing;
    std::ostringstream line;
    line.precision(6);
    line << "Step " << time_.timeIndex() << "  Courant " << courant << "  max|U| "
         << summary.largestSpeed << " m/s  Mach "
         << summary.largestSpeed / static_cast<double>(settings.soundSpeed) << '\n'
         << "Density range " << summary.lowestDensity << " .. " << summary.highestDensity
         << " kg/m^3 (" << 100 * summary.lowestDeviation << " .. " << 100 * summary.highestDeviation
         << " % of rho_s)  p " << summary.lowestPressure << " .. " << summary.highestPressure
         << " Pa\n"
         << "Mass " << summary.mass << " kg  kinetic energy " << summary.kineticEnergy
         << " J  moved back from walls "
         << comm_.sum(static_cast<std::int64_t>(flow_->lastWallClearance().corrected)) << '\n';
    info() << line.str();
  }
  if (!movingMolds_.empty()) movingMolds_.log(fluid_->attributes().at("spacing"));
  pouringInlets_.log(time_.value());
  if (energy_) logHeat();
  if (solidification_) logSolidification();
  info() << clock_.timesLine() << '\n'
         << clock_.progressLine(time_.progress(), stepsTaken_, solidEnd()) << '\n'
         << std::endl;  // flushed: a killed run's log ends at its last step
}

void CastingSolver::logHeat() {
  std::ostringstream line;
  line.precision(6);
  if (flow_) {
    std::string limiter;
    const double limit = energy_->stableDeltaT(limiter);
    line << "Heat: " << heatSchedule_.steps() << " heat steps in " << stepsTaken_ << " steps ("
         << (cooling_                       ? "cooling"
             : heatSetup_.heatEveryFlowStep ? "every flow step"
                                            : "interval auto")
         << ", the last " << heatSchedule_.deltaT() << " s long; " << limiter << " limit " << limit
         << " s)\n";
  }
  for (const HeatCloud& heat : energy_->context().clouds) {
    if (heat.fixedTemperature) continue;
    const auto& T = heat.cloud->scalarField(field::T);
    const auto& u = heat.cloud->scalarField(field::u);
    const auto& mass = heat.cloud->scalarField(field::mass);
    double lowest = std::numeric_limits<double>::infinity(), highest = -lowest, energy = 0;
    for (std::size_t i = 0; i < heat.cloud->ownedSize(); ++i) {
      lowest = std::min(lowest, double(T[i]));
      highest = std::max(highest, double(T[i]));
      energy += double(mass[i]) * double(u[i]);
    }
    lowest = comm_.min(lowest);  // every rank's
    highest = comm_.max(highest);
    energy = comm_.sum(energy);
    line << "T " << heat.cloud->name() << ' ' << lowest << " .. " << highest
         << " K  internal energy " << energy << " J\n";
  }
  info() << line.str();
}

std::optional<std::pair<double, std::string>> CastingSolver::solidEnd() const {
  if (!solidification_ || !solidificationSetup_.endWhenSolid) return std::nullopt;
  const auto seconds = solidEstimate_.secondsLeft();
  if (!seconds) return std::nullopt;
  return std::make_pair(*seconds, std::string("all solid, endWhenSolid"));
}

void CastingSolver::logSolidification() {
  const SolidificationSummary s = solidification_->summary(comm_);
  std::ostringstream line;
  line.precision(4);
  line << "Solidification: solid fraction " << s.solidFraction << " (by mass); of " << s.particles
       << " particles " << s.liquid << " liquid, " << s.frozen << " frozen (" << s.solid
       << " fully solid), " << s.particles - s.frozen << " flowing";
  if (s.viscosityCapped > 0) line << " (" << s.viscosityCapped << " with mu capped)";
  // with endWhenSolid the run ends with the last liquid, not at endTime: the progress line's
  // ETA follows the rise of the solid fraction (CompletionEstimate)
  if (solidificationSetup_.endWhenSolid) solidEstimate_.add(clock_.clockTime(), s.solidFraction);
  if (cooling_) {
    line << "\n    cooling: heat steps of " << heatSchedule_.deltaT() << " s, each with "
         << solidificationSetup_.cooling->flowStepsPerHeatStep << " flow steps (the last "
         << lastFlowSubStep_ << " s); " << flowSubSteps_ << " flow steps so far";
  }
  info() << line.str() << '\n';
}

void CastingSolver::logTimeSpent() {
  std::ostringstream line;
  line.precision(3);
  line << "Time spent (wall, s):";
  if (neighbourhood_) line << " neighbour search " << searchSeconds_ << ",";
  if (flow_) {
    const FlowTimings& t = flow_->timings();
    line << " wall clearance " << t.wallClearance << ", flow rates " << t.rates;
    if (surfaceTension_) line << " (surface tension " << surfaceTension_->seconds() << ")";
    line << ", flow integration " << t.integration << ",";
  }
  if (energy_) line << " heat " << heatSeconds_ << ",";
  line << " health checks " << checkSeconds_ << ", function objects " << functionSeconds_
       << ", output " << outputSeconds_;
  info() << line.str() << '\n';
  if (neighbourhood_) {
    info() << "Pair lists: searched in the cells " << neighbourhood_->rebuildCount()
           << " times, filtered from the last search " << neighbourhood_->reuseCount()
           << " times (skin " << neighbourhood_->skin() << " m)\n";
  }
  info() << "Run health: " << warnings_.summary() << '\n';
  // the process's peak resident memory (Linux gives ru_maxrss in KiB): what a larger case needs
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) == 0) {
    info() << "Peak memory (resident): " << double(usage.ru_maxrss) / 1024.0 << " MiB\n";
  }
}

// What the run left out, and about what it saved at its own measured cost per unit of work (an
// estimate: the skipped work would have cost about what the same work cost where it was done).
void CastingSolver::logWorkSkipped() {
  if (!flow_) return;
  const FlowWork& work = flow_->work();
  const FlowTimings& t = flow_->timings();
  std::ostringstream line;
  line.precision(3);
  line << "Work skipped since this start (estimates at this run's own cost):";
  bool skippedAny = false;
  const std::uint64_t computed = work.particleSteps - work.skippedFrozen;
  if (work.skippedFrozen > 0 && computed > 0) {
    skippedAny = true;
    const double perParticleStep = t.rates / double(computed);
    line << "\n    flow rates of frozen metal with no melt within two neighbour hops: "
         << work.skippedFrozen << " of " << work.particleSteps << " particle-steps ("
         << 100.0 * double(work.skippedFrozen) / double(work.particleSteps) << " %), about "
         << perParticleStep * double(work.skippedFrozen) << " s at " << 1e6 * perParticleStep
         << " us per computed particle-step";
  }
  if (flowSubSteps_ > 0 && flowStepsWithoutCooling_ > double(flowSubSteps_)) {
    skippedAny = true;
    const double perFlowStep =
        work.flowSteps > 0
            ? (searchSeconds_ + t.wallClearance + t.rates + t.integration) / double(work.flowSteps)
            : 0.0;
    line << "\n    the cooling mode: " << flowSubSteps_ << " flow steps where controlDict's maxCo "
         << time_.settings().maxCo << " would have taken about "
         << std::llround(flowStepsWithoutCooling_) << ", about "
         << perFlowStep * (flowStepsWithoutCooling_ - double(flowSubSteps_)) << " s at "
         << perFlowStep << " s per flow step";
  }
  if (energy_ && work.flowSteps > std::uint64_t(heatSchedule_.steps())) {
    skippedAny = true;
    line << "\n    heat: " << heatSchedule_.steps() << " heat steps for " << work.flowSteps
         << " flow steps (each of the heat's own stable length)";
  }
  // the searches the pair lists' skin saved: the "Pair lists" line above
  if (!skippedAny) line << " none (no frozen metal, cooling mode or heat)";
  info() << line.str() << '\n';
}

void CastingSolver::logRereadMessage() {
  const std::string message = time_.takeRereadMessage();
  if (!message.empty()) info() << message << "\n\n";
}

}  // namespace sphcast
