#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/Registry.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"
#include "sph/FluidForceModel.h"
#include "surface/SurfaceTensionSettings.h"

namespace sphcast {

// A surface-tension model: a force on the flow's fluid that also says what it is in the log.
class SurfaceTensionModel : public FluidForceModel {
 public:
  // What the model is and its constants, one or more lines for the log (no trailing newline).
  virtual std::string summary(double soundSpeed) const = 0;
  // A warning about the settings, for the log; empty: none.
  virtual std::string settingsWarning(double soundSpeed) const {
    (void)soundSpeed;
    return {};
  }
};

// What every model needs of sigma = Gamma_g(T): the fluid has T when sigma is a table (an error
// naming the table's file and line otherwise), and sigma at every particle's T now.
void requireTemperatureFor(const TemperatureTable& sigma, const ParticleCloud& fluid);
void tensionAtParticles(const TemperatureTable& sigma, const ParticleCloud& fluid,
                        std::vector<Real>& tension);

// The capillary step limit 0.25 sqrt(rho_min dx^3 / (2 pi sigma_max)) (Brackbill, Kothe &
// Zemach 1992) of the continuum surface force and the pair force: sigma_max from the last
// pass's tensions at the particles (`lastTension`, when it has one per particle), else from the
// table over the fluid's T; no limit where sigma is 0 or the fluid is empty.
double capillaryStepLimit(const TemperatureTable& sigma, const std::vector<Real>& lastTension,
                          const ParticleCloud& fluid, double spacing);

// The walls' particle volumes (particleVolumes), kept between passes and taken again when a
// wall's particles were added, removed or reordered (a decomposed run's re-balance, a moving
// mold's migration between ranks): a cache by each wall's layoutVersion().
class WallVolumes {
 public:
  // The volumes of walls[w], up to date.
  const std::vector<std::vector<Real>>& of(const std::vector<const ParticleCloud*>& walls,
                                           int dimension);

 private:
  std::vector<std::vector<Real>> volumes_;
  std::vector<std::uint64_t> layouts_;
};

// The models by the names constant/physicsModels gives them (surfaceTension { model NAME; }),
// each built on the fluid among the walls, in the flow's neighbourhood; registered in
// SurfaceTensionModel.cpp, the first the default.
using SurfaceTensionModels =
    Registry<SurfaceTensionModel, const SurfaceTensionSettings&, ParticleCloud&,
             std::vector<const ParticleCloud*>, Neighbourhood&>;
SurfaceTensionModels& surfaceTensionModels();

}  // namespace sphcast
