#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/dictionary/Dictionary.h"

namespace sphcast {

// A material property as a function of temperature (doc/physics.md §4: rho_s(T), mu(T), ...), read
// from one entry of constant/physicalProperties, either a constant or a table of (T value) rows:
//
//   density  [1 -3 0 0 0 0 0] 2400;
//   density  [1 -3 0 0 0 0 0] table ((300 2700) (853 2550) (903 2380) (1000 2350));
//
// Between rows the value is interpolated linearly in T; outside the table it is the first or
// last row's value (clamped), so a melt that cools below the table keeps the solid's value.
// A row's temperature (K) must exceed the previous row's; the error names the row's file, line
// and the key. Every value must be positive (a density, a viscosity, a conductivity).
class TemperatureTable {
 public:
  // Reads `key` of `dict`; a dimension set written in the entry must equal valueDimensions.
  static TemperatureTable read(const Dictionary& dict, std::string_view key,
                               const Dimensions& valueDimensions);

  // The value at temperature T (K), clamped at the ends of the table.
  double operator()(double temperature) const;

  bool isConstant() const { return temperatures_.size() == 1; }
  double lowestTemperature() const { return temperatures_.front(); }
  double highestTemperature() const { return temperatures_.back(); }
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
  SourceLocation location_;
  std::string description_;
};

}  // namespace sphcast
