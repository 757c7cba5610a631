#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <span>

#include "boundaries/WallCondition.h"
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
  Real viscosityRegularisation;  // eta^2 of the viscous term, 0.01 dx^2
  // The lowest pressure a wall pair carries (accumulateWallPair): 0, a wall only pushes, for a
  // fluid whose tension has no floor; the floor (cavitationPressure) for a melt that holds
  // suction, so that its wall pairs carry the tension its fluid pairs do.
  Real wallTensionFloor = 0;
};

// The viscous acceleration of eq. (2)'s second term from one neighbour, with dynamic viscosity
// and the harmonic mean mu_ij = 2 mu_i mu_j / (mu_i + mu_j), which keeps the shear stress
// continuous where mu jumps by decades across the solidification front (Cleary 1998).
// Two forms, selectable in system/sphSchemes:
//
// Cleary (Monaghan-Cleary; paper eq. (4), doc/physics.md §5): a central pair force, so angular
// momentum is conserved,
//   2 (d + 2) m_j mu_ij / (rho_i rho_j) (v_ij . x_ij) / (|x_ij|^2 + eta^2) grad_i W_ij,
// whose factor 2 (d + 2) makes the pair sum nu Laplacian(v) for divergence-free flow in the
// continuum limit. On a lattice with h = 3 dx it gives only 0.88 of the Laplacian (a fourth
// moment of the kernel, which a few dozen neighbours integrate poorly: 0.96 at h = 4 dx, 0.99 at
// h = 6 dx), so a Poiseuille flow runs some 13 % too fast at any resolution.
struct ClearyViscosity {
  static constexpr const char* name = "Cleary";
  template <int Dim>
  static Vector acceleration(Real massJ, Real harmonicViscosity, Real inverseDensities,
                             const Vector& shearVelocity, const Vector& xij, Real r,
                             const Vector& gradW, Real etaSquared) {
    return (Real(2 * (Dim + 2)) * massJ * harmonicViscosity * inverseDensities *
            shearVelocity.dot(xij) / (r * r + etaSquared)) *
           gradW;
  }
};

// Morris, Fox & Zhu (1997): the velocity difference itself, weighted by x_ij . grad W / r^2,
//   2 m_j mu_ij / (rho_i rho_j) (x_ij . grad_i W_ij) / (|x_ij|^2 + eta^2) v_ij.
// Its lattice sum needs only the kernel's second moment: 0.997 of the Laplacian at h = 3 dx.
// Not a central force (angular momentum is conserved only to discretisation error).
struct MorrisViscosity {
  static constexpr const char* name = "Morris";
  template <int Dim>
  static Vector acceleration(Real massJ, Real harmonicViscosity, Real inverseDensities,
                             const Vector& shearVelocity, const Vector& xij, Real r,
                             const Vector& gradW, Real etaSquared) {
    return (Real(2) * massJ * harmonicViscosity * inverseDensities * xij.dot(gradW) /
            (r * r + etaSquared)) *
           shearVelocity;
  }
};

// The viscous term left out of the rates: the flow steps it implicitly after the second kick
// (ImplicitViscosity.h, viscositySolver implicit or auto in system/sphSchemes).
struct ImplicitlySolvedViscosity {
  static constexpr const char* name = "implicit";
  template <int Dim>
  static Vector acceleration(Real, Real, Real, const Vector&, const Vector&, Real, const Vector&,
                             Real) {
    return Vector::Zero();
  }
};

// The interface of dualCriteria's viscous pass (WeaklyCompressibleFlow::advectionStep), which
// takes the viscous term alone: no pressure, and v* = v_i, so that the pair's pressure and
// continuity terms vanish and FluidPair and accumulateWallPair add only the Viscosity form's.
struct ViscousTermOnlyInterface {
  static constexpr const char* name = "viscous term only";
  static constexpr bool fluidTensionAtWalls = false;
  [[gnu::always_inline]] InterfaceState operator()(const InterfaceSide& left,
                                                   const InterfaceSide& /*right*/,
                                                   const Vector& /*towardsRight*/,
                                                   Real /*soundSpeed*/,
                                                   Real /*restingJump*/ = 0) const {
    return {Real(0), left.velocity};
  }
  [[gnu::always_inline]] InterfaceState withCompression(const InterfaceSide& left,
                                                        const InterfaceSide& right,
                                                        const Vector& towardsRight,
                                                        Real /*compression*/, Real soundSpeed,
                                                        Real restingJump = 0) const {
    return (*this)(left, right, towardsRight, soundSpeed, restingJump);
  }
};

