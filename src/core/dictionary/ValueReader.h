#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/dictionary/ValueItem.h"

namespace sphcast::dictionary {

// Walks the items of one value (or of one list inside it) while a typed reader takes them, and
// phrases every complaint the same way: "expected a vector (x y z) for 'g', found word
// 'uniform'", with "'table' item 3.2" naming an element inside lists.
class ItemCursor {
 public:
  // The items of the entry `key`; whereIfMissing is reported when the value runs out of items.
  ItemCursor(std::span<const ValueItem> items, std::string key, SourceLocation whereIfMissing);
  // The elements of `list`, an item that `parent` has just taken.
  ItemCursor(const ValueItem& list, const ItemCursor& parent);

  bool atEnd() const { return next_ == items_.size(); }

  // The next item, or an error saying that `expected` was missing.
  const ValueItem& take(std::string_view expected);
  // The next item as a list, which may be preceded by its count written apart, as OpenFOAM
  // writes long lists ("3\n(a b c)"); the count is checked.
  const ValueItem& takeList(std::string_view expected);

  // Which element (0-based) of a list is being read, for messages.
  void setElement(std::size_t index);
  // "'g'" or "'table' item 3.2" (1-based, as a user counts).
  std::string subject() const;

  [[noreturn]] void fail(const ValueItem& found, std::string_view expected) const;
  // Nothing may be left once the whole value has been read; leftovers often mean a missing ';'.
  void expectEnd() const;

 private:
  std::span<const ValueItem> items_;
  std::size_t next_ = 0;
  std::string key_;
  std::vector<std::size_t> elementPath_;
  SourceLocation whereIfMissing_;
};

double readReal(ItemCursor& cursor, std::string_view expected);
float readFloat(ItemCursor& cursor, std::string_view expected);
// An integral number in [min, max]; written as digits, or as an exactly integral float (1e3).
long long readInteger(ItemCursor& cursor, long long min, long long max, std::string_view expected);
bool readBool(ItemCursor& cursor, std::string_view expected);
std::string readText(ItemCursor& cursor, std::string_view expected);

// How a value of type T is read from items. Each specialisation gives description(), the
// words used in "expected ... for 'key'", and read(), which takes exactly T's items.
template <class T>
struct ValueTraits;

template <>
struct ValueTraits<double> {
  static std::string description() { return "a number"; }
  static double read(ItemCursor& cursor) { return readReal(cursor, description()); }
};

template <>
struct ValueTraits<float> {
  static std::string description() { return "a number"; }
  static float read(ItemCursor& cursor) { return readFloat(cursor, description()); }
};

template <class Integer>
requires(std::is_integral_v<Integer> &&
         !std::is_same_v<Integer, bool>) struct ValueTraits<Integer> {
  static std::string description() {
    return std::is_signed_v<Integer> ? "an integer" : "a non-negative integer";
  }
  static Integer read(ItemCursor& cursor) {
    // Values beyond long long's range are never needed in a dictionary; clip the bounds to it.
    constexpr long long min = static_cast<long long>(std::numeric_limits<Integer>::min());
    constexpr long long max =
        std::numeric_limits<Integer>::max() >
                static_cast<unsigned long long>(std::numeric_limits<long long>::max())
            ? std::numeric_limits<long long>::max()
            : static_cast<long long>(std::numeric_limits<Integer>::max());
    return static_cast<Integer>(readInteger(cursor, min, max, description()));
  }
};

template <>
struct ValueTraits<bool> {
  static std::string description() { return "a boolean (yes/no/on/off/true/false)"; }
  static bool read(ItemCursor& cursor) { return readBool(cursor, description()); }
};

template <>
struct ValueTraits<std::string> {
  static std::string description() { return "a word or string"; }
  static std::string read(ItemCursor& cursor) { return readText(cursor, description()); }
};

// Fixed-size column vectors: sphcast::Vector (x y z), Eigen::Vector2d (x y).
template <class Scalar, int Size, int Options, int MaxRows, int MaxCols>
requires(Size > 0) struct ValueTraits<Eigen::Matrix<Scalar, Size, 1, Options, MaxRows, MaxCols>> {
  using VectorType = Eigen::Matrix<Scalar, Size, 1, Options, MaxRows, MaxCols>;

  static std::string description() {
    if constexpr (Size == 3) return "a vector (x y z)";
    if constexpr (Size == 2) return "a 2-vector (x y)";
    return "a list of " + std::to_string(Size) + " numbers";
  }
  static VectorType read(ItemCursor& cursor) {
    const ValueItem& list = cursor.takeList(description());
    if (list.items.size() != static_cast<std::size_t>(Size)) cursor.fail(list, description());
    ItemCursor components(list, cursor);
    VectorType vector;
    for (int i = 0; i < Size; ++i) {
      components.setElement(static_cast<std::size_t>(i));
      vector[i] = static_cast<Scalar>(readReal(components, "a number"));
    }
    return vector;
  }
};

template <class Element>
struct ValueTraits<std::vector<Element>> {
  static std::string description() { return "a list"; }
  static std::vector<Element> read(ItemCursor& cursor) {
    const ValueItem& list = cursor.takeList(description());
    ItemCursor elements(list, cursor);
    std::vector<Element> values;
    for (std::size_t i = 0; !elements.atEnd(); ++i) {
      elements.setElement(i);
      values.push_back(ValueTraits<Element>::read(elements));
    }
    return values;
  }
};

// One row of a table: `(300 2700)` as std::tuple<double, double>.
template <class... Columns>
struct ValueTraits<std::tuple<Columns...>> {
  static std::string description() {
    return "a list of " + std::to_string(sizeof...(Columns)) + " values";
  }
  static std::tuple<Columns...> read(ItemCursor& cursor) {
    const ValueItem& list = cursor.takeList(description());
    ItemCursor row(list, cursor);
    auto values = readColumns(row, std::index_sequence_for<Columns...>{});
    if (!row.atEnd()) cursor.fail(list, description());
    return values;
  }

 private:
  template <std::size_t... Index>
  static std::tuple<Columns...> readColumns(ItemCursor& row, std::index_sequence<Index...>) {
    // A braced initialiser evaluates left to right, so the columns are taken in order.
    return std::tuple<Columns...>{readColumn<Columns>(row, Index)...};
  }
  template <class Column>
  static Column readColumn(ItemCursor& row, std::size_t index) {
    row.setElement(index);
    return ValueTraits<Column>::read(row);
  }
};

}  // namespace sphcast::dictionary
