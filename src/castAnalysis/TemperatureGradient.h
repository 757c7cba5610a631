#pragma once

#include <vector>

#include "core/Real.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// grad T at every particle of a cloud, with the kernel gradient corrected so that a linear field
// is differentiated exactly also where the support is cut by the casting's surface (Bonet &
// Lok 1999, Comput. Methods Appl. Mech. Engrg. 180:97, eq. (37)):
//
//   grad T_i = L_i sum_j V_j (T_j - T_i) grad_i W_ij,   L_i = (sum_j V_j grad_i W_ij (x_j -
//   x_i)^T)^-1
//
// over the cloud's own particles within h (Wendland C2; V_j = m_j / rho_j, or spacing^d without
// mass and rho). Where L_i cannot be inverted (fewer neighbours than the dimension needs) the
// uncorrected sum is taken. The temperature gradient G of the Niyama criterion is its length.
std::vector<Vector> temperatureGradient(const ParticleCloud& cloud, Real supportRadius,
                                        int dimension);

}  // namespace sphcast
