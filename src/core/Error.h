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

// An Error that every rank of a parallel run throws alike, after deciding together (a health
// check's stop, written state and all): rank 0 prints it, and the ranks end normally.
class CollectiveError : public Error {
 public:
  using Error::Error;
};

}  // namespace sphcast
