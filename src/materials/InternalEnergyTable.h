#pragma once

#include <vector>

#include "core/Real.h"
#include "core/dictionary/Dictionary.h"
#include "materials/PropertyEntry.h"

namespace sphcast {

// Specific internal energy u(T) (J/kg) of a material, the state variable of the heat equation
// (paper eq. (17)): the latent heat is a steep stretch of u(T) across the mushy zone (Table 1,
// 4.86e5 J/kg between 830.44 K and 888.64 K), so the heat transfer advances u and reads T back.
//
// u is piecewise linear between rows and extrapolated beyond the ends with the end segments'
// slopes, so the specific heat du/dT stays the end rows' value outside the table. It is built
// from either
//   internalEnergy  table ((T u) ...);   at least 2 rows, u strictly increasing with T; or
//   specificHeat    cp, or table ((T cp) ...);   cp > 0; then u(T) is the integral of cp from
//                   0 K, cp clamped to its end values outside the table. The integral of the
//                   piecewise-linear cp is quadratic between rows; each interval is subdivided
//                   until the piecewise-linear u lies within 1e-6 relative of it.
// energy() and temperature() are exact inverses of each other (both piecewise linear over the
// same nodes) and cost a binary search each, since they run once per particle per step.
class InternalEnergyTable {
 public:
  // Relative accuracy of u(T) built from cp(T) against the exact integral.
  static constexpr double integrationTolerance = 1e-6;

  // From an `internalEnergy` entry (rows or a column); errors name file, line, key and row.
  static InternalEnergyTable fromInternalEnergy(const PropertyEntry& entry);
  // From a `specificHeat` entry (a constant, rows or a column).
  static InternalEnergyTable fromSpecificHeat(const PropertyEntry& entry);

  // u(T), J/kg.
  Real energy(Real temperature) const;
  // T(u), K: the inverse of energy().
  Real temperature(Real energy) const;
  // du/dT of the segment holding T (at a node, the segment above it), J/kg/K.
  Real specificHeat(Real temperature) const;
  // The smallest du/dT over the whole table and its extrapolations: the bound of a step limit.
  Real smallestSpecificHeat() const { return smallestSpecificHeat_; }

  // The nodes of the piecewise-linear u(T), for tests and logs.
  const std::vector<double>& nodeTemperatures() const { return temperatures_; }
  const std::vector<double>& nodeEnergies() const { return energies_; }
  const SourceLocation& location() const { return location_; }
  const std::string& description() const { return description_; }

 private:
  InternalEnergyTable(std::vector<double> temperatures, std::vector<double> energies,
                      const PropertyEntry& entry);

  // Index of the segment [i, i + 1] that holds x in `nodes` (the end segments beyond the ends).
  static std::size_t segmentOf(const std::vector<double>& nodes, double x);

  std::vector<double> temperatures_;  // strictly increasing, at least two
  std::vector<double> energies_;      // strictly increasing
  double smallestSpecificHeat_ = 0.0;
  SourceLocation location_;
  std::string description_;
};

}  // namespace sphcast
