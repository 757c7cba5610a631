#pragma once

#include <string>
#include <vector>

#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"
#include "surface/SurfaceTensionModel.h"

namespace sphcast {

// Surface tension set by sigma, with the contact angle theta at the walls, from a short-range
// pair force between particles (Tartakovsky & Panchenko 2016, J. Comput. Phys. 305:1119; for a
// free surface with one phase Nair & Poeschel 2018, Chem. Eng. Sci. 176:192):
//
//   a_i = (1 / rho_i) sum_j s_ij V_j [psi(r_ij) x_ij / r_ij - 2 (P / s) grad_i W_ij],
//   psi(r) = cos(3 pi r / (2 h))                                                         (PF)
//
// over the fluid (s_ij = (s_i + s_j) / 2) and the walls (s_iw = s_i (1 + cos theta) / 2), r < h.
// psi repels inside h/3 (a spacing at h = 3 dx: the nearest neighbours sit where it changes
// sign) and attracts beyond. Its virial pulls the bulk together with the pressure p_c < 0; the
// second term is the SPH force of the uniform pressure P = -p_c where the attraction is missing
// (a surface, a wall that attracts less), so the bulk's pressure stays the flow's own (0 under a
// flat surface). m_i a_i is antisymmetric in i and j: momentum is kept. The strength s_i follows
// from sigma(T_i) by Kirkwood and Buff: the work per area to part the lattice of spacing dx
// along a plane, of both terms together (PairwiseForce.cpp), no fit. The contact angle is
// Young's: a wall attracting with (1 + cos theta) / 2 of the liquid's strength has
// Gamma_s - Gamma_sl = sigma cos theta; at 180 degrees the wall does not attract at all.
//
// Measured, and not the default (doc/validation.md §2.4): P cancels about 60 % of the
// cohesion's tension, and the rest follows the arrangement: a settled drop's pressure is 4 (30
// across) to 9 (60 across) times Laplace's jump in 2D; the n = 2 mode of a 2D drop gives no
// period; sessile drops read 84.6 / 88.1 / 97.5 / 116.7 / 141.7 degrees at 60 / 90 / 120 / 150 /
// 180 set (the particles lock into place and the contact line hardly moves).
//
// Reads the fluid's positions, mass, rho, T (when sigma is a table); the walls' positions and
// volumes. Adds to `acceleration`.
class PairwiseForce : public SurfaceTensionModel {
 public:
  PairwiseForce(SurfaceTensionSettings settings, ParticleCloud& fluid,
                std::vector<const ParticleCloud*> walls, Neighbourhood& neighbourhood);

  std::string limitName() const override { return "capillary"; }
  std::string summary(double soundSpeed) const override;
  void addAcceleration() override;
  // 0.25 sqrt(rho_min dx^3 / (2 pi sigma_max)) (Brackbill, Kothe & Zemach 1992), as the
  // continuum surface force.
  double stableDeltaT() const override;
  double seconds() const override { return seconds_; }

  // The pair function's constants per unit strength s (PairwiseForce.cpp: lattice sums)
  struct PairConstants {
    double cohesionPressure = 0;  // p_c / s, the cohesion's virial pressure (negative)
    double heldPressure = 0;      // P / s, the uniform pressure that cancels it
    double tension = 0;           // sigma / s (Kirkwood-Buff, with the held pressure)
    double strengthPerTension() const { return 1 / tension; }
  };
  const PairConstants& constants() const { return constants_; }

 private:
  template <int Dim>
  void addForce();

  SurfaceTensionSettings settings_;
  Real wallShare_;  // (1 + cos theta) / 2
  PairConstants constants_;
  ParticleCloud& fluid_;
  std::vector<const ParticleCloud*> walls_;
  WallVolumes wallVolumes_;
  Neighbourhood& neighbourhood_;
  std::vector<Real> volume_, tension_;
  double seconds_ = 0;
};

}  // namespace sphcast
