#include "solver/RunHealth.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "particles/FieldNames.h"

namespace sphcast {

namespace {

bool isBad(const Vector& x, const Vector& u, Real rho, const Domain& domain) {
  return !x.allFinite() || !u.allFinite() || !std::isfinite(rho) || !inside(domain, x);
}

void requirePositive(const Dictionary& dict, const std::string& key, double value) {
  if (!(value > 0) || !std::isfinite(value)) {
    throw DictionaryError(dict.location(key),
                          "'" + key + "' must be a positive number in " + dict.name());
  }
}

}  // namespace

HealthSettings HealthSettings::read(const Dictionary& controlDict) {
  HealthSettings s;
  if (!controlDict.found("healthChecks")) return s;
  const Dictionary& dict = controlDict.subDict("healthChecks");
  dict.checkKeys({"warnDensityDeviation", "maxDensityDeviation", "maxWallPenetration",
                  "minDeltaTFraction", "maxSpilledFraction", "domain"});
  s.warnDensityDeviation =
      dict.getOrDefault<double>("warnDensityDeviation", s.warnDensityDeviation);
  s.maxDensityDeviation = dict.getOrDefault<double>("maxDensityDeviation", s.maxDensityDeviation);
  s.maxWallPenetration = dict.getOrDefault<double>("maxWallPenetration", s.maxWallPenetration);
  s.minDeltaTFraction = dict.getOrDefault<double>("minDeltaTFraction", s.minDeltaTFraction);
  s.maxSpilledFraction = dict.getOrDefault<double>("maxSpilledFraction", s.maxSpilledFraction);
  for (const char* key : {"warnDensityDeviation", "maxDensityDeviation", "maxWallPenetration",
                          "minDeltaTFraction", "maxSpilledFraction"}) {
    if (dict.found(key)) requirePositive(dict, key, dict.get<double>(key));
  }
  if (dict.found("domain")) {
    const Dictionary& box = dict.subDict("domain");
    box.checkKeys({"lower", "upper"});
    Domain domain;
    domain.lower = box.get<Vector>("lower");
    domain.upper = box.get<Vector>("upper");
    if (!(domain.lower.array() < domain.upper.array()).all()) {
      throw DictionaryError(box.location("upper"),
                            "'upper' must lie above 'lower' in every direction in " + box.name() +
                                " (in a 2D case along z too: e.g. -1 and 1)");
    }
    s.domain = domain;
  }
  if (s.minDeltaTFraction >= 1) {
    throw DictionaryError(dict.location("minDeltaTFraction"),
                          "'minDeltaTFraction' must lie below 1 in " + dict.name());
  }
  if (s.warnDensityDeviation >= s.maxDensityDeviation) {
    throw DictionaryError(dict.location("warnDensityDeviation"),
                          "'warnDensityDeviation' must be below 'maxDensityDeviation' (" +
                              std::to_string(s.maxDensityDeviation) + ") in " + dict.name());
  }
  return s;
}

Domain runDomain(const HealthSettings& settings, ParticleCloud& fluid,
                 const std::vector<const ParticleCloud*>& walls, const Communicator& comm) {
  Domain domain;
  if (settings.domain) {
    domain = *settings.domain;
  } else if (const std::optional<Domain> kept = storedDomain(fluid)) {
    domain = *kept;
  } else {
    Domain box = walls.empty() ? boundingBox({&fluid}) : boundingBox(walls);
    std::vector<double> lower(box.lower.data(), box.lower.data() + 3);
    std::vector<double> upper(box.upper.data(), box.upper.data() + 3);
    comm.min(lower);  // the box of every rank's particles
    comm.max(upper);
    for (int a = 0; a < 3; ++a) {
      box.lower[a] = static_cast<Real>(lower[static_cast<std::size_t>(a)]);
      box.upper[a] = static_cast<Real>(upper[static_cast<std::size_t>(a)]);
    }
    domain = withMargin(box);
  }
  storeDomain(fluid, domain);
  return domain;
}

CloudHealth measureCloudHealth(const ParticleCloud& cloud, const Domain& domain,
                               bool expansionOpensCavities) {
  const auto& x = cloud.positions();
  const auto& u = cloud.vectorField(field::U);
  CloudHealth health;
  health.firstBad = cloud.ownedSize();
  health.hasDensity = cloud.hasScalarField(field::rho) && cloud.hasScalarField(field::restDensity);
  static const std::vector<Real> none;
  const auto& rho = health.hasDensity ? cloud.scalarField(field::rho) : none;
  const auto& restDensity = health.hasDensity ? cloud.scalarField(field::restDensity) : none;
  const double lowestCounted = expansionOpensCavities ? 0.0 : -1e300;
  auto deviationOf = [&](std::size_t i) {
    const double relative = static_cast<double>(rho[i] / restDensity[i]) - 1.0;
    return std::abs(std::max(relative, lowestCounted));
  };
  const Real noDensity = 1;  // a cloud without density: only position and velocity are checked
  // Counted in one pass (max and sums: the same on any number of threads); the particles named
  // in messages are found again only when needed.
  std::size_t nonFinite = 0;
  std::size_t outside = 0;
  double deviation = 0;
#pragma omp parallel for reduction(+ : nonFinite, outside) reduction(max : deviation)
  for (std::size_t i = 0; i < cloud.ownedSize(); ++i) {
    const Real density = health.hasDensity ? rho[i] : noDensity;
    if (!x[i].allFinite() || !u[i].allFinite() || !std::isfinite(density)) {
      ++nonFinite;
    } else if (!inside(domain, x[i])) {
      ++outside;
    } else if (health.hasDensity) {
      deviation = std::max(deviation, deviationOf(i));
    }
  }
  health.nonFinite = nonFinite;
  health.outside = outside;
  health.largestDensityDeviation = deviation;
  if (!health.finiteAndInside()) {
    for (std::size_t i = 0; i < cloud.ownedSize(); ++i) {
      if (isBad(x[i], u[i], health.hasDensity ? rho[i] : noDensity, domain)) {
        health.firstBad = i;
        health.firstBadPosition = x[i];
        break;
      }
    }
  }
  if (health.hasDensity && deviation > 0) {
    for (std::size_t i = 0; i < cloud.ownedSize(); ++i) {
      if (deviationOf(i) == deviation) {
        health.mostDeviating = i;
        health.mostDeviatingPosition = x[i];
        break;
      }
    }
  }
  return health;
}

std::string describeParticle(const ParticleCloud& cloud, std::size_t index, const Vector& x) {
  const Eigen::IOFormat plain(Eigen::StreamPrecision, Eigen::DontAlignCols, " ", " ");
  std::ostringstream text;
  text.precision(6);
  // the id first: the index is the particle's place after the step's reorder, which the
  // written state (from before the step) need not share
  if (cloud.hasIdField(field::id) && index < cloud.size()) {
    text << "particle id " << cloud.idField(field::id)[index] << " (index " << index << ")";
  } else {
    text << "particle " << index;
  }
  text << " of cloud '" << cloud.name() << "' at (" << x.transpose().format(plain) << ")";
  return text.str();
}

bool HealthWarnings::shouldPrint(const std::string& kind, double severity) {
  Kind& k = kinds_[kind];
  ++k.count;
  if (k.count == 1 || severity >= 1.5 * k.printedSeverity) {
    k.printedSeverity = severity;
    return true;
  }
  return false;
}

std::string HealthWarnings::summary() const {
  if (kinds_.empty()) return "no warnings";
  std::ostringstream text;
  text << "warnings:";
  const char* separator = " ";
  for (const auto& [kind, k] : kinds_) {
    text << separator << k.count << " step(s) with " << kind;
    separator = ", ";
  }
  return text.str();
}

FluidSummary summarizeFluid(const ParticleCloud& fluid, const Communicator& comm) {
  const auto& u = fluid.vectorField(field::U);
  const auto& rho = fluid.scalarField(field::rho);
  const auto& restDensity = fluid.scalarField(field::restDensity);
  const auto& p = fluid.scalarField(field::p);
  const auto& mass = fluid.scalarField(field::mass);
  const double inf = std::numeric_limits<double>::infinity();
  // the lowest values as the largest of their negatives: one reduction for all
  std::vector<double> largest{0, -inf, -inf, -inf, -inf, -inf, -inf};
  std::vector<double> sums{0, 0, 0};
  for (std::size_t i = 0; i < fluid.ownedSize(); ++i) {
    const double speedSquared = static_cast<double>(u[i].squaredNorm());
    const double deviation = static_cast<double>(rho[i] / restDensity[i]) - 1.0;
    const double values[] = {std::sqrt(speedSquared),
                             static_cast<double>(rho[i]),
                             -static_cast<double>(rho[i]),
                             deviation,
                             -deviation,
                             static_cast<double>(p[i]),
                             -static_cast<double>(p[i])};
    for (std::size_t k = 0; k < largest.size(); ++k) largest[k] = std::max(largest[k], values[k]);
    sums[0] += static_cast<double>(mass[i]);
    sums[1] += 0.5 * static_cast<double>(mass[i]) * speedSquared;
    sums[2] += 1;
  }
  comm.max(largest);
  comm.sum(sums);
  FluidSummary s;
  if (sums[2] == 0) return s;
  s.largestSpeed = largest[0];
  s.highestDensity = largest[1];
  s.lowestDensity = -largest[2];
  s.highestDeviation = largest[3];
  s.lowestDeviation = -largest[4];
  s.highestPressure = largest[5];
  s.lowestPressure = -largest[6];
  s.mass = sums[0];
  s.kineticEnergy = sums[1];
  return s;
}

std::string StepCollapseWatch::check(double stableDeltaT, const std::string& limiter,
                                     double minDeltaTFraction) {
  if (!(stableDeltaT > 0) || !std::isfinite(stableDeltaT)) {
    std::ostringstream problem;
    problem << "the stable time step (" << limiter << ") is " << stableDeltaT;
    return problem.str();
  }
  if (meanStableDeltaT_ > 0 && stableDeltaT < minDeltaTFraction * meanStableDeltaT_) {
    std::ostringstream problem;
    problem.precision(4);
    problem << "the stable time step collapsed to " << stableDeltaT << " s (" << limiter
            << "), below " << minDeltaTFraction << " of its running mean " << meanStableDeltaT_
            << " s (healthChecks minDeltaTFraction)";
    return problem.str();
  }
  meanStableDeltaT_ =
      meanStableDeltaT_ > 0 ? 0.99 * meanStableDeltaT_ + 0.01 * stableDeltaT : stableDeltaT;
  return "";
}

}  // namespace sphcast
