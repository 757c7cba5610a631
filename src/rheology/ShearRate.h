#pragma once

#include <vector>

#include "boundaries/WallCondition.h"
#include "core/Real.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"
#include "sph/KernelCorrection.h"

namespace sphcast {

class WeaklyCompressibleFlow;

// A wall the shear rate sees (its particles carry volume, normal, wallDistance and, when they
// move, U) and its condition: the fluid sticks to a no-slip wall, slides along a slip one.
struct ShearWall {
  const ParticleCloud* cloud;
  WallCondition condition;
};

// The flow's walls with their conditions.
std::vector<ShearWall> shearWalls(const WeaklyCompressibleFlow& flow);

// The shear rate of every owned fluid particle, gammaDot = sqrt(2 D:D), D the symmetric part of
// the velocity gradient from the fluid and wall neighbours,
//   grad v_i = sum_j V_j (v_j - v_i) (x) L_i grad_i W_ij,
// with the kernel-gradient normalisation L_i (sph/KernelCorrection.h) so that a linear velocity
// field gives its gradient exactly where the support is truncated (a free surface, where the
// plain sum reads half the shear). A wall particle k carries the fluid's velocity continued
// through the wall surface as the viscous term's no-slip does (Morris, Fox & Zhu 1997):
// v_k - v_i = -beta (v_i - v_wall), beta = 1 + d_k / d_i, at a no-slip wall, and only its normal
// part at a slip wall (no shear across it). So the wall's velocity enters the gradient where the
// shear is largest: a power-law liquid's profile across a gap of 6 spacings (curved, its slope
// largest at the wall) read from the fluid alone gave the wall too little shear, and a squeeze
// 2.3 to 2.6 times too slow (1.6 times with the walls: doc/validation.md §1.7); Poiseuille's
// power law at 10 rows across, 13 % of u_max off (3.6 % with them). In simple shear v_x = s y it
// gives s. Only a particle with nearly no neighbours (a splash's droplet) keeps the plain sum.
void computeShearRates(const ParticleCloud& fluid, const Neighbourhood& neighbourhood,
                       const std::vector<ShearWall>& walls, int dimension, Real supportRadius,
                       std::vector<Real>& shearRate);

// gammaDot = sqrt(2 D:D) of a velocity gradient, D its symmetric part.
Real shearRateOf(const Matrix& gradient);

// The velocity gradient grad v (row a, column b: d v_a / d x_b) of every owned fluid particle
// that computeShearRates reduces to gammaDot: the same sum, walls and normalisation.
void computeVelocityGradients(const ParticleCloud& fluid, const Neighbourhood& neighbourhood,
                              const std::vector<ShearWall>& walls, int dimension,
                              Real supportRadius, std::vector<Matrix>& gradient);

}  // namespace sphcast
