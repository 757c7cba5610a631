#pragma once

#include <vector>

#include "core/Real.h"

namespace sphcast {

// Initial density of a filled melt, for the linear equation of state of doc/physics.md §4,
// eq. (3): p = c^2 (rho - rho_s(T)).
//
// Hydrostatic start: the pressure that holds the column up, p = rho_s |g| d at depth d below
// the free surface, asks for
//   rho = rho_s + rho_s |g| d / c^2,
// (first order in |g| d / c^2, which the weakly compressible choice of c keeps below ~1 %; the
// exact solution of dp/dd = rho |g| with this equation of state, rho_s exp(|g| d / c^2), differs
// by (|g| d / c^2)^2 / 2 relative). A melt started at rho = rho_s everywhere has no pressure
// gradient to carry its weight: gravity compresses it in the first acoustic periods and it
// bounces. Measured on tutorials/validation/hydrostaticTank (4,000 particles, c = 10 m/s),
// 0 to 0.5 s: from rho_s the centroid dropped 0.11 mm (0.022 dx) in 0.05 s and the mean
// vertical velocity swung between -4.9 and +6.4 mm/s; from the hydrostatic density it stayed
// between 0 and +1.2 mm/s. (Both runs show the same slow rise of the surface, ~0.7 dx in
// 0.5 s for the top particle: that comes from the solver, not from the start.)
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
