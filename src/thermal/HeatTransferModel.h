#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/dictionary/Dictionary.h"
#include "materials/Material.h"
#include "parallel/Communicator.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// A cloud that carries heat: its material and, for a Dirichlet boundary (a mold surface held
// at 300 K), the temperature it or some of its patches are held at. Fields (EnergyEquation.h):
// T (K), u (specific internal energy, J/kg), energyRate (du/dt, W/kg), conductivity (kappa(T),
// W/m/K), rho and mass (a mold's from its material's density and its particles' volume), and
// `heldTemperature` (K; 0 for a free particle) where any particle is held.
struct HeatCloud {
  ParticleCloud* cloud;
  const Material* material;
  bool fixedTemperature = false;  // the whole cloud held; the heat it takes in counts as lost
  double heldTemperature = 0;     // K, when fixedTemperature
  // Patches of a mold cloud held at a temperature: (the value of its particles' `patch` field,
  // as constant/particles/patches numbers it, T in K).
  std::vector<std::pair<std::int64_t, double>> heldPatches;
  bool holdsAny() const { return fixedTemperature || !heldPatches.empty(); }
};

// 0 for a free particle, else the temperature it is held at: the `heldTemperature` field of a
// cloud that holds any, else null (no particle held).
inline const Real* heldTemperatures(const HeatCloud& heat) {
  return heat.holdsAny() ? heat.cloud->scalarField(field::heldTemperature).data() : nullptr;
}

// What every heat path sees: the heat clouds, the shared neighbourhood, the kernel.
struct HeatTransferContext {
  int dimension = 3;
  Real supportRadius = 0;  // h
  Real spacing = 0;        // dx, of the regularisation eta^2 = 0.01 dx^2 and the step limits
  double maxDi = 0.1;      // the conduction step, maxDi dx^2 / alpha_max (controlDict)
  std::vector<HeatCloud> clouds;
  Neighbourhood* neighbourhood = nullptr;
  // A decomposed run's ranks: books and losses are summed over them (owned particles only).
  Communicator comm = Communicator::self();
};

// The heat clouds (indices into context.clouds) of `material`, which the entry `key` of `dict`
// names; a DictionaryError there when no heat cloud has it, listing the materials they have.
std::vector<std::size_t> cloudsOfMaterial(const HeatTransferContext& context,
                                          const std::string& material, const Dictionary& dict,
                                          const std::string& key);

// One heat path of eq. (17), rho du/dt = Q_hc + Q_ht + Q_ha + Q_hr (doc/physics.md §10.2): a
// model reads its own sub-dictionary of heatTransfer in constant/physicsModels, asks the
// neighbourhood for the pairs it needs when it is built, and in each step adds its du/dt to
// the clouds' energyRate (never overwrites: EnergyEquation zeroes it) and names its step limit.
class HeatTransferModel {
 public:
  virtual ~HeatTransferModel() = default;

  // conduction, moldContact, atmosphere, radiation: the key in constant/physicsModels
  virtual const char* name() const = 0;
  // One line for the log: the equation and the coefficients it runs with.
  virtual std::string description() const = 0;

  // Once, after the first neighbourhood update and before the first rates: what the path
  // prepares from the start state. Returns a line for the log, or "".
  virtual std::string start() { return ""; }

  // Adds this path's du/dt to every heat cloud's energyRate.
  virtual void addEnergyRates() = 0;

  // Heat per second leaving each heat cloud through this path (W, by cloud in the context's
  // order), over the particles not held at a fixed temperature, for the state of the last
  // addEnergyRates(); empty for a path between particles, which moves heat inside the system.
  virtual std::vector<double> powerLeaving() const { return {}; }

  // The longest step this path stays stable and accurate with (s), for the state of the last
  // addEnergyRates().
  virtual double stableDeltaT() const { return std::numeric_limits<double>::infinity(); }
  // Whether the path reads the exposed area A_i (sph/ExposedArea.h) of a heat cloud (by index
  // into the context's clouds): the areas are computed where some path reads them.
  virtual bool readsExposedAreaOf(std::size_t /*cloud*/) const { return false; }
};

}  // namespace sphcast
