#pragma once

#include <string>

#include "core/Error.h"

namespace sphcast {

// A place in a dictionary file, for messages: "system/controlDict:12:5".
struct SourceLocation {
  std::string file;
  int line = 0;    // 1-based; 0 when the file as a whole is meant (e.g. it cannot be opened)
  int column = 0;  // 1-based, counted in bytes

  // "file:line:column", or just "file" when no line is known.
  std::string str() const;
};

// Every mistake in a dictionary: the message starts with where it is, so that a user can jump
// straight to it ("system/controlDict:12:5: missing key 'endTime' in controlDict").
class DictionaryError : public Error {
 public:
  DictionaryError(const SourceLocation& where, const std::string& message);

  const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

}  // namespace sphcast
