#include "materials/TemperatureTable.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>

namespace sphcast {

TemperatureTable TemperatureTable::read(const Dictionary& dict, std::string_view key,
                                        const Dimensions& valueDimensions,
                                        Interpolation interpolation, ValueRule rule,
                                        const TemperatureColumn* columns) {
  return fromEntry(readPropertyEntry(dict, key, valueDimensions, columns), interpolation, rule);
}

TemperatureTable TemperatureTable::fromEntry(const PropertyEntry& entry,
                                             Interpolation interpolation, ValueRule rule) {
  // log(0) has no place in a log-linear table: a log-linear property is positive.
  const bool positive = rule == ValueRule::positive || interpolation == Interpolation::logLinear;
  for (std::size_t i = 0; i < entry.values.size(); ++i) {
    const double value = entry.values[i];
    if (positive ? value > 0.0 : value >= 0.0) continue;
    const char* range = positive ? "> 0" : ">= 0";
    const char* must = positive ? "must be positive" : "must not be negative";
    std::ostringstream message;
    if (entry.isConstant()) {
      message << "'" << entry.key << "' is " << value << " in " << entry.dictionaryName << "; it "
              << must << " (valid range: " << range << ")";
    } else {
      message << "'" << entry.key << "' " << must << " in " << entry.dictionaryName << "; row "
              << i + 1 << " has " << value << " (valid range: " << range << ")";
    }
    throw DictionaryError(entry.rowLocation(i), message.str());
  }
  TemperatureTable table;
  table.location_ = entry.location;
  table.description_ = entry.description;
  table.interpolation_ = interpolation;
  table.temperatures_ = entry.isConstant() ? std::vector<double>{0.0} : entry.temperatures;
  table.values_ = entry.values;
  if (interpolation == Interpolation::logLinear) {
    for (const double value : table.values_) table.logValues_.push_back(std::log(value));
  }
  return table;
}

double TemperatureTable::operator()(double temperature) const {
  if (temperature <= temperatures_.front()) return values_.front();
  if (temperature >= temperatures_.back()) return values_.back();
  const auto above = std::upper_bound(temperatures_.begin(), temperatures_.end(), temperature);
  const auto i = static_cast<std::size_t>(std::distance(temperatures_.begin(), above));
  const double t0 = temperatures_[i - 1], t1 = temperatures_[i];
  const double fraction = (temperature - t0) / (t1 - t0);
  if (interpolation_ == Interpolation::logLinear) {
    return std::exp(logValues_[i - 1] + fraction * (logValues_[i] - logValues_[i - 1]));
  }
  return values_[i - 1] + fraction * (values_[i] - values_[i - 1]);
}

double TemperatureTable::integral(double temperature) const {
  const double lowest = temperatures_.front();
  if (temperature <= lowest || isConstant()) return values_.front() * (temperature - lowest);
  double sum = 0;
  for (std::size_t i = 1; i < temperatures_.size(); ++i) {
    const double t0 = temperatures_[i - 1], t1 = temperatures_[i];
    const double end = std::min(temperature, t1);
    const double v0 = values_[i - 1];
    if (interpolation_ == Interpolation::logLinear && logValues_[i] != logValues_[i - 1]) {
      // exp(l0 + (l1 - l0) s), s = (T - t0) / (t1 - t0): its integral is (v(end) - v0) over
      // the slope of l in T
      sum += ((*this)(end) - v0) * (t1 - t0) / (logValues_[i] - logValues_[i - 1]);
    } else {
      const double slope = interpolation_ == Interpolation::logLinear
                               ? 0.0
                               : (values_[i] - v0) / (t1 - t0);
      sum += (end - t0) * (v0 + 0.5 * slope * (end - t0));
    }
    if (temperature <= t1) return sum;
  }
  return sum + values_.back() * (temperature - temperatures_.back());
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
