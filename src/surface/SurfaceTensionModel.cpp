// The registration of the surface-tension models: the one place that maps the names of
// constant/physicsModels to constructors.

#include "surface/SurfaceTensionModel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "sph/ParticleVolumes.h"
#include "surface/ContinuumSurfaceForce.h"
#include "surface/SurfaceEnergyTension.h"

namespace sphcast {

void requireTemperatureFor(const TemperatureTable& sigma, const ParticleCloud& fluid) {
  if (sigma.isConstant() || fluid.hasScalarField(field::T)) return;
  throw DictionaryError(sigma.location(), sigma.description() + " is a table in T, but cloud '" +
                                              fluid.name() +
                                              "' has no T (set it with setCastFields)");
}

void tensionAtParticles(const TemperatureTable& sigma, const ParticleCloud& fluid,
                        std::vector<Real>& tension) {
  const std::size_t n = fluid.size();
  tension.resize(n);
  if (sigma.isConstant()) {
    std::fill(tension.begin(), tension.end(), static_cast<Real>(sigma(0)));
    return;
  }
  const auto& temperature = fluid.scalarField(field::T);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    tension[i] = static_cast<Real>(sigma(static_cast<double>(temperature[i])));
  }
}

double capillaryStepLimit(const TemperatureTable& sigma, const std::vector<Real>& lastTension,
                          const ParticleCloud& fluid, double spacing) {
  double largest = 0;
  if (sigma.isConstant()) {
    largest = sigma(0);
  } else if (lastTension.size() == fluid.size() && !lastTension.empty()) {
    largest = static_cast<double>(*std::max_element(lastTension.begin(), lastTension.end()));
  } else {
    for (const Real t : fluid.scalarField(field::T)) largest = std::max(largest, sigma(t));
  }
  const auto& rho = fluid.scalarField(field::rho);
  if (!(largest > 0) || rho.empty()) return std::numeric_limits<double>::max();
  const double lightest = *std::min_element(rho.begin(), rho.end());
  return 0.25 *
         std::sqrt(lightest * spacing * spacing * spacing / (2 * std::numbers::pi * largest));
}

const std::vector<std::vector<Real>>& WallVolumes::of(
    const std::vector<const ParticleCloud*>& walls, int dimension) {
  volumes_.resize(walls.size());
  layouts_.resize(walls.size(), ~std::uint64_t(0));
  for (std::size_t w = 0; w < walls.size(); ++w) {
    if (layouts_[w] == walls[w]->layoutVersion() && volumes_[w].size() == walls[w]->size()) {
      continue;
    }
    volumes_[w] = particleVolumes(*walls[w], dimension);
    layouts_[w] = walls[w]->layoutVersion();
  }
  return volumes_;
}

SurfaceTensionModels& surfaceTensionModels() {
  static SurfaceTensionModels models = [] {
    SurfaceTensionModels registry("surface-tension model");
    registry.add<ContinuumSurfaceForce>("continuumSurfaceForce");  // the default
    registry.add<SurfaceEnergyTension>("surfaceEnergy");
    return registry;
  }();
  return models;
}

}  // namespace sphcast
