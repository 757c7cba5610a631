#pragma once

#include <cstddef>
#include <vector>

#include "core/Real.h"
#include "particles/CellGrid.h"
#include "particles/NeighbourList.h"
#include "particles/ParticleCloud.h"
#include "sph/ParticleVolumes.h"

namespace sphcast {

// The gradient of a scalar field at particle i with the kernel gradient corrected in full
// (Bonet & Lok 1999, Comput. Methods Appl. Mech. Engrg. 180:97, eq. (37)):
//
//   grad f_i = L_i sum_j V_j (f_j - f_i) grad_i W_ij,   L_i = (sum_j V_j grad_i W_ij (x_j -
//   x_i)^T)^-1
//
// exact for a linear field on any arrangement, also where the support is cut by a surface; the
// uncorrected sum where L_i cannot be inverted (fewer neighbours than the dimension needs). For
// what is measured (the Niyama criterion's G), not for the flow's forces, whose correction
// blends out at free surfaces for stability (KernelCorrection.h). Wendland C2 of support h;
// pairs: the cloud's neighbours of itself (self excluded); volume: V_j per particle.
Vector correctedGradient(const ParticleCloud& cloud, const std::vector<Real>& field,
                         const std::vector<Real>& volume, const NeighbourList& pairs,
                         const PeriodicBox& periodic, Real supportRadius, int dimension,
                         std::size_t i);

}  // namespace sphcast