// Contributions of one fluid neighbour j to fluid particle i (paper eqs. (1) and (2)):
//   drho_i/dt += 2 rho_i (m_j / rho_j) (v_i - v*) . grad_i W_ij
//   dv_i/dt   += -2 m_j p* / (rho_i rho_j) grad_i W_ij  + the Viscosity form's term
// with p*, v* from the Interface (Riemann solver or arithmetic mean).
template <int Dim, class Interface, class Viscosity>
struct FluidPair {
  // shearVelocity is v_ij of the viscous term: v_i - v_j between fluid particles, and the
  // wall's extrapolated difference for a wall particle (accumulateWallPair). wallCompression,
  // when given, is the U_L - U_R a wall pair's interface dissipates in place of the pair line's
  // (wallDissipation normalApproach, accumulateWallPair).
  // Forced inline, as the interfaces' functions: g++ 12 -O3 left them out of line in the rate
  // loop, a call per pair (perf on conicalMold, tests/benchmarks/README.md).
  [[gnu::always_inline]] static void accumulate(const InterfaceSide& i, const InterfaceSide& j,
                                                Real massJ, Real viscosityI, Real viscosityJ,
                                                const Vector& shearVelocity, const Vector& xij,
                                                Real r, const Vector& gradW,
                                                const FlowConstants& constants, Real& densityRate,
                                                Vector& acceleration,
                                                const Real* wallCompression = nullptr) {
    const Shared shared = interfaceOf(i, j, massJ, xij, r, constants, wallCompression);
    densityRate +=
        Real(2) * i.density * shared.volumeJ * (i.velocity - shared.star.velocity).dot(gradW);
    acceleration -= Real(2) * massJ * shared.star.pressure * shared.inverseDensities * gradW;
    // (an inviscid pair, both zero, has none: 0 / 0 would be NaN; the floor, not a branch, so
    // the pair loop stays as fast)
    const Real harmonicViscosity =
        Real(2) * viscosityI * viscosityJ /
        std::max(viscosityI + viscosityJ, std::numeric_limits<Real>::min());
    acceleration += Viscosity::template acceleration<Dim>(
        massJ, harmonicViscosity, shared.inverseDensities, shearVelocity, xij, r, gradW,
        constants.viscosityRegularisation);
  }

  // The density rate alone, the same bits as accumulate's: for frozen metal, which is held
  // (its acceleration would be thrown away) but whose density the melt moving against it, and
  // the pressure jumps, still change.
  [[gnu::always_inline]] static void accumulateDensityRate(
      const InterfaceSide& i, const InterfaceSide& j, Real massJ, const Vector& xij, Real r,
      const Vector& gradW, const FlowConstants& constants, Real& densityRate) {
    const Shared shared = interfaceOf(i, j, massJ, xij, r, constants, nullptr);
    densityRate +=
        Real(2) * i.density * shared.volumeJ * (i.velocity - shared.star.velocity).dot(gradW);
  }

 private:
  struct Shared {
    InterfaceState star;
    Real inverseDensities;  // 1 / (rho_i rho_j)
    Real volumeJ;           // m_j / rho_j
  };
  // wallCompression: U_L - U_R given by a wall pair; null for a fluid pair (along its line)
  [[gnu::always_inline]] static Shared interfaceOf(const InterfaceSide& i, const InterfaceSide& j,
                                                   Real massJ, const Vector& xij, Real r,
                                                   const FlowConstants& constants,
                                                   const Real* wallCompression) {
    // -e_ij = -x_ij / r, one division for the three components
    const Vector towardsJ = r > Real(0) ? Vector((Real(-1) / r) * xij) : Vector::Zero();
    // p_i - p_j of the fluid at rest: rho g . x_ij (hydrostatic)
    const Real restingJump = Real(0.5) * (i.density + j.density) * constants.gravity.dot(xij);
    const InterfaceState star =
        wallCompression ? Interface{}.withCompression(i, j, towardsJ, *wallCompression,
                                                      constants.soundSpeed, restingJump)
                        : Interface{}(i, j, towardsJ, constants.soundSpeed, restingJump);
    const Real inverseDensities = Real(1) / (i.density * j.density);
    // m_j / rho_j = m_j rho_i / (rho_i rho_j): the division is shared with the momentum terms
    return {star, inverseDensities, massJ * i.density * inverseDensities};
  }
};

