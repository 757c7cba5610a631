#pragma once

#include <vector>

#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The area A_i of each particle exposed to the outside (the air), eq. (11) of the paper
// (doc/physics.md §5.4), from its rate of granularity s_i, eq. (7):
//
//   s_i = sum_j V_j W(|x_i - x_j|, h)          over i itself and every particle of every
//                                              covering cloud (metal and molds alike: a face
//                                              against the mold is not exposed to the air)
//   A_i = R_A g(1 - s_i, 1 - s_min,i) V_i^((d-1)/d),   s_min,i = V_i W(0, h),
//   g(p, q) = p (p/q)^2 - (p/2) (p/q)^3 for 0 <= p < q, q/2 for p >= q, 0 for p < 0   (10)
//
// with V = mass / rho where a cloud has both, else its `volume` field. The paper takes R_A =
// R_d, the surface-tension constant (41.3 in 3D); with it a flat surface of a cubic lattice at
// h = 3 dx would count 2.4 times its area (doc/physics.md §5.4). Here R_A is calibrated on its
// own, by calibratedAreaFactor(): the sum of A_i over a column of a semi-infinite cubic lattice
// under a flat free surface is exactly the column's cross-section dx^(d-1). Edges, corners and
// curved surfaces are then approximations (measured in tests/unit/sph/ExposedAreaTest.cpp).
//
// Writes the field `exposedArea` (m^2 in 3D, m in 2D) of each exposed cloud, and `granularity`
// (s_i), shared by every model that needs them (atmosphere, radiation; surface tension next).
class ExposedArea {
 public:
  // exposed: the clouds whose A_i is wanted; covering: every cloud whose particles cover
  // (include the exposed ones). Registers the pairs in the neighbourhood. spacing: the lattice
  // spacing dx the calibration assumes (the exposed clouds' `spacing` attribute).
  ExposedArea(int dimension, Real supportRadius, Real spacing,
              std::vector<ParticleCloud*> exposed, std::vector<const ParticleCloud*> covering,
              Neighbourhood& neighbourhood);

  // s_i and A_i of every exposed particle, for the neighbourhood's last update.
  void compute();

  Real areaFactor() const { return areaFactor_; }

  // R_A for this dimension and h/dx (see the class comment).
  static Real calibratedAreaFactor(int dimension, Real supportRadius, Real spacing);

 private:
  template <int Dim>
  void computeIn();

  int dimension_;
  Real supportRadius_;
  Real areaFactor_;
  std::vector<ParticleCloud*> exposed_;
  std::vector<const ParticleCloud*> covering_;
  const Neighbourhood& neighbourhood_;
};

// g(p, q)/R_d of eq. (10).
inline Real exposureWeight(Real p, Real q) {
  if (!(p > Real(0))) return Real(0);
  if (p >= q) return Real(0.5) * q;
  const Real ratio = p / q;
  return p * ratio * ratio - Real(0.5) * p * ratio * ratio * ratio;
}

// V_i of every particle of a cloud: mass / rho where it has both, else its `volume`.
std::vector<Real> particleVolumes(const ParticleCloud& cloud);

}  // namespace sphcast
