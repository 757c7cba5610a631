#pragma once

#include <cmath>
#include <vector>

#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"
#include "sph/ParticleVolumes.h"

namespace sphcast {

// How the exposed area is estimated (doc/physics.md §10.2.4).
enum class ExposedAreaForm {
  // A_i = R_A V_i |grad s_i|, grad s_i = sum_j V_j grad_i W_ij: the surface delta function of
  // the continuum surface force (Brackbill, Kothe & Zemach 1992), whose integral across any
  // interface is its area; the default.
  gradient,
  // A_i = R_A g(1 - s_i, 1 - s_min,i) V_i^((d-1)/d), eq. (11) of the paper with g of eq. (10):
  // g grows as (1 - s)^3, so particles with few neighbours (edges, the steps of a lattice cut
  // by a curved surface) count far more than their share.
  granularity
};

// The area A_i of each particle exposed to the outside (the air), from its rate of
// granularity s_i, eq. (7) of the paper:
//
//   s_i = sum_j V_j W(|x_i - x_j|, h)          over i itself and every particle of every
//                                              covering cloud (metal and molds alike: a face
//                                              against the mold is not exposed to the air)
//
// by either form above, with V from particleVolumes (ParticleVolumes.h: mass / rho, else volume).
// R_A is calibrated for the form, the dimension and h/dx by calibratedAreaFactor(): the sum of
// A_i over a column of a semi-infinite cubic lattice under a flat free surface is exactly the
// column's cross-section dx^(d-1). At h = 3 dx: R_A = 2.00 (3D) and 2.01 (2D) for the gradient
// form (the particles sample only the inner half of the smoothed interface), 59.2 (3D) and
// 44.3 (2D) for eq. (11), where the paper takes R_A = R_d, the surface-tension constant: its
// R_3 = 41.3 would count 70 % of a flat face, its R_2 = 41.4 94 %.
// Edges, corners and curved surfaces are then approximations, measured in
// tests/unit/thermal/SurfaceHeatLossTest.cpp: the sum over a cube of 10 / 20 / 40 particles
// across is 22 / 11 / 6 % short of 6 L^2 with the gradient form (edges rounded over about h),
// 60 / 31 / 15 % over with eq. (11); over a ball cut from the lattice, 15 / 6 / 2.6 % against
// 140 / 99 / 84 %.
//
// Writes the field `exposedArea` (m^2 in 3D, m in 2D) of each exposed cloud, and `granularity`
// (s_i), shared by every model that needs them (atmosphere, radiation; surface tension next).
class ExposedArea {
 public:
  // exposed: the clouds whose A_i is wanted; covering: every cloud whose particles cover
  // (include the exposed ones). Registers the pairs in the neighbourhood. spacing: the lattice
  // spacing dx the calibration assumes (the exposed clouds' `spacing` attribute).
  ExposedArea(ExposedAreaForm form, int dimension, Real supportRadius, Real spacing,
              std::vector<ParticleCloud*> exposed, std::vector<const ParticleCloud*> covering,
              Neighbourhood& neighbourhood);

  // s_i and A_i of every exposed particle, for the neighbourhood's last update (particles that
  // do not move keep theirs: the solver computes it once without a flow).
  void compute();

  Real areaFactor() const { return areaFactor_; }

  // R_A for this form, dimension and h/dx (see the class comment).
  static Real calibratedAreaFactor(ExposedAreaForm form, int dimension, Real supportRadius,
                                   Real spacing);

 private:
  template <int Dim>
  void computeIn();

  ExposedAreaForm form_;
  int dimension_;
  Real supportRadius_;
  Real areaFactor_;
  std::vector<ParticleCloud*> exposed_;
  std::vector<const ParticleCloud*> covering_;
  std::vector<std::vector<Real>> coveringVolume_;  // V of each covering cloud, every pass
  const Neighbourhood& neighbourhood_;
};

// g(p, q)/R_d of eq. (10).
inline Real exposureWeight(Real p, Real q) {
  if (!(p > Real(0))) return Real(0);
  if (p >= q) return Real(0.5) * q;
  const Real ratio = p / q;
  return p * ratio * ratio - Real(0.5) * p * ratio * ratio * ratio;
}

// sum_k g(1 - s_k, 1 - s_min)/R_d over the layers k = 0, 1, ... of a semi-infinite cubic
// lattice of spacing dx under a flat free surface, s_k summed with `kernel` (value(r)) over the
// half lattice and s_min = dx^d kernel.value(0): 1 / R_d for eq. (10)'s g to make the face's
// area (the calibration of eq. (11) here, of the surface energy in surface/).
template <int Dim, class Kernel>
Real flatSurfaceExposureSum(const Kernel& kernel, Real supportRadius, Real spacing) {
  const Real cell = std::pow(spacing, Dim);
  const int reach = static_cast<int>(std::ceil(supportRadius / spacing)) + 1;
  const int dyRange = Dim == 3 ? reach : 0;
  const Real q = Real(1) - cell * kernel.value(0);
  Real columnSum = 0;
  for (int layer = 0; layer <= reach; ++layer) {
    Real s = 0;
    for (int dz = -reach; dz <= reach; ++dz) {
      if (layer + dz < 0) continue;  // above the surface: no particle
      for (int dy = -dyRange; dy <= dyRange; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          s += cell * kernel.value(spacing * std::sqrt(Real(dx * dx + dy * dy + dz * dz)));
        }
      }
    }
    columnSum += exposureWeight(Real(1) - s, q);
  }
  return columnSum;
}

}  // namespace sphcast
