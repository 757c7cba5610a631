#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/dictionary/Dimensions.h"
#include "core/dictionary/SourceLocation.h"
#include "core/dictionary/ValueItem.h"
#include "core/dictionary/ValueReader.h"

namespace sphcast {

namespace dictionary {
class Parser;
}

// An OpenFOAM dictionary read from a case file (doc/design.md §2): `key value;` entries,
// sub-dictionaries `{ }`, lists, optional dimension sets, comments, #include and $macros, all
// resolved while reading. Values are converted when a reader asks for a type, so that every
// mistake is reported against the key and the file, line and column where it was written.
// A dictionary is immutable once read; copies share their sub-dictionaries.
class Dictionary {
 public:
  // An empty dictionary, e.g. for optional settings that were not given.
  Dictionary() = default;

  // A missing or unreadable file is a DictionaryError naming it.
  static Dictionary read(const std::filesystem::path& file);
  // How many times read() has parsed `file` in this process (by its absolute path): the tests
  // hold each tool to one reading of each case file (case/CaseDescription.h).
  static int readCount(const std::filesystem::path& file);
  // #include paths are relative to fileName's folder; fileName also names the locations.
  static Dictionary parse(std::string_view text, const std::string& fileName = "<string>");

  // Scoped name for messages: "controlDict", "controlDict/functions/probes".
  const std::string& name() const { return name_; }
  // Where this (sub-)dictionary starts.
  const SourceLocation& location() const { return location_; }

  // Keys in file order (an overridden key keeps its first place); the FoamFile header excluded.
  // A key may be given again to override an entry of an #include file or of a $macro merge
  // (`$defaults`); a value given twice in one file and scope is an error naming both lines. A
  // sub-dictionary given twice is merged, its entries by the same rule.
  std::vector<std::string> keys() const;
  bool found(std::string_view key) const;
  bool isDict(std::string_view key) const;
  // Missing, or not a dictionary: DictionaryError.
  const Dictionary& subDict(std::string_view key) const;
  // Where the key's entry is written.
  SourceLocation location(std::string_view key) const;

  // The value of `key` as T: double, float, the integer types, bool, std::string,
  // sphcast::Vector, Eigen::Vector2d, std::vector of those, and tables as
  // std::vector<std::tuple<...>>. Missing key or wrong type: DictionaryError.
  template <class T>
  T get(std::string_view key) const;
  // As get(key), but a dimension set written in the entry must equal `expected`.
  template <class T>
  T get(std::string_view key, const Dimensions& expected) const;
  template <class T>
  T getOrDefault(std::string_view key, const T& fallback) const;

  // A word out of `choices`, OpenFOAM style, suggesting the nearest one:
  // "unknown stopAt 'wirteNow'; did you mean 'writeNow'? valid stopAt are: (endTime ...)".
  std::string getChoice(std::string_view key, const std::vector<std::string>& choices) const;
  std::string getChoiceOrDefault(std::string_view key, const std::vector<std::string>& choices,
                                 const std::string& fallback) const;

  // An entry that is a dimension set alone, as `dimensions [0 1 -2 0 0 0 0];` in constant/g,
  // must equal `expected`: "dimensions [0 1 -1 0 0 0 0] of 'dimensions' do not match ...".
  void checkDimensions(std::string_view key, const Dimensions& expected) const;

  // The first key not in validKeys is an error at that key, suggesting the nearest valid one:
  // "unknown key 'endTme' in controlDict; did you mean 'endTime'? valid keys are: (...)".
  void checkKeys(const std::vector<std::string>& validKeys) const;

  // The FoamFile sub-dictionary, or nullptr when the file has none.
  const Dictionary* header() const { return header_.get(); }

 private:
  friend class dictionary::Parser;

  struct Entry {
    std::string key;
    SourceLocation where;  // of the key
    bool copied = false;   // brought in by a $macro merge, not written here
    std::vector<dictionary::ValueItem> value;
    SourceLocation valueEnd;              // just after the value, for "found nothing"
    std::shared_ptr<Dictionary> subDict;  // set for a sub-dictionary, which has no value
  };

  const Entry* findEntry(std::string_view key) const;
  Entry* findEntry(std::string_view key);
  // Adds an entry with a key not yet present.
  void appendEntry(Entry entry);
  // The items of `key`'s value with a leading dimension set stripped (and checked against
  // `expected` when given); `description` says what the reader wants, for the errors.
  dictionary::ItemCursor valueCursor(std::string_view key, const Dimensions* expected,
                                     const std::string& description) const;

  std::string name_;
  SourceLocation location_;
  std::vector<Entry> entries_;                                // in file order
  std::map<std::string, std::size_t, std::less<>> keyIndex_;  // key -> place in entries_
  std::shared_ptr<Dictionary> header_;
};

template <class T>
T Dictionary::get(std::string_view key) const {
  using Traits = dictionary::ValueTraits<T>;
  dictionary::ItemCursor cursor = valueCursor(key, nullptr, Traits::description());
  T value = Traits::read(cursor);
  cursor.expectEnd();
  return value;
}

template <class T>
T Dictionary::get(std::string_view key, const Dimensions& expected) const {
  using Traits = dictionary::ValueTraits<T>;
  dictionary::ItemCursor cursor = valueCursor(key, &expected, Traits::description());
  T value = Traits::read(cursor);
  cursor.expectEnd();
  return value;
}

template <class T>
T Dictionary::getOrDefault(std::string_view key, const T& fallback) const {
  return found(key) ? get<T>(key) : fallback;
}

// The FoamFile header of a dictionary sphCast writes (class dictionary), ending "}\n".
std::string foamFileHeader(std::string_view location, std::string_view object);

// The word of validWords that `misspelt` most likely meant, for "did you mean" in messages:
// within a third of its length (at least one edit; a swap of two neighbouring letters is one),
// the first of equally near ones; empty if none is that near.
std::string nearestWord(std::string_view misspelt, const std::vector<std::string>& validWords);

}  // namespace sphcast