// The extra terms of deltaSPH (Antuono, Colagrossi, Marrone & Molteni 2010, Comput. Phys.
// Commun. 181:532), added to the plain-mean pair of fluid particles i and j. Continuity gains the
// density diffusion
//   delta h c sum_j psi_ij . grad_i W_ij V_j,
//   psi_ij = 2 (rho_j - rho_i) x_ji / |x_ji|^2 - (<grad rho>_i^L + <grad rho>_j^L),
// whose renormalised-gradient term (KernelCorrection.h) cancels it on a hydrostatic density
// profile, and momentum the artificial viscosity
//   alpha h c rho_0 / rho_i sum_j pi_ij grad_i W_ij V_j,  pi_ij = v_ij . x_ij / |x_ij|^2.
// `diffusion` is delta h c, `viscousScale` alpha h c rho_0 / rho_i; |x_ij|^2 carries the eta^2
// of the viscous term.
struct DeltaSPHPair {
  static void accumulate(Real densityI, Real densityJ, const Vector& densityGradientI,
                         const Vector& densityGradientJ, Real volumeJ, const Vector& vij,
                         const Vector& xij, Real r, const Vector& gradW, Real diffusion,
                         Real viscousScale, const FlowConstants& constants, Real& densityRate,
                         Vector& acceleration) {
    const Real inverseSquare = Real(1) / (r * r + constants.viscosityRegularisation);
    const Vector psi = (Real(-2) * (densityJ - densityI) * inverseSquare) * xij -
                       (densityGradientI + densityGradientJ);
    densityRate += diffusion * volumeJ * psi.dot(gradW);
    acceleration += (viscousScale * volumeJ * vij.dot(xij) * inverseSquare) * gradW;
  }
};

// A wall particle k seen from fluid particle i: a mirror state (Adami, Hu & Adams 2012, J.
// Comput. Phys. 231:7057; with the Riemann solver as Zhang, Hu & Adams 2017). Its pressure p_k
// is extrapolated from the fluid around it (wallPressure), and its velocity mirrors the fluid's,
// v_k = 2 v_wall - v_i, so any approach is resisted through the interface pressure. Its mass is
// rho_k V_k, its viscosity mu_i.
// No-slip shear as Morris, Fox & Zhu (1997): the fluid's velocity relative to the wall is
// extended linearly through the wall surface, v_ik = beta (v_i - v_wall), beta = 1 + d_k / d_i,
// with d_k the wall particle's depth behind the surface and d_i the fluid particle's distance in
// front of it (at least half a spacing, which bounds beta for a particle touching the wall).
struct WallParticle {
  Vector velocity;
  Vector normal;  // unit, out of the wall into the fluid
  Real volume;
  Real depth;     // distance of the particle centre behind the wall surface
  Real pressure;  // extrapolated from the fluid (wallPressure)
  Real density;   // from the pressure through the equation of state
};

