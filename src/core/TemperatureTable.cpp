#include "core/TemperatureTable.h"

#include <algorithm>
#include <iterator>
#include <sstream>

namespace sphcast {

namespace {

// The value of a property entry as written: a number, or the word `table` and a list of rows.
struct PropertyValue {
  std::vector<double> temperatures;
  std::vector<double> values;
  std::vector<SourceLocation> rowLocations;  // empty for a number
};

}  // namespace

namespace dictionary {

template <>
struct ValueTraits<PropertyValue> {
  static std::string description() { return "a number or table ((T value) ...)"; }
  static PropertyValue read(ItemCursor& cursor) {
    PropertyValue property;
    const ValueItem& first = cursor.take(description());
    if (first.kind == ValueItem::Kind::Number) {
      property.temperatures.push_back(0.0);
      property.values.push_back(first.number);
      return property;
    }
    // The word `table` is optional: the reader strips a word followed by a dimension set (the
    // old style `nu nu [0 2 -1 0 0 0 0] 1e-5`), so `density table [1 -3 ...] (...)` arrives
    // here as the bare list.
    const bool tableWord = first.kind == ValueItem::Kind::Word && first.text == "table";
    if (!tableWord && first.kind != ValueItem::Kind::List) cursor.fail(first, description());
    const ValueItem& list = tableWord ? cursor.takeList(description()) : first;
    ItemCursor rows(list, cursor);
    for (std::size_t i = 0; !rows.atEnd(); ++i) {
      rows.setElement(i);
      const auto [temperature, value] = ValueTraits<std::tuple<double, double>>::read(rows);
      property.temperatures.push_back(temperature);
      property.values.push_back(value);
      property.rowLocations.push_back(list.items[i].location());
    }
    if (property.values.empty()) cursor.fail(list, "a table with at least one row (T value)");
    return property;
  }
};

}  // namespace dictionary

TemperatureTable TemperatureTable::read(const Dictionary& dict, std::string_view key,
                                        const Dimensions& valueDimensions) {
  const auto property = dict.get<PropertyValue>(key, valueDimensions);
  TemperatureTable table;
  table.location_ = dict.location(key);
  table.description_ = "'" + std::string(key) + "' in " + dict.name();
  for (std::size_t i = 0; i < property.values.size(); ++i) {
    const SourceLocation& where =
        property.rowLocations.empty() ? table.location_ : property.rowLocations[i];
    std::ostringstream message;
    if (!(property.values[i] > 0.0)) {
      message << "'" << key << "' must be positive in " << dict.name() << "; row " << i + 1
              << " has " << property.values[i];
      throw DictionaryError(where, message.str());
    }
    if (i > 0 && !(property.temperatures[i] > property.temperatures[i - 1])) {
      message << "temperatures of the table '" << key << "' in " << dict.name()
              << " must increase: row " << i + 1 << " has T = " << property.temperatures[i]
              << " K after " << property.temperatures[i - 1] << " K";
      throw DictionaryError(where, message.str());
    }
  }
  table.temperatures_ = property.temperatures;
  table.values_ = property.values;
  return table;
}

double TemperatureTable::operator()(double temperature) const {
  if (temperature <= temperatures_.front()) return values_.front();
  if (temperature >= temperatures_.back()) return values_.back();
  const auto above = std::upper_bound(temperatures_.begin(), temperatures_.end(), temperature);
  const auto i = static_cast<std::size_t>(std::distance(temperatures_.begin(), above));
  const double t0 = temperatures_[i - 1], t1 = temperatures_[i];
  const double fraction = (temperature - t0) / (t1 - t0);
  return values_[i - 1] + fraction * (values_[i] - values_[i - 1]);
}

void TemperatureTable::checkCovers(double temperature, const SourceLocation& where) const {
  if (isConstant()) return;
  if (temperature >= lowestTemperature() && temperature <= highestTemperature()) return;
  std::ostringstream message;
  message << "T = " << temperature << " K lies outside the table " << description_ << " ("
          << location_.str() << "), which covers " << lowestTemperature() << " K to "
          << highestTemperature() << " K (temperatures are in kelvin)";
  throw DictionaryError(where, message.str());
}

}  // namespace sphcast
