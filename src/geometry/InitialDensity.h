#pragma once

#include <vector>

#include "core/Real.h"

namespace sphcast {

// Initial density of a filled melt, for the linear equation of state of DESIGN.md §4,
// eq. (3): p = c^2 (rho - rho_s(T)).
//
// Hydrostatic start: the pressure that holds the column up, p = rho_s |g| d at depth d below
// the free surface, asks for
//   rho = rho_s + rho_s |g| d / c^2,
// (first order in |g| d / c^2, which the weakly compressible choice of c keeps below ~1 %; the
// exact solution of dp/dd = rho |g| with this equation of state, rho_s exp(|g| d / c^2), differs
// by (|g| d / c^2)^2 / 2 relative). A melt started at rho = rho_s everywhere has no pressure
// gradient to carry its weight: it is compressed by gravity in the first acoustic periods, the
// surface drops and rebounds and sloshes (a 3D tank's surface rose 0.37 dx in 1.5 s).
inline double hydrostaticDensity(double restDensity, double gravityMagnitude, double depth,
                                 double soundSpeed) {
  return restDensity * (1.0 + gravityMagnitude * depth / (soundSpeed * soundSpeed));
}

// Depth of each particle below the free surface of the whole set along gravity: the surface is
// the highest particle along -g plus spacing / 2 (the top of its cell), d = surface - height.
// All zero when gravity is zero.
std::vector<double> depthsBelowFreeSurface(const std::vector<Vector>& positions,
                                           const Vector& gravity, double spacing);

}  // namespace sphcast
