#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "materials/TemperatureTable.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"
#include "particles/WendlandKernel.h"
#include "surface/SurfaceTensionModel.h"

namespace sphcast {

// Surface tension from the surface energy (paper §3, eqs. (6)-(12); doc/physics.md §10.1):
//
//   s_i   = sum_j V_j W_s(|x_i - x_j|)      over the fluid only, i included                (7)
//   E_s,p = sum_i R_d g(1 - s_i, 1 - s_min,i) Gamma_i(l_i) V_i^(1 - 1/d)                   (8)
//   Gamma_i = Gamma_g chi(l_i, eps) + Gamma_s (1 - chi(l_i, eps))                          (9)
//   f_s,k = -dE_s,p / dx_k                                                                 (12)
//
// with g of eq. (10) (sph/ExposedArea.h: exposureWeight), s_min,i = V_i W_s(0), V = m / rho,
// and l_i the distance of particle i from the wall surface (particles/WallSurfaceDistance.h,
// from the wall particles' normals and depths). The sum for s counts the fluid alone: a face
// against the mold is a surface too, one that costs Gamma_s instead of Gamma_g; that is what
// chi does. (The heat's exposed area counts the molds as covering: a face on the mold loses no
// heat to the air.) The force is the exact gradient, s_j depending on x_k for every neighbour:
// with phi_i = dE/ds_i = -R_d g_p(1 - s_i, 1 - s_min,i) Gamma_i V_i^(1 - 1/d),
//
//   f_s,k = -sum_j (phi_k V_j + phi_j V_k) grad_k W_kj  -  R_d g_k V_k^(1 - 1/d) dGamma/dl n_k
//
// whose pair part is antisymmetric (momentum conserved pair by pair) and whose last part is the
// wall's pull (n_k: the wall normal at k, the gradient of l). Gamma_g(T) is a constant of the
// positions; V = m / rho is one too, but rho changes by the continuity equation as the particles
// move, and E with it: that part, Psi_j = dE/drho_j, enters as the pressure
// p_j = rho_j^2 Psi_j / m_j of the momentum equation (densityCoupling),
//
//   f_k += -sum_j (Psi_k m_j + Psi_j m_k) grad_k W_kj          (W: the flow's kernel)
//
// so that the surface layer's crowding, which lowers s-energy, costs what it changes in the
// densities. Without it the static 2D drop's pressure was 4.5 to 10 times Laplace's; with it,
// 0.47 to 1.14 times with the lattice face's R_d (doc/validation.md §2). tests/unit/surface checks
// -dE/dx (at fixed rho) and Psi against finite differences of energy().
//
// W_s is not the paper's W (GranularityKernel below; doc/physics.md §10.1): with W the energy
// falls when two surface particles merge, the pair attraction has the shape of their pressure
// repulsion, and the surface clumps in pairs (a 2D drop at rest goes non-finite within 10^5
// steps). W_s pushes pairs closer than 0.7 dx apart, and is normalised so that s = 1 inside a
// fluid on the lattice.
//
// Reads the fluid's positions, mass, rho, T (when Gamma_g is a table); the walls' normal and
// wallDistance (as the flow does). Adds to `acceleration`; writes the field `surfaceEnergy`
// (R_d g Gamma V^(1-1/d) per particle, J in 3D, J/m in 2D: where the surface is, for ParaView).
class SurfaceEnergyTension : public SurfaceTensionModel {
 public:
  // Registers the fluid-fluid and fluid-wall pairs in the neighbourhood the flow searches.
  SurfaceEnergyTension(SurfaceTensionSettings settings, ParticleCloud& fluid,
                       std::vector<const ParticleCloud*> walls, Neighbourhood& neighbourhood);

  std::string limitName() const override { return "capillary"; }
  std::string summary(double soundSpeed) const override;
  // When the surface layer's compression R_d Gamma / (rho c^2 dx) passes 3 %.
  std::string settingsWarning(double soundSpeed) const override;
  void addAcceleration() override;
  // The capillary limit 0.25 sqrt(rho_min dx^3 / (2 pi Gamma_max)) (Brackbill, Kothe & Zemach
  // 1992): the step must resolve the fastest capillary wave the particles carry.
  double stableDeltaT() const override;
  double seconds() const override { return seconds_; }
  // R_d Gamma_max / (rho_min c^2 dx): the surface layer is pulled inwards by about
  // R_d Gamma / dx, which only the equation of state resists, so its density rises by that
  // fraction (doc/physics.md §10.1: R_d was calibrated at 0.3 to 3 %).
  double surfaceCompression(double soundSpeed) const;

  // E_s,p of eq. (8) at the neighbourhood's last update, summed in particle order.
  double energy();
  Real energyFactor() const { return energyFactor_; }
  // Psi_j = dE/drho_j of every particle, at the positions of the last energy() (for the tests).
  std::vector<Real> densityDerivative();
  // Gamma_s at temperature T (N/m).
  Real solidTension(Real gasTension) const;

  // R_d that makes the energy of a flat free surface of a cubic lattice Gamma_g per unit area:
  // R_d = 1 / sum_k g_k / R_d down a column of the lattice under the surface. At h = 3 dx with
  // the default core: 32.3 in 2D, 50.7 in 3D.
  static Real latticeEnergyFactor(int dimension, Real supportRadius, Real spacing, Real coreRadius);
  // The mechanical tension of a relaxed free surface, per Gamma_g, with R_d the lattice's: the
  // work of stretching it per unit of new area (the particles stay: a surface of particles
  // stretches, it does not draw new ones from the bulk). Measured, not derived
  // (doc/physics.md §10.1: relaxed periodic slabs and drops at h = 3 dx, core dx; used at
  // other h/dx and cores too, where nobody has measured it).
  static Real relaxedTensionRatio(int dimension);
  // R_d that gives a relaxed surface the mechanical tension Gamma_g: latticeEnergyFactor /
  // relaxedTensionRatio. At h = 3 dx with the default core: 62.1 in 2D, 80.5 in 3D; the paper's
  // R_2 = 41.4 and R_3 = 41.3 are 67 % and 51 % of them.
  static Real calibratedEnergyFactor(int dimension, Real supportRadius, Real spacing,
                                     Real coreRadius);

