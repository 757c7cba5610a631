// The run's monitor: the log of a printed step and of the run's end (OpenFOAM's log style),
// and the health checks after each step.
#include "solver/RunMonitor.h"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>

#include "particles/FieldNames.h"

namespace sphcast {

RunMonitor::RunMonitor(const CastingModels& models, const TimeControl& time,
                       const Communicator& comm, const HeatStepSchedule& heatSchedule,
                       const FlowSetup& flow, const HeatSetup& heat,
                       const SolidificationSetup& solidification)
    : models_(models),
      time_(time),
      comm_(comm),
      heatSchedule_(heatSchedule),
      flow_(flow),
      heat_(heat),
      solidification_(solidification) {}

void RunMonitor::logStep(bool printBlock, bool cooling) {
  if (!printBlock) return;
  info() << "deltaT = " << time_.deltaT() << "  (" << time_.deltaTLimiter() << ")\n"
         << "Time = " << time_.timeName() << "\n\n";
  if (models_.flow) {
    const FluidSummary summary = summarizeFluid(*models_.fluid, comm_);
    const FlowSettings& settings = flow_.settings;
    const double spacing = models_.fluid->attributes().at("spacing");
    // the incompressible flow's Courant number is the flow speed's; it has no Mach number
    const double signalSpeed =
        (settings.incompressible ? 0 : static_cast<double>(settings.soundSpeed)) +
        summary.largestSpeed;
    const double courant = signalSpeed * time_.deltaT() / spacing;
    std::ostringstream line;
    line.precision(6);
    line << "Step " << time_.timeIndex() << "  Courant " << courant << "  max|U| "
         << summary.largestSpeed << " m/s";
    if (!settings.incompressible) {
      line << "  Mach " << summary.largestSpeed / static_cast<double>(settings.soundSpeed);
    }
    line << '\n' << "Density range " << summary.lowestDensity << " .. " << summary.highestDensity
         << " kg/m^3 (" << 100 * summary.lowestDeviation << " .. " << 100 * summary.highestDeviation
         << " % of rho_s)  p " << summary.lowestPressure << " .. " << summary.highestPressure
         << " Pa\n"
         << "Mass " << summary.mass << " kg  kinetic energy " << summary.kineticEnergy
         << " J  moved back from walls "
         << comm_.sum(static_cast<std::int64_t>(models_.flow->lastWallClearance().corrected))
         << '\n';
    const FlowWork& work = models_.flow->work();
    if (work.pressureSolves > 0) {
      const IncompressibleReport& last = models_.flow->lastPressureSolve();
      line << "Pressure solved in " << last.iterations << " iterations: mean compression "
           << 100 * last.meanCompression << " %, largest " << 100 * last.largestCompression
           << " %";
      if (work.unconvergedPressureSolves > 0) {
        line << " (" << work.unconvergedPressureSolves << " of " << work.pressureSolves
             << " solves stopped at maxIterations above densityTolerance)";
      }
      line << '\n';
    }
    if (work.implicitViscousSteps > 0) {  // (every rank takes the same steps alike)
      const ImplicitViscosityReport& last = models_.flow->lastViscousSolve();
      line << "Viscosity solved implicitly in " << work.implicitViscousSteps << " of "
           << work.flowSteps << " flow steps, "
           << double(work.viscousIterations) / double(work.implicitViscousSteps)
           << " iterations a solve (the last " << last.iterations << ", residual " << last.residual
           << ")\n";
    }
    info() << line.str();
  }
  if (!models_.movingMolds.empty())
    models_.movingMolds.log(models_.fluid->attributes().at("spacing"));
  models_.pouringInlets.log(time_.value());
  if (models_.energy) logHeat(cooling);
  if (models_.solidification) logSolidification(cooling);
  info() << clock_.timesLine() << '\n'
         << clock_.progressLine(time_.progress(), counts_.steps, solidEnd()) << '\n'
         << std::endl;  // flushed: a killed run's log ends at its last step
}

void RunMonitor::logHeat(bool cooling) {
  std::ostringstream line;
  line.precision(6);
  if (models_.flow) {
    std::string limiter;
    const double limit = models_.energy->stableDeltaT(limiter);
    line << "Heat: " << heatSchedule_.steps() << " heat steps in " << counts_.steps << " steps ("
         << (cooling                   ? "cooling"
             : heat_.heatEveryFlowStep ? "every flow step"
                                       : "interval auto")
         << ", the last " << heatSchedule_.deltaT() << " s long; " << limiter << " limit " << limit
         << " s)\n";
  }
  for (const HeatCloud& heat : models_.energy->context().clouds) {
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

std::optional<std::pair<double, std::string>> RunMonitor::solidEnd() const {
  if (!models_.solidification || !solidification_.endWhenSolid) return std::nullopt;
  const auto seconds = solidEstimate_.secondsLeft();
  if (!seconds) return std::nullopt;
  return std::make_pair(*seconds, std::string("all solid, endWhenSolid"));
}

void RunMonitor::logSolidification(bool cooling) {
  const SolidificationSummary s = models_.solidification->summary(comm_);
  std::ostringstream line;
  line.precision(4);
  line << "Solidification: solid fraction " << s.solidFraction << " (by mass); of " << s.particles
       << " particles " << s.liquid << " liquid, " << s.frozen << " frozen (" << s.solid
       << " fully solid), " << s.particles - s.frozen << " flowing";
  if (s.viscosityCapped > 0) line << " (" << s.viscosityCapped << " with mu capped)";
  // with endWhenSolid the run ends with the last liquid, not at endTime: the progress line's
  // ETA follows the rise of the solid fraction (CompletionEstimate)
  if (solidification_.endWhenSolid) solidEstimate_.add(clock_.clockTime(), s.solidFraction);
  if (cooling) {
    line << "\n    cooling: heat steps of " << heatSchedule_.deltaT() << " s, each with "
         << solidification_.cooling->flowStepsPerHeatStep << " flow steps (the last "
         << counts_.lastFlowSubStep << " s); " << counts_.flowSubSteps << " flow steps so far";
  }
  info() << line.str() << '\n';
}

void RunMonitor::logTimeSpent() {
  std::ostringstream line;
  line.precision(3);
  line << "Time spent (wall, s):";
  if (models_.neighbourhood) line << " neighbour search " << times_.search << ",";
  if (models_.flow) {
    const FlowTimings& t = models_.flow->timings();
    line << " wall clearance " << t.wallClearance << ", flow rates " << t.rates;
    if (t.viscousSolve > 0) line << ", implicit viscosity " << t.viscousSolve;
    if (models_.surfaceTension)
      line << " (surface tension " << models_.surfaceTension->seconds() << ")";
    line << ", flow integration " << t.integration << ",";
  }
  if (models_.energy) line << " heat " << times_.heat << ",";
  line << " health checks " << times_.checks << ", function objects " << times_.functions
       << ", output " << times_.output;
  info() << line.str() << '\n';
  if (models_.neighbourhood) {
    info() << "Pair lists: searched in the cells " << models_.neighbourhood->rebuildCount()
           << " times, filtered from the last search " << models_.neighbourhood->reuseCount()
           << " times (skin " << models_.neighbourhood->skin() << " m)\n";
  }
  if (models_.flow && models_.flow->work().advectionSteps > 0) {
    const FlowWork& work = models_.flow->work();
    info() << "Time stepping (dualCriteria): " << work.advectionSteps << " advection steps, "
           << work.acousticSubSteps << " acoustic sub-steps ("
           << double(work.acousticSubSteps) / double(work.advectionSteps) << " a step)\n";
  }
  if (models_.flow && models_.flow->work().pressureSolves > 0) {
    const FlowWork& work = models_.flow->work();
    const IncompressibleReport& last = models_.flow->lastPressureSolve();
    info() << "Pressure solves (incompressible): " << work.pressureSolves << ", "
           << double(work.pressureIterations) / double(work.pressureSolves)
           << " Jacobi iterations a solve; the last left a mean compression of "
           << 100 * last.meanCompression << " % (largest " << 100 * last.largestCompression
           << " %) in " << last.iterations << " iterations; " << work.unconvergedPressureSolves
           << " solves stopped at maxIterations above densityTolerance\n";
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
void RunMonitor::logWorkSkipped() {
  if (!models_.flow) return;
  const FlowWork& work = models_.flow->work();
  const FlowTimings& t = models_.flow->timings();
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
  if (counts_.flowSubSteps > 0 && counts_.flowStepsWithoutCooling > double(counts_.flowSubSteps)) {
    skippedAny = true;
    const double perFlowStep =
        work.flowSteps > 0
            ? (times_.search + t.wallClearance + t.rates + t.integration) / double(work.flowSteps)
            : 0.0;
    line << "\n    the cooling mode: " << counts_.flowSubSteps
         << " flow steps where controlDict's maxCo " << time_.settings().maxCo
         << " would have taken about " << std::llround(counts_.flowStepsWithoutCooling)
         << ", about "
         << perFlowStep * (counts_.flowStepsWithoutCooling - double(counts_.flowSubSteps))
         << " s at " << perFlowStep << " s per flow step";
  }
  if (models_.energy && work.flowSteps > std::uint64_t(heatSchedule_.steps())) {
    skippedAny = true;
    line << "\n    heat: " << heatSchedule_.steps() << " heat steps for " << work.flowSteps
         << " flow steps (each of the heat's own stable length)";
  }
  // the searches the pair lists' skin saved: the "Pair lists" line above
  if (!skippedAny) line << " none (no frozen metal, cooling mode or heat)";
  info() << line.str() << '\n';
}

std::string RunMonitor::checkHealth(const std::vector<ParticleCloud>& clouds,
                                    const Domain& domain) {
  std::ostringstream problem;
  problem.precision(4);
  for (const ParticleCloud& cloud : clouds) {
    if (!cloud.hasVectorField(field::U)) continue;  // at rest: nothing to go bad
    const bool cavities = &cloud == models_.fluid &&
                          flow_.settings.cavitationPressure > std::numeric_limits<Real>::lowest();
    const CloudHealth health = measureCloudHealth(cloud, domain, cavities);
    if (!health.finiteAndInside()) {
      problem << health.outside << " particle(s) of cloud '" << cloud.name()
              << "' left the domain and " << health.nonFinite << " went non-finite; the first, "
              << describeParticle(cloud, health.firstBad, health.firstBadPosition);
      return problem.str();
    }
    // only the flow evolves the density (a ballistic cloud carries its start value)
    if (!health.hasDensity || &cloud != models_.fluid) continue;
    const double deviation = health.largestDensityDeviation;
    if (deviation <= health_.warnDensityDeviation) continue;
    const std::string where =
        describeParticle(cloud, health.mostDeviating, health.mostDeviatingPosition);
    if (deviation > health_.maxDensityDeviation) {
      problem << "the density of " << where << " deviates by " << 100 * deviation
              << " % from rho_s (healthChecks maxDensityDeviation "
              << 100 * health_.maxDensityDeviation << " %)";
      return problem.str();
    }
    if (warnings_.shouldPrint("density deviation above " +
                                  std::to_string(std::lround(100 * health_.warnDensityDeviation)) +
                                  " %",
                              deviation)) {
      std::ostringstream message;
      message.precision(4);
      message << "time " << time_.timeName() << " (step " << time_.timeIndex()
              << "): the density of " << where << " deviates by " << 100 * deviation
              << " % from rho_s; a larger soundSpeed (c >= 10 |U|max) keeps it smaller";
      warning(message.str());
    }
  }
  if (models_.energy) {
    const std::string bad = checkTemperatures();
    if (!bad.empty()) return bad;
  }
  if (models_.flow) {
    const WallClearanceReport& clearance = models_.flow->lastWallClearance();
    const double spacing = models_.fluid->attributes().at("spacing");
    const double depth = static_cast<double>(clearance.deepest) / spacing;
    if (clearance.beyondSurface > 0) {
      const std::string where =
          describeParticle(*models_.fluid, clearance.deepestParticle, clearance.deepestPosition);
      if (depth > health_.maxWallPenetration) {
        problem << where << " was " << depth
                << " dx behind a wall surface after the step (healthChecks maxWallPenetration "
                << health_.maxWallPenetration << " dx): it went through the wall";
        return problem.str();
      }
      if (warnings_.shouldPrint("fluid pushed back out of a wall", depth)) {
        std::ostringstream message;
        message.precision(4);
        message << "time " << time_.timeName() << " (step " << time_.timeIndex()
                << "): " << clearance.beyondSurface
                << " fluid particle(s) reached behind a wall surface"
                << " and were moved back in front of it; the deepest, " << where << ", " << depth
                << " dx behind";
        warning(message.str());
      }
    }
  }
  return "";
}

// A temperature that is not finite or not above 0 K: the energy equation went unstable (a step
// past its limits) or a table was extrapolated far beyond its range.
std::string RunMonitor::checkTemperatures() const {
  for (const HeatCloud& heat : models_.energy->context().clouds) {
    const auto& T = heat.cloud->scalarField(field::T);
    for (std::size_t i = 0; i < heat.cloud->ownedSize(); ++i) {
      if (T[i] > 0 && std::isfinite(T[i])) continue;
      std::ostringstream problem;
      problem << "the temperature of "
              << describeParticle(*heat.cloud, i, heat.cloud->positions()[i]) << " is " << T[i]
              << " K";
      return problem.str();
    }
  }
  return "";
}

}  // namespace sphcast
