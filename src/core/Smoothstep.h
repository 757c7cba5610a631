#pragma once

#include "core/Real.h"

namespace sphcast {

// 0 for t <= 0, 1 for t >= 1, 3 t^2 - 2 t^3 between: a ramp with zero slope at both ends, for
// weights that switch a term on or off without kicking a particle that crosses the threshold.
inline Real smoothstep(Real t) {
  if (!(t > 0)) return 0;
  if (t >= 1) return 1;
  return t * t * (Real(3) - Real(2) * t);
}

}  // namespace sphcast
