#pragma once

#include <vector>

#include "core/Real.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The shear rate of every owned fluid particle, gammaDot = sqrt(2 D:D), D the symmetric part of
// the velocity gradient from the fluid neighbours,
//   grad v_i = sum_j V_j (v_j - v_i) (x) L_i grad_i W_ij,
// with the kernel-gradient normalisation L_i (sph/KernelCorrection.h) so that a linear velocity
// field gives its gradient exactly where the support is truncated too: beside a wall (whose
// particles carry no flow velocity of their own) and at a free surface, where the plain sum
// reads half the shear. Only a particle with nearly no neighbours (a splash's droplet) keeps the
// plain sum. In simple shear v_x = s y it gives s.
void computeShearRates(const ParticleCloud& fluid, const Neighbourhood& neighbourhood,
                       int dimension, Real supportRadius, std::vector<Real>& shearRate);

}  // namespace sphcast
