#pragma once

#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/Real.h"
#include "parallel/Communicator.h"
#include "particles/Domain.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

class Dictionary;

// The thresholds of the run's health checks: system/controlDict's optional `healthChecks`
// sub-dictionary, every entry optional.
struct HealthSettings {
  // |rho / rho_s - 1| above this is written to the log as a warning (the weakly compressible
  // error is about the Mach number squared, or v/c at an impact: 3 % says c is too small).
  double warnDensityDeviation = 0.03;
  // ... and above this the run stops: no flow with 20 % compression is still the liquid's.
  double maxDensityDeviation = 0.2;
  // A fluid particle found this many spacings behind a wall surface after a step has tunnelled
  // through the wall (the wall clearance pushes back anything less): the run stops.
  double maxWallPenetration = 0.5;
  // The models' stable step below this fraction of its running mean (over ~100 steps) means the
  // run is blowing up: it stops.
  double minDeltaTFraction = 1e-3;
  // The metal spilled out of the domain (solver/MetalSpill.h), as a fraction of the metal's mass
  // (spilled included), above which the run stops: a mold that leaks, not a splash.
  double maxSpilledFraction = 0.05;
  // The case's own domain, `domain { lower (x y z); upper (x y z); }` (a floor: lower's z);
  // without it the molds' box grown by half its size, fixed at the run's first start.
  std::optional<Domain> domain;

  static HealthSettings read(const Dictionary& controlDict);
};

// The box the run's particles must stay in: the case's (settings.domain), else the one the run
// started with (kept with the fluid's cloud, storeDomain: a restart after a punch moved keeps
// it), else the molds' box (the fluid's without molds) grown by half its size, over every rank
// (collective). Stored with the fluid's cloud.
Domain runDomain(const HealthSettings& settings, ParticleCloud& fluid,
                 const std::vector<const ParticleCloud*>& walls, const Communicator& comm);

// One moving cloud's state after a step, measured in one pass.
struct CloudHealth {
  std::size_t nonFinite = 0;  // position, velocity or density not finite
  std::size_t outside = 0;    // finite but outside the domain
  std::size_t firstBad = 0;   // index of the first of either
  Vector firstBadPosition = Vector::Zero();
  bool hasDensity = false;  // the cloud has rho and restDensity
  // max |rho / rho_s - 1| (fraction); with expansionOpensCavities max(rho / rho_s - 1, 0)
  double largestDensityDeviation = 0;
  std::size_t mostDeviating = 0;
  Vector mostDeviatingPosition = Vector::Zero();

  bool finiteAndInside() const { return nonFinite == 0 && outside == 0; }
};

// expansionOpensCavities: the melt's pressure has a floor (FlowSettings::cavitationPressure), so
// a density below rho_s is a shrinkage cavity spread over the particles, not an error: only
// compression counts as deviation.
CloudHealth measureCloudHealth(const ParticleCloud& cloud, const Domain& domain,
                               bool expansionOpensCavities = false);

// The particle's place in a message: "particle id 345 (index 12) of cloud 'metal' at (0.2 0.05
// 0.01)".
std::string describeParticle(const ParticleCloud& cloud, std::size_t index, const Vector& x);

// Keeps the count of each kind of warning and decides which to print: the first of a kind, then
// only when it is half as bad again as the last one printed, so a long run's log stays readable.
class HealthWarnings {
 public:
  // Whether a warning of `kind` with this `severity` should be printed now; counts it either way.
  bool shouldPrint(const std::string& kind, double severity);
  // "warnings: 3 density deviation, 12 wall contact" or "no warnings".
  std::string summary() const;

 private:
  struct Kind {
    long count = 0;
    double printedSeverity = 0;
  };
  std::map<std::string, Kind> kinds_;
};

// Watches the models' stable step for a collapse (a run blowing up): a step that is not positive
// and finite, or below minDeltaTFraction of its running mean over about the last 100 steps.
class StepCollapseWatch {
 public:
  // Why the run must stop before the next step, or "" (the mean then takes this step in).
  std::string check(double stableDeltaT, const std::string& limiter, double minDeltaTFraction);
  // Forget the mean: the steps change length by design (the cooling mode starts or stops).
  void restart() { meanStableDeltaT_ = 0; }

 private:
  double meanStableDeltaT_ = 0;
};

// What the log prints of a fluid cloud at a printed step: sums in particle order (the same on
// any number of threads).
struct FluidSummary {
  double largestSpeed = 0;                           // m/s
  double lowestDensity = 0, highestDensity = 0;      // kg/m^3
  double lowestDeviation = 0, highestDeviation = 0;  // rho / rho_s - 1
  double lowestPressure = 0, highestPressure = 0;    // Pa
  double mass = 0;                                   // kg
  double kineticEnergy = 0;                          // J
};

// Of the owned particles of every rank of comm (a decomposed run's halo is not counted).
FluidSummary summarizeFluid(const ParticleCloud& fluid,
                            const Communicator& comm = Communicator::self());

}  // namespace sphcast