// The wall's condition (boundaries/WallCondition.h) sets the shear and the dissipation: slip
// takes the viscous shear away, the mirror velocity staying the full 2 v_wall - v_i (reflecting
// only its normal part, a free slip, left no resistance along pair lines towards a neighbouring
// face, and in crossDitchPress's pour a particle went 0.66 dx through the mold at 0.156 s);
// normalApproach has the interface's dissipation see only the fluid's approach to the wall,
// below.
template <int Dim, class Interface, class Viscosity>
[[gnu::always_inline]] inline void accumulateWallPair(
    const InterfaceSide& i, Real viscosityI, const WallParticle& k, Real halfSpacing,
    const Vector& xik, Real r, const Vector& gradW, const FlowConstants& constants,
    const WallCondition& condition, Real& densityRate, Vector& acceleration) {
  // A wall only pushes: with tension (p < 0) on either side the pair would pull a lone fluid
  // particle into the wall (measured: one of a 2D dam break's ended 0.11 dx inside the back
  // wall), so both sides enter with p >= 0 (riemann, standard).
  // A melt with a cavitation floor is the exception: its tension is bounded, and a particle in
  // tension beside a wall has its fluid pairs pull it off the wall with -p_i V / rho_i sum_walls
  // grad W unless the wall pairs carry the same tension. With the floor at -5,000 Pa, at c = 50
  // m/s crossDitchPress's pressed melt, there at the floor near the molds, stirred at up to
  // 1 m/s within 0.01 s of rest (doc/physics.md §10.4). So there both sides may go down to the
  // particle's own tension, never below: the wall pulls no harder than the melt holds.
  const Real lowest = std::max(std::min(i.pressure, Real(0)), constants.wallTensionFloor);
  // deltaSPH keeps the fluid's own p_i: its momentum term -(p_i + p_k) V_k / rho_i grad W sums
  // p_i grad W over the whole support, fluid and wall, which cancels for a uniform p_i; with
  // p_i clamped in the wall pairs only, a fluid particle in tension is pushed off the wall by
  // -p_i / rho_i sum_walls V_k grad W, expands further as it leaves (the mirror velocity doubles
  // the continuity term), and nothing but alpha damps it (the Riemann interface does; plain
  // means do not). Measured in the 2D dam break at a/dx = 20: density range [-98, +48] kg/m^3
  // about rho_0 with the clamp, [-2, +15] without, as the Riemann scheme's [-5, +10].
  const Real fluidPressure =
      Interface::fluidTensionAtWalls ? i.pressure : std::max(i.pressure, lowest);
  const InterfaceSide fluid{i.density, fluidPressure, i.velocity};
  const Vector relative = i.velocity - k.velocity;
  const InterfaceSide mirror{k.density, std::max(k.pressure, lowest),
                             Real(2) * k.velocity - i.velocity};
  const Real fluidDistance = std::max(xik.dot(k.normal) - k.depth, halfSpacing);
  const Real beta = Real(1) + k.depth / fluidDistance;
  // The interface's dissipation, U_L - U_R along the pair line:
  // - relativeVelocity (the default) takes it from the whole relative velocity. A particle
  //   sliding past the wall compresses the oblique pairs ahead of it, and the limiter's pressure
  //   there is a drag: the 2D dam break's front runs 8.6 / 5.8 / 3.7 % RMS behind the converged
  //   inviscid one at a/dx = 10 / 20 / 40 (doc/physics.md §7).
  // - normalApproach takes it from the normal part only, 2 ((v_i - v_wall) . n)(n . (-e_ik)),
  //   the compression a free-slip mirror would give (its sign does not depend on n's);
  //   continuity keeps the whole mirror velocity. The front is then 2.3 / 0.6 / 0.7 % RMS from
  //   the converged one. Zhang, Hu & Adams (2017) §3.3 and SPHinXsys take 2 (v_i - v_wall) . n
  //   for every pair: the same fronts, but a splash into a box's concave edge reached 20 %
  //   density deviation (12 % with this form, 10 % with relativeVelocity) and a particle went
  //   0.52 dx into a small lid's corner, whose corner particles carry a side face's normal
  //   (tests/integration/curvedWallsHoldTheMetal.sh, coolingModeWaitsForABodysRelease.sh).
  const bool normalApproach = condition.normalApproach();
  const Real wallCompression = normalApproach && r > Real(0)
                                   ? Real(-2) * relative.dot(k.normal) * k.normal.dot(xik) / r
                                   : Real(0);
  FluidPair<Dim, Interface, Viscosity>::accumulate(
      fluid, mirror, k.density * k.volume, viscosityI, viscosityI,
      condition.shearVelocity(beta, relative), xik, r, gradW, constants, densityRate, acceleration,
      normalApproach ? &wallCompression : nullptr);
}

// Adami et al. (2012) eq. (27), static wall: the pressure of wall particle w from its fluid
// neighbours f, p_w = (sum p_f W_wf + g . sum rho_f (x_w - x_f) W_wf) / sum W_wf, the
// hydrostatic continuation of the fluid's pressure into the wall; 0 without fluid neighbours.
struct WallPressureSums {
  Real weight = 0;
  Real pressure = 0;
  Vector densityMoment = Vector::Zero();

  void add(Real w, Real fluidPressure, Real fluidDensity, const Vector& xwf) {
    weight += w;
    pressure += fluidPressure * w;
    densityMoment += fluidDensity * w * xwf;
  }
  Real wallPressure(const Vector& gravity) const {
    return weight > Real(0) ? (pressure + gravity.dot(densityMoment)) / weight : Real(0);
  }
};

}  // namespace sphcast
