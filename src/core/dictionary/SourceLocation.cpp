#include "core/dictionary/SourceLocation.h"

namespace sphcast {

std::string SourceLocation::str() const {
  if (line <= 0) return file;
  return file + ':' + std::to_string(line) + ':' + std::to_string(column);
}

DictionaryError::DictionaryError(const SourceLocation& where, const std::string& message)
    : Error(where.str() + ": " + message), where_(where) {}

}  // namespace sphcast
