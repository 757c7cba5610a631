#include "core/dictionary/Dictionary.h"

#include <algorithm>
#include <map>
#include <mutex>
#include <utility>

#include "core/dictionary/Parser.h"

namespace sphcast {

namespace {

std::string inQuotes(std::string_view key) {
  // Appended piecewise: "'" + std::string(...) trips a false -Wrestrict in GCC 12.
  std::string text(1, '\'');
  text.append(key);
  text += '\'';
  return text;
}

// "(a b c)", as OpenFOAM lists the valid words.
std::string listed(const std::vector<std::string>& words) {
  std::string text = "(";
  for (std::size_t i = 0; i < words.size(); ++i) text += (i == 0 ? "" : " ") + words[i];
  return text + ")";
}

// Optimal string alignment distance: insertions, deletions, substitutions and transpositions
// of two neighbouring letters ("modle" for "model") each count one edit. Three rows at a time.
std::size_t editDistance(std::string_view from, std::string_view to) {
  std::vector<std::size_t> beforeLast(to.size() + 1), last(to.size() + 1), row(to.size() + 1);
  for (std::size_t j = 0; j <= to.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= from.size(); ++i) {
    std::swap(beforeLast, last);
    std::swap(last, row);
    row[0] = i;
    for (std::size_t j = 1; j <= to.size(); ++j) {
      const std::size_t substitution = last[j - 1] + (from[i - 1] == to[j - 1] ? 0 : 1);
      row[j] = std::min({last[j] + 1, row[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && from[i - 1] == to[j - 2] && from[i - 2] == to[j - 1]) {
        row[j] = std::min(row[j], beforeLast[j - 2] + 1);
      }
    }
  }
  return row[to.size()];
}

// "; did you mean 'endTime'?" when a valid word is near, else "".
std::string suggestion(std::string_view misspelt, const std::vector<std::string>& validWords) {
  const std::string nearest = nearestWord(misspelt, validWords);
  return nearest.empty() ? "" : "; did you mean " + inQuotes(nearest) + "?";
}

}  // namespace

std::string foamFileHeader(std::string_view location, std::string_view object) {
  return "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       dictionary;\n"
         "    location    \"" +
         std::string(location) + "\";\n    object      " + std::string(object) + ";\n}\n";
}

std::string nearestWord(std::string_view misspelt, const std::vector<std::string>& validWords) {
  std::string nearest;
  std::size_t nearestDistance = 0;
  for (const std::string& valid : validWords) {
    const std::size_t tolerance = std::max<std::size_t>(1, valid.size() / 3);
    // The distance is at least the difference in length: a long word is not compared at all.
    const std::size_t shorter = std::min(misspelt.size(), valid.size());
    if (std::max(misspelt.size(), valid.size()) - shorter > tolerance) continue;
    const std::size_t distance = editDistance(misspelt, valid);
    if (distance <= tolerance && (nearest.empty() || distance < nearestDistance)) {
      nearest = valid;
      nearestDistance = distance;
    }
  }
  return nearest;
}

namespace {
std::mutex readCountMutex;
std::map<std::string, int> readCounts;  // absolute path -> reads
std::string countKey(const std::filesystem::path& file) {
  return std::filesystem::absolute(file).lexically_normal().string();
}
}  // namespace

Dictionary Dictionary::read(const std::filesystem::path& file) {
  {
    const std::lock_guard<std::mutex> lock(readCountMutex);
    ++readCounts[countKey(file)];
  }
  return dictionary::Parser::readFile(file);
}

int Dictionary::readCount(const std::filesystem::path& file) {
  const std::lock_guard<std::mutex> lock(readCountMutex);
  const auto found = readCounts.find(countKey(file));
  return found == readCounts.end() ? 0 : found->second;
}

Dictionary Dictionary::parse(std::string_view text, const std::string& fileName) {
  return dictionary::Parser::parseText(text, fileName);
}

const Dictionary::Entry* Dictionary::findEntry(std::string_view key) const {
  const auto place = keyIndex_.find(key);
  return place == keyIndex_.end() ? nullptr : &entries_[place->second];
}

Dictionary::Entry* Dictionary::findEntry(std::string_view key) {
  const auto place = keyIndex_.find(key);
  return place == keyIndex_.end() ? nullptr : &entries_[place->second];
}

void Dictionary::appendEntry(Entry entry) {
  keyIndex_.emplace(entry.key, entries_.size());
  entries_.push_back(std::move(entry));
}

std::vector<std::string> Dictionary::keys() const {
  std::vector<std::string> result;
  result.reserve(entries_.size());
  for (const Entry& entry : entries_) result.push_back(entry.key);
  return result;
}

bool Dictionary::found(std::string_view key) const { return findEntry(key) != nullptr; }

bool Dictionary::isDict(std::string_view key) const {
  const Entry* entry = findEntry(key);
  return entry && entry->subDict;
}

const Dictionary& Dictionary::subDict(std::string_view key) const {
  const Entry* entry = findEntry(key);
  if (!entry) {
    throw DictionaryError(location_, "missing sub-dictionary " + inQuotes(key) + " in " + name_);
  }
  if (!entry->subDict) {
    throw DictionaryError(entry->where, "expected a sub-dictionary { ... } for " + inQuotes(key) +
                                            " in " + name_ + ", found a value");
  }
  return *entry->subDict;
}

SourceLocation Dictionary::location(std::string_view key) const {
  const Entry* entry = findEntry(key);
  if (!entry) throw DictionaryError(location_, "missing key " + inQuotes(key) + " in " + name_);
  return entry->where;
}

dictionary::ItemCursor Dictionary::valueCursor(std::string_view key, const Dimensions* expected,
                                               const std::string& description) const {
  using dictionary::ValueItem;
  const Entry* entry = findEntry(key);
  if (!entry) throw DictionaryError(location_, "missing key " + inQuotes(key) + " in " + name_);
  if (entry->subDict) {
    throw DictionaryError(entry->where, "expected " + description + " for " + inQuotes(key) +
                                            ", found a sub-dictionary");
  }

  // A dimension set comes first, or after a name in the old style `nu nu [0 2 -1 0 0 0 0] 1e-5`.
  std::span<const ValueItem> items = entry->value;
  std::size_t dimensionsAt = items.size();
  if (!items.empty() && items[0].kind == ValueItem::Kind::Dimensions) {
    dimensionsAt = 0;
  } else if (items.size() > 1 && items[0].kind == ValueItem::Kind::Word &&
             items[1].kind == ValueItem::Kind::Dimensions) {
    dimensionsAt = 1;
  }
  if (dimensionsAt < items.size()) {
    const ValueItem& dimensions = items[dimensionsAt];
    if (expected && dimensions.dimensions() != *expected) {
      throw DictionaryError(dimensions.location(),
                            "dimensions " + dimensions.dimensions().str() + " of " + inQuotes(key) +
                                " do not match the expected " + expected->str());
    }
    items = items.subspan(dimensionsAt + 1);
  }
  return dictionary::ItemCursor(items, std::string(key), entry->valueEnd);
}

void Dictionary::checkDimensions(std::string_view key, const Dimensions& expected) const {
  const std::string description = "a dimension set " + expected.str();
  const Entry* entry = findEntry(key);
  if (entry && !entry->subDict &&
      (entry->value.empty() || entry->value[0].kind != dictionary::ValueItem::Kind::Dimensions)) {
    throw DictionaryError(entry->where, "expected " + description + " for " + inQuotes(key));
  }
  valueCursor(key, &expected, description).expectEnd();
}

std::string Dictionary::getChoice(std::string_view key,
                                  const std::vector<std::string>& choices) const {
  const std::string expected = "one of " + listed(choices);
  dictionary::ItemCursor cursor = valueCursor(key, nullptr, expected);
  const dictionary::ValueItem& item = cursor.take(expected);
  if (item.kind != dictionary::ValueItem::Kind::Word &&
      item.kind != dictionary::ValueItem::Kind::String) {
    cursor.fail(item, expected);
  }
  cursor.expectEnd();
  if (std::find(choices.begin(), choices.end(), item.text) == choices.end()) {
    const std::string didYouMean = suggestion(item.text, choices);
    throw DictionaryError(item.location(), "unknown " + std::string(key) + " " +
                                               inQuotes(item.text) + didYouMean +
                                               (didYouMean.empty() ? "; " : " ") + "valid " +
                                               std::string(key) + " are: " + listed(choices));
  }
  return item.text;
}

std::string Dictionary::getChoiceOrDefault(std::string_view key,
                                           const std::vector<std::string>& choices,
                                           const std::string& fallback) const {
  return found(key) ? getChoice(key, choices) : fallback;
}

void Dictionary::checkKeys(const std::vector<std::string>& validKeys) const {
  for (const Entry& entry : entries_) {
    if (std::find(validKeys.begin(), validKeys.end(), entry.key) != validKeys.end()) continue;
    const std::string didYouMean = suggestion(entry.key, validKeys);
    throw DictionaryError(entry.where, "unknown key " + inQuotes(entry.key) + " in " + name_ +
                                           didYouMean + (didYouMean.empty() ? "; " : " ") +
                                           "valid keys are: " + listed(validKeys));
  }
}

}  // namespace sphcast
