#include "materials/InternalEnergyTable.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>

namespace sphcast {

namespace {

// Sub-intervals of [t0, t1] on which a cp rising linearly from cp0 to cp1 keeps the linear
// interpolation of u within `tolerance` relative of its exact (quadratic) integral, u0 = u(t0).
// On a sub-interval [a, a + d] the interpolation errs by (s/2)(T - a)(a + d - T) with s the
// slope of cp, at most s d^2 / 8, while u(T) >= u0; near T = 0 K, where u0 is 0, the error
// relative to u(T) >= cpMin (T - a) is at most s d / (2 cpMin). Either bound suffices.
long subdivisions(double t0, double t1, double cp0, double cp1, double u0, double tolerance) {
  const double slope = std::abs(cp1 - cp0) / (t1 - t0);
  if (slope == 0.0) return 1;
  const double cpMin = std::min(cp0, cp1);
  const double byEnergy = std::sqrt(8.0 * tolerance * u0 / slope);
  const double bySpecificHeat = 2.0 * tolerance * cpMin / slope;
  const double width = std::max(byEnergy, bySpecificHeat);
  return std::max(1L, static_cast<long>(std::ceil((t1 - t0) / width)));
}

}  // namespace

InternalEnergyTable::InternalEnergyTable(std::vector<double> temperatures,
                                         std::vector<double> energies, const PropertyEntry& entry)
    : temperatures_(std::move(temperatures)),
      energies_(std::move(energies)),
      location_(entry.location),
      description_(entry.description) {
  smallestSpecificHeat_ = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < temperatures_.size(); ++i) {
    const double slope =
        (energies_[i + 1] - energies_[i]) / (temperatures_[i + 1] - temperatures_[i]);
    smallestSpecificHeat_ = std::min(smallestSpecificHeat_, slope);
  }
}

InternalEnergyTable InternalEnergyTable::fromInternalEnergy(const PropertyEntry& entry) {
  if (entry.values.size() < 2) {
    throw DictionaryError(entry.location,
                          entry.description +
                              " needs at least 2 rows (T u): u(T) is extrapolated beyond the "
                              "table with the slopes of its end segments; for a constant "
                              "specific heat write specificHeat instead");
  }
  for (std::size_t i = 1; i < entry.values.size(); ++i) {
    if (entry.values[i] > entry.values[i - 1]) continue;
    std::ostringstream message;
    message << "'" << entry.key << "' must increase with T in " << entry.dictionaryName
            << " (its slope is the specific heat): row " << i + 1 << " has u = " << entry.values[i]
            << " J/kg at T = " << entry.temperatures[i] << " K after " << entry.values[i - 1]
            << " J/kg at " << entry.temperatures[i - 1] << " K";
    throw DictionaryError(entry.rowLocation(i), message.str());
  }
  return InternalEnergyTable(entry.temperatures, entry.values, entry);
}

InternalEnergyTable InternalEnergyTable::fromSpecificHeat(const PropertyEntry& entry) {
  for (std::size_t i = 0; i < entry.values.size(); ++i) {
    if (entry.values[i] > 0.0) continue;
    std::ostringstream message;
    message << "'" << entry.key << "' must be positive in " << entry.dictionaryName;
    if (!entry.isConstant()) message << "; row " << i + 1;
    message << " has " << entry.values[i] << " (valid range: > 0)";
    throw DictionaryError(entry.rowLocation(i), message.str());
  }
  if (entry.isConstant()) {
    // u = cp T: one segment, extrapolated both ways.
    return InternalEnergyTable({0.0, 1.0}, {0.0, entry.values.front()}, entry);
  }
  if (entry.temperatures.front() < 0.0) {
    std::ostringstream message;
    message << "'" << entry.key << "' in " << entry.dictionaryName
            << " starts at T = " << entry.temperatures.front()
            << " K; u(T) is integrated from 0 K and temperatures are in kelvin";
    throw DictionaryError(entry.rowLocation(0), message.str());
  }
  const std::vector<double>& t = entry.temperatures;
  const std::vector<double>& cp = entry.values;
  std::vector<double> temperatures{0.0}, energies{0.0};
  // Below the first row cp is its value: u is exactly linear there.
  if (t.front() > 0.0) {
    temperatures.push_back(t.front());
    energies.push_back(cp.front() * t.front());
  }
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const long pieces =
        subdivisions(t[i], t[i + 1], cp[i], cp[i + 1], energies.back(), 0.5 * integrationTolerance);
    const double width = (t[i + 1] - t[i]) / static_cast<double>(pieces);
    double cpStart = cp[i];
    for (long k = 1; k <= pieces; ++k) {
      const double fraction = static_cast<double>(k) / static_cast<double>(pieces);
      const double tEnd = k == pieces ? t[i + 1] : t[i] + static_cast<double>(k) * width;
      const double cpEnd = cp[i] + fraction * (cp[i + 1] - cp[i]);
      // the trapezoid rule is exact for a cp linear over the piece
      energies.push_back(energies.back() + 0.5 * (cpStart + cpEnd) * (tEnd - temperatures.back()));
      temperatures.push_back(tEnd);
      cpStart = cpEnd;
    }
  }
  // One more segment at the last row's cp, so that the extrapolation above the table has the
  // slope cp(T_last), not the mean cp of the last piece.
  temperatures.push_back(t.back() + 1.0);
  energies.push_back(energies.back() + cp.back());
  return InternalEnergyTable(std::move(temperatures), std::move(energies), entry);
}

std::size_t InternalEnergyTable::segmentOf(const std::vector<double>& nodes, double x) {
  const auto above = std::upper_bound(nodes.begin() + 1, nodes.end() - 1, x);
  return static_cast<std::size_t>(std::distance(nodes.begin(), above)) - 1;
}

Real InternalEnergyTable::energy(Real temperature) const {
  const double tt = static_cast<double>(temperature);
  const std::size_t i = segmentOf(temperatures_, tt);
  const double fraction = (tt - temperatures_[i]) / (temperatures_[i + 1] - temperatures_[i]);
  return static_cast<Real>(energies_[i] + fraction * (energies_[i + 1] - energies_[i]));
}

Real InternalEnergyTable::temperature(Real energy) const {
  const double u = static_cast<double>(energy);
  const std::size_t i = segmentOf(energies_, u);
  const double fraction = (u - energies_[i]) / (energies_[i + 1] - energies_[i]);
  return static_cast<Real>(temperatures_[i] + fraction * (temperatures_[i + 1] - temperatures_[i]));
}

Real InternalEnergyTable::specificHeat(Real temperature) const {
  const std::size_t i = segmentOf(temperatures_, static_cast<double>(temperature));
  return static_cast<Real>((energies_[i + 1] - energies_[i]) /
                           (temperatures_[i + 1] - temperatures_[i]));
}

}  // namespace sphcast
