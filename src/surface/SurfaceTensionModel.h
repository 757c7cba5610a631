#pragma once

#include <memory>
#include <string>
#include <vector>

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

// The models by the names constant/physicsModels gives them (surfaceTension { model NAME; }),
// in the order the error for an unknown name lists them; the first is the default.
const std::vector<std::string>& surfaceTensionModelNames();

// Builds the model `name` (one of surfaceTensionModelNames()) on the fluid among the walls, in
// the flow's neighbourhood.
std::unique_ptr<SurfaceTensionModel> makeSurfaceTensionModel(
    const std::string& name, const SurfaceTensionSettings& settings, ParticleCloud& fluid,
    std::vector<const ParticleCloud*> walls, Neighbourhood& neighbourhood);

}  // namespace sphcast
