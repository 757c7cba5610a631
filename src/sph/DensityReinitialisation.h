#pragma once

#include <vector>

#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The fluid's density relaxed towards the particles' arrangement (densityReinitialisation packed
// in system/sphSchemes), after the density summation of free-surface flows (Zhang, Hu & Adams
// 2017, J. Comput. Phys. 340:439; SPHinXsys re-initialises to max(rho_sum, rho_0) at each
// advection step):
//
//   rho_sum,i = rho_s,i (sum_j V_j W_ij) / sigma_0,
//   rho_i <- rho_i + beta (max(rho_sum,i, min(rho_i, rho_s,i)) - rho_i),
//
// V_j the rest volume m_j / rho_s,j of a fluid particle (i itself included) or the volume V_k of a
// wall particle, sigma_0 the same sum over a full lattice of the fluid's spacing, beta the
// relaxation (densityReinitialisationCoeffs, default 0.3), before every evaluation of the rates.
// The continuity equation's tension stays (a melt pulled apart by its shrinkage, a free surface),
// and its compression where the particles are packed; where it says compressed and the particles
// stand apart (sum_j V_j W_ij below sigma_0: a film squeezed from a block, its rows spread across
// it), the arrangement wins and the pressure falls, so that a load presses the particles together
// instead of resting on a density no arrangement carries. Measured (doc/physics.md §7.4, a
// periodic film of N rows squeezed from a block 2N high under a piston at 400 Pa, 0.5 s): with
// continuity alone the film stood 0.78 / 0.88 / 1.14 dx thicker than its volume at N = 2 / 4 / 8,
// its particles' kernel sums 0.73 to 0.96; with beta 0.3, 0.000 / 0.003 dx at N = 2 / 8 (beta
// 0.1: 0.009 / 0.034, still settling; beta 1, the whole step to the target, set the piston
// bouncing by 2 dx).
class DensityReinitialisation {
 public:
  // relaxation: the share beta of the way to the re-initialised density taken at each call.
  DensityReinitialisation(int dimension, Real supportRadius, Real spacing, Real relaxation);

  // Over the owned particles (frozen ones too: they keep their continuity density only where it
  // is packed); a decomposed run's halo gets its owners' rho.
  void apply(ParticleCloud& fluid, const std::vector<const ParticleCloud*>& walls,
             const Neighbourhood& neighbourhood) const;

 private:
  template <int Dim>
  void applyIn(ParticleCloud& fluid, const std::vector<const ParticleCloud*>& walls,
               const Neighbourhood& neighbourhood) const;

  int dimension_;
  Real supportRadius_;
  Real relaxation_;
  Real latticeSum_;  // sigma_0 (particles/WendlandKernel.h, latticeKernelSum)
};

}  // namespace sphcast
