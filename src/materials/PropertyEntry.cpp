#include "materials/PropertyEntry.h"

#include <sstream>

namespace sphcast {

namespace {

// The value of a property entry as written: a number, `table` and a list of rows, or a plain
// list of numbers (a column).
struct WrittenProperty {
  enum class Form { Constant, Rows, Column };
  Form form = Form::Constant;
  std::vector<double> temperatures;  // Rows only
  std::vector<double> values;
  std::vector<SourceLocation> rowLocations;  // Rows and Column
};

const Dimensions temperatureDimensions{{0, 0, 0, 1, 0, 0, 0}};

}  // namespace

namespace dictionary {

template <>
struct ValueTraits<WrittenProperty> {
  static std::string description() {
    return "a number or table ((T value) ...), or a column (value1 value2 ...)";
  }
  static WrittenProperty read(ItemCursor& cursor) {
    WrittenProperty property;
    const ValueItem& first = cursor.take(description());
    if (first.kind == ValueItem::Kind::Number) {
      property.values.push_back(first.number);
      return property;
    }
    // The word `table` is optional: the reader strips a word followed by a dimension set (the
    // old style `nu nu [0 2 -1 0 0 0 0] 1e-5`), so `density table [1 -3 ...] (...)` arrives
    // here as the bare list.
    const bool tableWord = first.kind == ValueItem::Kind::Word && first.text == "table";
    if (!tableWord && first.kind != ValueItem::Kind::List) cursor.fail(first, description());
    const ValueItem& list = tableWord ? cursor.takeList(description()) : first;
    ItemCursor elements(list, cursor);
    // A list of numbers is a column; a list of (T value) lists, rows.
    const bool column =
        !tableWord && !list.items.empty() && list.items.front().kind == ValueItem::Kind::Number;
    property.form = column ? WrittenProperty::Form::Column : WrittenProperty::Form::Rows;
    for (std::size_t i = 0; !elements.atEnd(); ++i) {
      elements.setElement(i);
      if (column) {
        property.values.push_back(readReal(elements, "a number"));
      } else {
        const auto [temperature, value] = ValueTraits<std::tuple<double, double>>::read(elements);
        property.temperatures.push_back(temperature);
        property.values.push_back(value);
      }
      property.rowLocations.push_back(list.items[i].location());
    }
    if (property.values.empty()) cursor.fail(list, "a table with at least one row (T value)");
    return property;
  }
};

}  // namespace dictionary

namespace {

std::string describeEntry(const Dictionary& dict, std::string_view key) {
  return "'" + std::string(key) + "' in " + dict.name();
}

// Row temperatures must increase strictly: interpolation divides by their differences.
void checkIncreasing(const std::vector<double>& temperatures,
                     const std::vector<SourceLocation>& rowLocations, std::string_view what) {
  for (std::size_t i = 1; i < temperatures.size(); ++i) {
    if (temperatures[i] > temperatures[i - 1]) continue;
    std::ostringstream message;
    message << "temperatures of the table " << what << " must increase: row " << i + 1
            << " has T = " << temperatures[i] << " K after " << temperatures[i - 1] << " K";
    throw DictionaryError(rowLocations[i], message.str());
  }
}

}  // namespace

TemperatureColumn readTemperatureColumn(const Dictionary& dict, std::string_view key) {
  const auto written = dict.get<WrittenProperty>(key, temperatureDimensions);
  TemperatureColumn column;
  column.location = dict.location(key);
  column.description = describeEntry(dict, key);
  if (written.form != WrittenProperty::Form::Column) {
    throw DictionaryError(column.location, column.description +
                                               " must be a list of temperatures (T1 T2 ...) in K, "
                                               "the rows of the properties written as columns");
  }
  column.temperatures = written.values;
  column.rowLocations = written.rowLocations;
  checkIncreasing(column.temperatures, column.rowLocations, column.description);
  return column;
}

PropertyEntry readPropertyEntry(const Dictionary& dict, std::string_view key,
                                const Dimensions& valueDimensions,
                                const TemperatureColumn* columns) {
  auto written = dict.get<WrittenProperty>(key, valueDimensions);
  PropertyEntry entry;
  entry.key = std::string(key);
  entry.location = dict.location(key);
  entry.dictionaryName = dict.name();
  entry.description = describeEntry(dict, key);
  entry.values = std::move(written.values);
  entry.rowLocations = std::move(written.rowLocations);
  switch (written.form) {
    case WrittenProperty::Form::Constant:
      break;
    case WrittenProperty::Form::Rows:
      entry.temperatures = std::move(written.temperatures);
      checkIncreasing(entry.temperatures, entry.rowLocations, entry.description);
      break;
    case WrittenProperty::Form::Column: {
      if (!columns) {
        throw DictionaryError(entry.location,
                              entry.description + " is a column of " +
                                  std::to_string(entry.values.size()) +
                                  " values, which needs the material's 'temperatures' "
                                  "(T1 T2 ...); or write table ((T value) ...)");
      }
      if (columns->temperatures.size() != entry.values.size()) {
        throw DictionaryError(
            entry.location,
            entry.description + " is a column of " + std::to_string(entry.values.size()) +
                " values, but " + columns->description + " (" + columns->location.str() + ") has " +
                std::to_string(columns->temperatures.size()) + " rows; the lengths must be equal");
      }
      entry.temperatures = columns->temperatures;
      break;
    }
  }
  return entry;
}

}  // namespace sphcast
