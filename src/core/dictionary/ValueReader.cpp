#include "core/dictionary/ValueReader.h"

#include <charconv>
#include <cmath>

namespace sphcast::dictionary {

SourceLocation TextPosition::location() const {
  return SourceLocation{file ? *file : std::string(), line, column};
}

Dimensions ValueItem::dimensions() const {
  Dimensions set;
  for (std::size_t i = 0; i < items.size() && i < set.exponents.size(); ++i) {
    set.exponents[i] = items[i].number;
  }
  return set;
}

std::string describe(const ValueItem& item) {
  switch (item.kind) {
    case ValueItem::Kind::Number:
      return "number " + item.text;
    case ValueItem::Kind::Word:
      return "word '" + item.text + "'";
    case ValueItem::Kind::String:
      return "string \"" + item.text + "\"";
    case ValueItem::Kind::List:
      return "a list of " + std::to_string(item.items.size()) +
             (item.items.size() == 1 ? " item" : " items");
    case ValueItem::Kind::Dimensions:
      return "dimension set " + item.dimensions().str();
  }
  return "an item";
}

std::string countMismatchMessage(std::string_view subject, std::string_view countText,
                                 std::size_t itemCount) {
  return "list for " + std::string(subject) + " has " + std::to_string(itemCount) +
         (itemCount == 1 ? " item" : " items") + " but its count says " + std::string(countText);
}

ItemCursor::ItemCursor(std::span<const ValueItem> items, std::string key,
                       SourceLocation whereIfMissing)
    : items_(items), key_(std::move(key)), whereIfMissing_(std::move(whereIfMissing)) {}

ItemCursor::ItemCursor(const ValueItem& list, const ItemCursor& parent)
    : items_(list.items),
      key_(parent.key_),
      elementPath_(parent.elementPath_),
      whereIfMissing_(list.location()) {
  elementPath_.push_back(0);
}

const ValueItem& ItemCursor::take(std::string_view expected) {
  if (atEnd()) {
    throw DictionaryError(whereIfMissing_, "expected " + std::string(expected) + " for " +
                                               subject() + ", found nothing");
  }
  return items_[next_++];
}

const ValueItem& ItemCursor::takeList(std::string_view expected) {
  if (next_ + 1 < items_.size()) {
    const ValueItem& count = items_[next_];
    const ValueItem& list = items_[next_ + 1];
    const bool unsignedInteger = count.kind == ValueItem::Kind::Number && count.isInteger &&
                                 !count.text.empty() && count.text.front() != '-' &&
                                 count.text.front() != '+';
    if (unsignedInteger && list.kind == ValueItem::Kind::List) {
      unsigned long long declared = 0;
      const char* end = count.text.data() + count.text.size();
      const auto [stop, error] = std::from_chars(count.text.data(), end, declared);
      if (error != std::errc() || stop != end || declared != list.items.size()) {
        throw DictionaryError(count.location(),
                              countMismatchMessage(subject(), count.text, list.items.size()));
      }
      next_ += 2;
      return list;
    }
  }
  const ValueItem& item = take(expected);
  if (item.kind != ValueItem::Kind::List) fail(item, expected);
  return item;
}

void ItemCursor::setElement(std::size_t index) {
  if (!elementPath_.empty()) elementPath_.back() = index;
}

std::string ItemCursor::subject() const {
  std::string text = "'" + key_ + "'";
  for (std::size_t i = 0; i < elementPath_.size(); ++i) {
    text += (i == 0 ? " item " : ".") + std::to_string(elementPath_[i] + 1);
  }
  return text;
}

void ItemCursor::fail(const ValueItem& found, std::string_view expected) const {
  throw DictionaryError(found.location(), "expected " + std::string(expected) + " for " +
                                              subject() + ", found " + describe(found));
}

void ItemCursor::expectEnd() const {
  if (atEnd()) return;
  const ValueItem& extra = items_[next_];
  std::string message = "unexpected " + describe(extra) + " after the value of " + subject();
  if (next_ > 0 && extra.position.line > items_[next_ - 1].position.line) {
    message +=
        "; missing ';' at the end of line " + std::to_string(items_[next_ - 1].position.line) + "?";
  }
  throw DictionaryError(extra.location(), message);
}

double readReal(ItemCursor& cursor, std::string_view expected) {
  const ValueItem& item = cursor.take(expected);
  if (item.kind != ValueItem::Kind::Number) cursor.fail(item, expected);
  return item.number;
}

float readFloat(ItemCursor& cursor, std::string_view expected) {
  const ValueItem& item = cursor.take(expected);
  if (item.kind != ValueItem::Kind::Number) cursor.fail(item, expected);
  if (std::fabs(item.number) > static_cast<double>(std::numeric_limits<float>::max())) {
    throw DictionaryError(item.location(), "number " + item.text + " for " + cursor.subject() +
                                               " is out of range for single precision");
  }
  return static_cast<float>(item.number);
}

long long readInteger(ItemCursor& cursor, long long min, long long max, std::string_view expected) {
  const ValueItem& item = cursor.take(expected);
  if (item.kind != ValueItem::Kind::Number) cursor.fail(item, expected);

  long long value = 0;
  bool inLongLongRange = true;
  if (item.isInteger) {
    // from_chars takes no '+' sign.
    std::string_view digits = item.text;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    const auto [stop, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    inLongLongRange = error == std::errc() && stop == digits.data() + digits.size();
  } else {
    // 1e3 is an integer too; but only where a double holds every integer exactly.
    constexpr double exactLimit = 9007199254740992.0;  // 2^53
    if (std::trunc(item.number) != item.number) cursor.fail(item, expected);
    inLongLongRange = std::fabs(item.number) <= exactLimit;
    if (inLongLongRange) value = static_cast<long long>(item.number);
  }
  if (!inLongLongRange || value < min || value > max) {
    throw DictionaryError(item.location(), "number " + item.text + " for " + cursor.subject() +
                                               " is out of range [" + std::to_string(min) + ", " +
                                               std::to_string(max) + "]");
  }
  return value;
}

bool readBool(ItemCursor& cursor, std::string_view expected) {
  const ValueItem& item = cursor.take(expected);
  if (item.kind == ValueItem::Kind::Word) {
    const std::string& word = item.text;
    if (word == "yes" || word == "on" || word == "true" || word == "y") return true;
    if (word == "no" || word == "off" || word == "false" || word == "n") return false;
  }
  cursor.fail(item, expected);
}

std::string readText(ItemCursor& cursor, std::string_view expected) {
  const ValueItem& item = cursor.take(expected);
  if (item.kind != ValueItem::Kind::Word && item.kind != ValueItem::Kind::String) {
    cursor.fail(item, expected);
  }
  return item.text;
}

}  // namespace sphcast::dictionary
