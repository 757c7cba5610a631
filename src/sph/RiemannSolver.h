#pragma once

#include <algorithm>

#include "core/Real.h"

namespace sphcast {

// The state of one side of a particle pair, projected on the line between them: the interface
// problem is one-dimensional along the unit vector `towardsRight` (from the left particle i to
// the right particle j, i.e. -e_ij with e_ij = x_ij / |x_ij|).
struct InterfaceSide {
  Real density;
  Real pressure;
  Vector velocity;
};

// What the pair sees at the interface: p_ij and v_ij of the paper's eqs. (1) and (2).
struct InterfaceState {
  Real pressure;
  Vector velocity;
};

// Standard SPH (the paper's comparison, Monaghan 1992): arithmetic means, no dissipation.
struct ArithmeticMeanInterface {
  static constexpr const char* name = "standard";
  // whether a wall pair takes the fluid particle's own pressure as it is, tension included
  // (accumulateWallPair says why deltaSPH does and the others do not)
  static constexpr bool fluidTensionAtWalls = false;
  [[gnu::always_inline]] InterfaceState operator()(const InterfaceSide& left,
                                                   const InterfaceSide& right,
                                                   const Vector& towardsRight, Real soundSpeed,
                                                   Real restingJump = 0) const {
    return withCompression(left, right, towardsRight, 0, soundSpeed, restingJump);
  }
  // the same with the compression given (no dissipation here to take it)
  [[gnu::always_inline]] InterfaceState withCompression(const InterfaceSide& left,
                                                        const InterfaceSide& right,
                                                        const Vector& /*towardsRight*/,
                                                        Real /*compression*/, Real /*soundSpeed*/,
                                                        Real /*restingJump*/ = 0) const {
    return {Real(0.5) * (left.pressure + right.pressure),
            Real(0.5) * (left.velocity + right.velocity)};
  }
};

// deltaSPH's pair (Antuono et al. 2010): the plain means of standard SPH, whose wall pairs keep
// the fluid particle's tension (FlowRates.h, accumulateWallPair); the density diffusion and
// artificial viscosity are added by the flow pass (DeltaSPHPair).
struct DeltaSPHInterface : ArithmeticMeanInterface {
  static constexpr const char* name = "deltaSPH";
  static constexpr bool fluidTensionAtWalls = true;
};

// The linearised (acoustic) Riemann solver of Parshikov & Medin (2002) with the low-dissipation
// limiter of Zhang, Hu & Adams (2017, J. Comput. Phys. 335:605): along the pair line,
//   U* = U_mean + (P_L - P_R) / (2 rho_mean c)
//   P* = P_mean + beta rho_mean c (U_L - U_R) / 2,   beta = min(eta max(U_L - U_R, 0) / c, 1)
// so pressure dissipation acts only where the pair compresses, in proportion to how fast, and
// the tangential velocity is the plain mean. eta = 3 as in Zhang et al.
// Evaluated with one division per pair: beta rho_mean c = rho_mean min(eta max(U_L - U_R, 0), c)
// (c cancels), and v* = v_mean + (U* - U_mean) e = v_mean + (P_L - P_R) / (2 rho_mean c) e.
// restingJump is the part of P_L - P_R that a fluid at rest has (hydrostatic, rho g . x_LR):
// U* takes only the rest, so a column at rest has v* = 0 and keeps its density. Without it
// the jump term diffuses the hydrostatic pressure wherever the support is not full, which
// raised the density at the free surface and walls of a tank at rest steadily.
struct AcousticRiemannInterface {
  static constexpr const char* name = "riemann";
  static constexpr bool fluidTensionAtWalls = false;
  static constexpr Real limiterSlope = 3;

  [[gnu::always_inline]] InterfaceState operator()(const InterfaceSide& left,
                                                   const InterfaceSide& right,
                                                   const Vector& towardsRight, Real soundSpeed,
                                                   Real restingJump = 0) const {
    // U_L - U_R, > 0 when the pair closes in
    const Real compression = left.velocity.dot(towardsRight) - right.velocity.dot(towardsRight);
    return withCompression(left, right, towardsRight, compression, soundSpeed, restingJump);
  }

  // The same with U_L - U_R given: a wall pair with wallDissipation normalApproach gives the
  // compression of the normal part of the relative velocity only (FlowRates.h,
  // accumulateWallPair).
  [[gnu::always_inline]] InterfaceState withCompression(const InterfaceSide& left,
                                                        const InterfaceSide& right,
                                                        const Vector& towardsRight,
                                                        Real compression, Real soundSpeed,
                                                        Real restingJump = 0) const {
    const Real meanDensity = Real(0.5) * (left.density + right.density);
    // beta rho_mean c, with beta = min(eta max(U_L - U_R, 0) / c, 1)
    const Real limitedImpedance =
        meanDensity * std::min(limiterSlope * std::max(compression, Real(0)), soundSpeed);
    const Real pressure =
        Real(0.5) * (left.pressure + right.pressure) + Real(0.5) * limitedImpedance * compression;
    // U* - U_mean
    const Real normalVelocityJump =
        Real(0.5) * (left.pressure - right.pressure - restingJump) / (meanDensity * soundSpeed);
    const Vector meanVelocity = Real(0.5) * (left.velocity + right.velocity);
    return {pressure, meanVelocity + normalVelocityJump * towardsRight};
  }
};

}  // namespace sphcast
