#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/dictionary/Dictionary.h"

namespace sphcast {

// A material's `temperatures (T1 T2 ...)` (K): the rows of the properties written as columns,
// so that a table can be copied as printed (Table 1 of the paper):
//
//   temperatures  (803.0  830.44  848 ...);
//   density       (2571.9 2565.5  2517 ...);
struct TemperatureColumn {
  std::vector<double> temperatures;
  std::vector<SourceLocation> rowLocations;
  SourceLocation location;  // of the key
  std::string description;  // "'temperatures' in physicalProperties/AC4CH"
};

// Reads `key` (the temperatures must increase; the error names the row).
TemperatureColumn readTemperatureColumn(const Dictionary& dict, std::string_view key);

// One property entry as written, before any rule on its values is applied: a constant,
// `table ((T value) ...)` rows, or a column of values beside `temperatures`. Rows (of either
// form) have increasing T: the reader checks that, and a column's length against the
// temperatures', each a DictionaryError naming file, line, key and row.
struct PropertyEntry {
  std::vector<double> temperatures;          // empty for a constant
  std::vector<double> values;                // one value for a constant
  std::vector<SourceLocation> rowLocations;  // where each value is written; empty for a constant
  SourceLocation location;                   // of the key
  std::string key;
  std::string dictionaryName;  // "physicalProperties/metal"
  std::string description;     // "'density' in physicalProperties/metal"

  bool isConstant() const { return temperatures.empty(); }
  // Where row i (0-based) is written, the key's place for a constant.
  const SourceLocation& rowLocation(std::size_t i) const {
    return rowLocations.empty() ? location : rowLocations[i];
  }
};

// Reads `key` of `dict`; a dimension set written in the entry must equal valueDimensions.
// `columns` are the material's temperatures, when it has them (a column needs them).
PropertyEntry readPropertyEntry(const Dictionary& dict, std::string_view key,
                                const Dimensions& valueDimensions,
                                const TemperatureColumn* columns = nullptr);

}  // namespace sphcast
