#include "core/dictionary/Dimensions.h"

#include <charconv>

namespace sphcast {

std::string Dimensions::str() const {
  std::string text = "[";
  for (std::size_t i = 0; i < exponents.size(); ++i) {
    if (i > 0) text += ' ';
    // -0 would read oddly in a message; it is the same exponent as 0.
    const double exponent = exponents[i] == 0.0 ? 0.0 : exponents[i];
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), exponent);
    text.append(buffer, result.ptr);
  }
  return text + "]";
}

}  // namespace sphcast
