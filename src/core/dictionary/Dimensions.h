#pragma once

#include <array>
#include <string>

namespace sphcast {

// An OpenFOAM dimension set: the exponents of
// [mass length time temperature moles current luminous-intensity], e.g. [0 2 -1 0 0 0 0] for a
// kinematic viscosity. Readers pass the set they expect; a dictionary entry may state its own.
struct Dimensions {
  std::array<double, 7> exponents{};

  bool operator==(const Dimensions&) const = default;

  // "[0 2 -1 0 0 0 0]"; fractional exponents keep their shortest exact form ("0.5").
  std::string str() const;
};

}  // namespace sphcast
