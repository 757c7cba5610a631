#pragma once

#include <optional>

#include "core/Real.h"
#include "materials/TemperatureTable.h"

namespace sphcast {

// The constants of the surface tension, read by the models (ContinuumSurfaceForce.h,
// SurfaceEnergyTension.h, PairwiseForce.h); each model's own are marked.
struct SurfaceTensionSettings {
  int dimension = 3;
  Real supportRadius = 0;  // h
  Real spacing = 0;        // dx, for the capillary step limit and the calibrated R_d
  // surfaceEnergy: R_d of eq. (10); 0: calibrated for the dimension and h/dx
  // (calibratedEnergyFactor)
  Real energyFactor = 0;
  // sigma = Gamma_g(T), N/m: the fluid's material table, or a constant; at T where it is 0
  // (the solid rows of AC4CH) a particle carries no surface tension.
  std::optional<TemperatureTable> gasTension;
  // The wall: cos(theta) of the contact angle (Gamma_s = -cos(theta) Gamma_g(T)), or Gamma_s
  // itself (N/m, surfaceEnergy only), one of them; 180 degrees by default (Gamma_s = Gamma_g:
  // the wall is like air).
  std::optional<Real> cosContactAngle;
  std::optional<Real> solidTension;
  // continuumSurfaceForce: in a gap between facing walls narrower than 2 h, whose meniscus the
  // kernel cannot resolve, the surface takes Young-Laplace's curvature -2 cos(theta) / w
  // (`gapMeniscus on`; off by default: ContinuumSurfaceForce.h)
  bool gapMeniscus = false;
  // surfaceEnergy: eps of eq. (9), m; 0: h
  Real wallSmoothing = 0;
  // surfaceEnergy: r0 of the granularity kernel (GranularityKernel), in spacings
  Real coreRadius = 1;
  // surfaceEnergy: the energy depends on the densities too (V_j = m_j / rho_j in s_i, q_i,
  // V_i^(1-1/d)); the continuity equation changes them as the particles move, and that part of
  // -dE/dt acts as a pressure p_j = rho_j^2 Psi_j / m_j, Psi_j = dE/drho_j. Without it (a
  // study's setting, no dictionary key: SurfaceForceTest checks -dE/dx with it off) the force is -dE/dx at fixed densities alone, and the surface layer's
  // crowding is resisted by nothing in the energy: the static drop's pressure came out 10
  // times Laplace's.
  bool densityCoupling = true;
  // surfaceEnergy: skip the pairs that carry no force (both ends inside the fluid, where
  // g = 0); off only to measure what it saves.
  bool surfaceParticlesOnly = true;
};

}  // namespace sphcast
