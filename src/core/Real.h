#pragma once

#include <Eigen/Core>

namespace sphcast {

// The one floating-point type of the particle data and the pair loops. Double by default;
// configure with -DSPHCAST_SINGLE_PRECISION=ON to measure speed against accuracy in float.
#ifdef SPHCAST_SINGLE_PRECISION
using Real = float;
#else
using Real = double;
#endif

// Positions, velocities and forces: always three components; 2D cases keep z = 0.
using Vector = Eigen::Matrix<Real, 3, 1>;

}  // namespace sphcast
