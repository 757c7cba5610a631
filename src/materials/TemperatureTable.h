#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/dictionary/Dictionary.h"
#include "materials/PropertyEntry.h"

namespace sphcast {

// How a table is interpolated between its rows. Log-linear interpolates log(value) linearly in
// T: the viscosity of Table 1 spans eight decades across the mushy zone, and a linear
// interpolation would hold it near the solid's value almost down to the liquidus.
enum class Interpolation { linear, logLinear };

// What a property's values may be: a density, a viscosity, a conductivity must be positive;
// a surface tension is 0 in the solid rows of Table 1.
enum class ValueRule { positive, nonNegative };

// A material property as a function of temperature (doc/physics.md §4.1: rho_s(T), mu(T), ...),
// read from one entry of constant/physicalProperties: a constant, a table of (T value) rows, or
// a column beside the material's `temperatures` (PropertyEntry.h):
//
//   density  [1 -3 0 0 0 0 0] 2400;
//   density  [1 -3 0 0 0 0 0] table ((300 2700) (853 2550) (903 2380) (1000 2350));
//
// Between rows the value is interpolated (linearly, or log-linearly); outside the table it is
// the first or last row's value (clamped), so a melt that cools below the table keeps the
// solid's value. A row's temperature (K) must exceed the previous row's; the error names the
// row's file, line and the key. Every value must obey the rule (positive by default).
class TemperatureTable {
 public:
  // Reads `key` of `dict`; a dimension set written in the entry must equal valueDimensions.
  // `columns`: the material's `temperatures`, for a property written as a column.
  static TemperatureTable read(const Dictionary& dict, std::string_view key,
                               const Dimensions& valueDimensions,
                               Interpolation interpolation = Interpolation::linear,
                               ValueRule rule = ValueRule::positive,
                               const TemperatureColumn* columns = nullptr);
  // From an entry already read (its rows checked for order); applies `rule` to the values.
  static TemperatureTable fromEntry(const PropertyEntry& entry, Interpolation interpolation,
                                    ValueRule rule);

  // The value at temperature T (K), clamped at the ends of the table.
  double operator()(double temperature) const;
  // The integral of the value over temperature from the table's lowest temperature to T (value
  // times K; negative below it), exact for the interpolation and the clamped ends: the
  // conductivity's Kirchhoff transform, phi(T) = int kappa dT (thermal/HeatConduction.h).
  double integral(double temperature) const;

  bool isConstant() const { return temperatures_.size() == 1; }
  double lowestTemperature() const { return temperatures_.front(); }
  double highestTemperature() const { return temperatures_.back(); }
  Interpolation interpolation() const { return interpolation_; }
  // Where the entry was written, and "'density' in physicalProperties/metal", for messages.
  const SourceLocation& location() const { return location_; }
  const std::string& description() const { return description_; }

  // An initial temperature outside a table's range is most likely a unit slip (deg C for K):
  // a DictionaryError at `where` (the place T was given) naming the table and its range.
  // A constant covers every temperature.
  void checkCovers(double temperature, const SourceLocation& where) const;

 private:
  std::vector<double> temperatures_;  // one entry (any value) for a constant
  std::vector<double> values_;
  std::vector<double> logValues_;  // log(value), for Interpolation::logLinear only
  Interpolation interpolation_ = Interpolation::linear;
  SourceLocation location_;
  std::string description_;
};

}  // namespace sphcast
