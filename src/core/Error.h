#pragma once

#include <stdexcept>
#include <string>

namespace sphcast {

// Every failure a user can cause (bad input, missing file, unstable run) is thrown as an Error
// whose message already says what was wrong and where; applications print it and exit non-zero.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sphcast
