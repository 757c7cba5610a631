#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/dictionary/Dimensions.h"
#include "core/dictionary/SourceLocation.h"

namespace sphcast::dictionary {

// Where an item was written. The file name is shared by every item of one file, so that a long
// table does not carry its own copy of the path for every number.
struct TextPosition {
  std::shared_ptr<const std::string> file;
  int line = 0;
  int column = 0;

  SourceLocation location() const;
};

// One item of an entry's value, as written: `value [0 1 -2 0 0 0 0] (0 0 -9.81);` holds a
// dimension set and a list of three numbers. Typed reading happens later, when a reader asks
// for a type (ValueReader.h), so that the error can say what that reader expected.
struct ValueItem {
  enum class Kind { Number, Word, String, List, Dimensions };

  Kind kind = Kind::Word;
  std::string text;              // a number as written, a word, or a string's contents
  double number = 0.0;           // Kind::Number
  bool isInteger = false;        // Kind::Number written as digits only, with an optional sign
  std::vector<ValueItem> items;  // Kind::List elements; Kind::Dimensions exponents (numbers)
  TextPosition position;

  SourceLocation location() const { return position.location(); }
  // Kind::Dimensions as a set: the exponents given, the rest zero.
  Dimensions dimensions() const;
};

// How an item reads in a message: "number 1.5", "word 'uniform'", "string \"a b\"",
// "a list of 3 items", "dimension set [0 1 0 0 0 0 0]".
std::string describe(const ValueItem& item);

// The message for `N( ... )` whose count N disagrees with what the list holds.
std::string countMismatchMessage(std::string_view subject, std::string_view countText,
                                 std::size_t itemCount);

}  // namespace sphcast::dictionary
