#pragma once

#include <cstddef>
#include <span>

#include "core/Real.h"
#include "particles/WendlandKernel.h"
#include "sph/RiemannSolver.h"

namespace sphcast {

// What the flow pass reads of a fluid cloud: plain views, so the pair functions stay plain.
struct FluidView {
  std::span<const Vector> position;
  std::span<const Vector> velocity;
  std::span<const Real> density;
  std::span<const Real> pressure;
  std::span<const Real> mass;
  std::span<const Real> viscosity;  // dynamic viscosity mu, Pa s
};

// What it reads of a wall cloud (static or moving rigid wall particles).
struct WallView {
  std::span<const Vector> position;
  std::span<const Vector> velocity;
  std::span<const Real> volume;
};

// What the pass writes: the rates of eqs. (1) and (2) for every fluid particle.
struct FlowRatesView {
  std::span<Real> densityRate;
  std::span<Vector> acceleration;
};

struct FlowConstants {
  Real soundSpeed;
  Vector gravity;
  Real viscosityRegularisation;  // eta^2 of the viscous term, 0.01 h^2
};

// Contributions of one fluid neighbour j to fluid particle i (paper eqs. (1), (2), (4)):
//   drho_i/dt += 2 rho_i (m_j / rho_j) (v_i - v*) . grad_i W_ij
//   dv_i/dt   += -2 m_j p* / (rho_i rho_j) grad_i W_ij
//              + 2 (d + 2) m_j (2 mu_i mu_j / (mu_i + mu_j)) / (rho_i rho_j)
//                          (v_ij . x_ij) / (|x_ij|^2 + eta^2) grad_i W_ij
// p*, v* come from the Interface (Riemann solver or arithmetic mean). The viscous term is the
// Monaghan-Cleary form with dynamic viscosity (DESIGN.md §4); its factor 2(d + 2) makes the pair
// sum reproduce nu Laplacian(v) for divergence-free flow (checked by the Poiseuille test).
template <int Dim, class Interface>
struct FluidPair {
  static void accumulate(const InterfaceSide& i, const InterfaceSide& j, Real massJ,
                         Real viscosityI, Real viscosityJ, const Vector& xij, Real r,
                         const Vector& gradW, const FlowConstants& constants, Real& densityRate,
                         Vector& acceleration) {
    const Vector towardsJ = r > Real(0) ? Vector(-xij / r) : Vector::Zero();
    const InterfaceState star = Interface{}(i, j, towardsJ, constants.soundSpeed);
    densityRate += Real(2) * i.density * (massJ / j.density) * (i.velocity - star.velocity).dot(gradW);
    const Real inverseDensities = Real(1) / (i.density * j.density);
    acceleration -= Real(2) * massJ * star.pressure * inverseDensities * gradW;
    const Real harmonicViscosity = Real(2) * viscosityI * viscosityJ / (viscosityI + viscosityJ);
    const Real viscousFactor = Real(2 * (Dim + 2)) * massJ * harmonicViscosity * inverseDensities *
                               (i.velocity - j.velocity).dot(xij) /
                               (r * r + constants.viscosityRegularisation);
    acceleration += viscousFactor * gradW;
  }
};

// A wall particle k seen from fluid particle i: a mirror state, as Zhang, Hu & Adams (2017) and
// Adami, Hu & Adams (2012) build it. Its pressure continues the fluid's hydrostatically,
// p_k = p_i + rho_i (g - a_wall) . (x_k - x_i), so a resting fluid feels exactly its weight
// carried by the wall; its velocity mirrors the fluid's, v_k = 2 v_wall - v_i, so any approach
// is resisted (impermeability through the Riemann solver) and the wall is no-slip for the
// viscous term. Its mass is rho_i V_k and its viscosity mu_i.
template <int Dim, class Interface>
inline void accumulateWallPair(const InterfaceSide& i, Real viscosityI, const Vector& wallVelocity,
                               Real wallVolume, const Vector& xik, Real r, const Vector& gradW,
                               const FlowConstants& constants, Real& densityRate,
                               Vector& acceleration) {
  const InterfaceSide mirror{i.density, i.pressure - i.density * constants.gravity.dot(xik),
                             Real(2) * wallVelocity - i.velocity};
  FluidPair<Dim, Interface>::accumulate(i, mirror, i.density * wallVolume, viscosityI, viscosityI,
                                        xik, r, gradW, constants, densityRate, acceleration);
}

}  // namespace sphcast
