// The run's health checks after each step, and the stop with the last good state.
#include "particles/FieldNames.h"
#include "solver/CastingSolver.h"

#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"

namespace sphcast {

std::string CastingSolver::checkHealth() {
  std::ostringstream problem;
  problem.precision(4);
  for (const ParticleCloud& cloud : clouds_) {
    if (!cloud.hasVectorField(field::U)) continue;  // at rest: nothing to go bad
    const bool cavities = &cloud == fluid_ && flowSetup_.settings.cavitationPressure >
                                                  std::numeric_limits<Real>::lowest();
    const CloudHealth health = measureCloudHealth(cloud, domain_, cavities);
    if (!health.finiteAndInside()) {
      problem << health.outside << " particle(s) of cloud '" << cloud.name()
              << "' left the domain and " << health.nonFinite << " went non-finite; the first, "
              << describeParticle(cloud, health.firstBad, health.firstBadPosition);
      return problem.str();
    }
    // only the flow evolves the density (a ballistic cloud carries its start value)
    if (!health.hasDensity || &cloud != fluid_) continue;
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
  if (energy_) {
    const std::string bad = checkTemperatures();
    if (!bad.empty()) return bad;
  }
  if (flow_) {
    const WallClearanceReport& clearance = flow_->lastWallClearance();
    const double spacing = fluid_->attributes().at("spacing");
    const double depth = static_cast<double>(clearance.deepest) / spacing;
    if (clearance.beyondSurface > 0) {
      const std::string where =
          describeParticle(*fluid_, clearance.deepestParticle, clearance.deepestPosition);
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
std::string CastingSolver::checkTemperatures() const {
  for (const HeatCloud& heat : energy_->context().clouds) {
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

// Every rank of a parallel run stops here alike (the failure is shared before), so the errors
// are CollectiveErrors: rank 0 prints them.
void CastingSolver::stopWithLastGoodState(const TimeState& good, bool restoreSaved,
                                          const std::string& what) {
  const std::string badTime = time_.timeName();
  const long badIndex = time_.timeIndex();
  logTimeSpent();
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
    movingMolds_.restoreState(good.value);
    pouringInlets_.restoreState();
  }
  std::vector<const ParticleCloud*> written;
  for (const ParticleCloud& cloud : clouds_) written.push_back(&cloud);
  writer_.write(good, written, uniformStateFiles(good.name));
  throw CollectiveError(
      failure + "The last good state, time " + good.name +
      ", is written (it passed every check); restart from it with a smaller maxCo or "
      "deltaT, a larger soundSpeed, or look for a gap in the walls there.");
}

}  // namespace sphcast
