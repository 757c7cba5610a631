#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "particles/FieldNames.h"
#include "thermal/HeatTransferModel.h"

namespace sphcast {

// The pass that atmosphere (15) and radiation (16) share: each particle of a cloud with a
// coefficient loses heat through its exposed area A_i (field exposedArea) at the rate
// coefficient * A_i * flux(T_i) W. Adds -that / m_i to energyRate; returns the power of each
// cloud (summed in particle order, so it does not depend on the thread count); held particles
// lose nothing (their T is the boundary's). Serial: one multiply-add per surface particle, far
// below a pair pass. A decomposed run's owned particles only (its halo's A_i lack neighbours,
// and its u is its owners').
template <class Flux>
std::vector<double> addSurfaceLoss(const HeatTransferContext& context,
                                   const std::vector<double>& coefficient, Flux flux) {
  std::vector<double> total(context.clouds.size(), 0.0);
  for (std::size_t c = 0; c < context.clouds.size(); ++c) {
    const HeatCloud& heat = context.clouds[c];
    if (coefficient[c] == 0 || heat.fixedTemperature) continue;
    ParticleCloud& cloud = *heat.cloud;
    const auto& area = cloud.scalarField(field::exposedArea);
    const auto& T = cloud.scalarField(field::T);
    const auto& mass = cloud.scalarField(field::mass);
    auto& energyRate = cloud.scalarField(field::energyRate);
    const Real* held = heldTemperatures(heat);
    for (std::size_t i = 0; i < cloud.ownedSize(); ++i) {
      if (area[i] == 0 || (held && held[i] > 0)) continue;
      const double power = coefficient[c] * area[i] * flux(static_cast<double>(T[i]));
      energyRate[i] -= static_cast<Real>(power / mass[i]);
      total[c] += power;
    }
  }
  return total;
}

// The step limit of such a loss for the current state: no particle's temperature relaxes by
// more than a quarter of its difference in a step, 0.25 m_i c_min / (coefficient A_i
// dflux/dT(T_i)) (c_min the smallest du/dT of the material's table), over the owned particles
// (EnergyEquation takes the smallest over the ranks).
template <class FluxSlope>
double surfaceLossStableDeltaT(const HeatTransferContext& context,
                               const std::vector<double>& coefficient, FluxSlope fluxSlope) {
  double stable = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < context.clouds.size(); ++c) {
    const HeatCloud& heat = context.clouds[c];
    if (coefficient[c] == 0 || heat.fixedTemperature) continue;
    const ParticleCloud& cloud = *heat.cloud;
    const auto& area = cloud.scalarField(field::exposedArea);
    const auto& T = cloud.scalarField(field::T);
    const auto& mass = cloud.scalarField(field::mass);
    const double heatCapacity = heat.material->internalEnergy->smallestSpecificHeat();
    const Real* held = heldTemperatures(heat);
    for (std::size_t i = 0; i < cloud.ownedSize(); ++i) {
      if (held && held[i] > 0) continue;
      const double slope = coefficient[c] * area[i] * fluxSlope(static_cast<double>(T[i]));
      if (slope > 0) stable = std::min(stable, 0.25 * mass[i] * heatCapacity / slope);
    }
  }
  return stable;
}

}  // namespace sphcast