 private:
  template <int Dim>
  void computeEnergy();
  template <int Dim>
  void addForces();
  template <int Dim>
  void computeDensityDerivative();
  void updateGasTension();
  double largestTension(const std::vector<Real>& gasTension) const;  // of Gamma_g and |Gamma_s|
  // of the last pass, or before any (a restart) at the particles' T now
  double currentLargestTension() const;
  double lightestDensity() const;  // of the fluid's rho now

  SurfaceTensionSettings settings_;
  Real energyFactor_;
  Real wallSmoothing_;
  ParticleCloud& fluid_;
  std::vector<const ParticleCloud*> walls_;
  Neighbourhood& neighbourhood_;
  // per particle, from the last pass
  std::vector<Real> volume_;
  std::vector<Real> gasTension_;
  std::vector<Real> energyDerivative_;           // phi_i = dE/ds_i
  std::vector<Vector> wallForce_;                // -R_d g V^(1-1/d) dGamma/dl n
  std::vector<Real> densityDerivative_;          // Psi_j = dE/drho_j (densityCoupling)
  std::vector<Real> explicitDensityDerivative_;  // rho_j times its part through q_j, V_j^(1-1/d)
  double largestTension_ = -1;                   // of the last pass (-1: none yet)
  double seconds_ = 0;
};

// The kernel of s_i: W beyond a core radius r0; within it the slope falls linearly from W'(r0)
// at r0 to zero at r_m = 0.7 r0 and turns positive below: s falls when two particles come
// closer than r_m, and the energy pushes them apart (see the class comment: without that the
// surface particles clump in pairs). All divided by the kernel's sum over a cubic lattice of
// spacing dx, so that s = 1 inside a fluid on the lattice.
template <int Dim>
class GranularityKernel {
 public:
  static constexpr Real repulsionFraction = Real(0.7);  // r_m / r0

  GranularityKernel(Real supportRadius, Real spacing, Real core)
      : kernel_(supportRadius),
        core_(core),
        coreValue_(kernel_.value(core)),
        coreSlope_(kernel_.derivative(core)) {
    const Real cell = std::pow(spacing, Dim);
    const int reach = static_cast<int>(std::ceil(supportRadius / spacing));
    const int zReach = Dim == 3 ? reach : 0;
    Real sum = 0;
    for (int k = -zReach; k <= zReach; ++k) {
      for (int j = -reach; j <= reach; ++j) {
        for (int i = -reach; i <= reach; ++i) {
          sum += cell * rawValue(spacing * std::sqrt(Real(i * i + j * j + k * k)));
        }
      }
    }
    scale_ = Real(1) / sum;
  }
  Real value(Real r) const { return scale_ * rawValue(r); }
  Real derivativeOverDistance(Real r) const {
    if (r >= core_) return scale_ * kernel_.derivativeOverDistance(r);
    if (!(r > 0)) return 0;  // coincident particles: no direction
    const Real t = r / core_;
    return scale_ * coreSlope_ * (t - repulsionFraction) / ((Real(1) - repulsionFraction) * r);
  }

 private:
  Real rawValue(Real r) const {
    if (r >= core_) return kernel_.value(r);
    const Real t = r / core_;
    const Real m = repulsionFraction;
    return coreValue_ -
           coreSlope_ * core_ / (Real(1) - m) * (Real(0.5) * (Real(1) - t * t) - m * (Real(1) - t));
  }
  WendlandC2Kernel<Dim> kernel_;
  Real core_, coreValue_, coreSlope_;
  Real scale_ = 1;
};

// dg/dp / R_d of eq. (10): 1 for p >= q, 3 (p/q)^2 - 2 (p/q)^3 for 0 <= p < q, 0 below; g is
// continuously differentiable, so the force is continuous.
inline Real exposureWeightSlope(Real p, Real q) {
  if (!(p > Real(0))) return Real(0);
  if (p >= q) return Real(1);
  const Real ratio = p / q;
  return ratio * ratio * (Real(3) - Real(2) * ratio);
}

// dg/dq / R_d of eq. (10): -1/2 for p >= q, (p/q)^3 (3/2 p/q - 2) for 0 <= p < q, 0 below.
inline Real exposureWeightSlopeInQ(Real p, Real q) {
  if (!(p > Real(0))) return Real(0);
  if (p >= q) return Real(-0.5);
  const Real ratio = p / q;
  return ratio * ratio * ratio * (Real(1.5) * ratio - Real(2));
}

// chi(l, eps) of eq. (9) and its derivative in l.
inline Real wallIndicator(Real l, Real eps) {
  if (!(l > Real(0))) return Real(0);
  if (l >= eps) return Real(1);
  const Real ratio = l / eps;
  return ratio * ratio * (Real(3) - Real(2) * ratio);
}
inline Real wallIndicatorSlope(Real l, Real eps) {
  if (!(l > Real(0)) || l >= eps) return Real(0);
  const Real ratio = l / eps;
  return Real(6) * ratio * (Real(1) - ratio) / eps;
}

}  // namespace sphcast
