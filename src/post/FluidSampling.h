#pragma once

#include <limits>
#include <vector>

#include "core/Real.h"
#include "parallel/Communicator.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// Values of a fluid cloud at points that are not particles, for probes and the dam-break
// measurements. Each call is one pass over the cloud (no neighbour grid): a few probes per step
// cost about as much as one field copy, far below a flow step.

// The value the sampling functions give where no fluid particle is within reach.
inline constexpr double noFluid = std::numeric_limits<double>::quiet_NaN();

// Shepard-normalised kernel interpolation (Shepard 1968; e.g. Monaghan 2005, Rep. Prog. Phys.
// 68:1703, sec. 3):
//   f(x) = sum_j f_j V_j W(|x - x_j|, h) / sum_j V_j W(|x - x_j|, h),   V_j = m_j / rho_j
// over the fluid particles within the support radius h (Wendland C2 shape; its normalisation
// cancels, so the dimension does not matter). V_j = 1 for a cloud without mass and rho.
// Exact for a constant field everywhere; exact for a linear field wherever the first moment
// sum_j V_j W (x_j - x) vanishes, e.g. at points of symmetry of a full uniform lattice; elsewhere
// its error is that moment times the gradient. noFluid where no particle lies within h.
// Collective over comm in a decomposed run: each rank sums its owned particles, and the sums
// are added over the ranks.
class ShepardInterpolation {
 public:
  ShepardInterpolation(const ParticleCloud& fluid, Real supportRadius,
                       const Communicator& comm = Communicator::self());

  double scalar(const std::vector<Real>& field, const Vector& point) const;
  Vector vector(const std::vector<Vector>& field, const Vector& point) const;

 private:
  template <class Accumulate>
  bool accumulate(const Vector& point, Accumulate add) const;

  const ParticleCloud& fluid_;
  Real supportRadius_;
  Communicator comm_;
  const std::vector<Real>* mass_ = nullptr;
  const std::vector<Real>* density_ = nullptr;
};

// The free-surface level above a horizontal point: the largest height (x . up) of a fluid
// particle within `radius` of the vertical line through `point`, plus half the cloud's lattice
// spacing (attribute "spacing", 0 without it) so that a column of n layers resting on y = 0
// reads n dx. noFluid where the column holds no fluid.
double surfaceHeight(const ParticleCloud& fluid, const Vector& up, const Vector& point,
                     Real radius, const Communicator& comm = Communicator::self());

// The leading edge of the fluid along a unit direction: the largest x . direction of a particle
// plus half the lattice spacing (the surge front of a dam break). noFluid for an empty cloud.
// Over every rank of comm in a decomposed run (its owned particles).
double fluidFront(const ParticleCloud& fluid, const Vector& direction,
                  const Communicator& comm = Communicator::self());

}  // namespace sphcast
