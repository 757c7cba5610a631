#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/dictionary/Dictionary.h"
#include "materials/InternalEnergyTable.h"
#include "materials/TemperatureTable.h"

namespace sphcast {

// One material of constant/physicalProperties (doc/physics.md §4.1), a sub-dictionary whose
// keys are all optional: a model that needs one asks for it (requireX), so a mold material
// need not give a viscosity.
//
//   AC4CH
//   {
//       temperatures    (803.0 830.44 848 873 888.64 973);   // K, rows of the columns below
//       internalEnergy  (7.89e5 8.44e5 1.11e6 1.23e6 1.33e6 1.431e6);   // u(T), J/kg
//       viscosity       table ((803 4.88e4) (973 1.28e-3));   // mu(T), Pa s, log-linear
//       density         2398.8;                                // rho_s(T), kg/m^3
//   }
//
// density [1 -3 0 0 0 0 0], viscosity (dynamic) [1 -1 -1 0 0 0 0], conductivity
// [1 1 -3 -1 0 0 0], internalEnergy [0 2 -2 0 0 0 0] or specificHeat [0 2 -2 -1 0 0 0] (not
// both), surfaceTension [1 0 -2 0 0 0 0] (may be 0), emissivity (a number in [0, 1]),
// liquidus and solidus [0 0 0 1 0 0 0] (both or neither, solidus below liquidus: the freezing
// range that solidification reads), dendriteArmSpacing (A n) (lambda_2 = A t_f^n, t_f the local
// freezing time in s, lambda_2 in m: A in m s^-n, n in (0, 1]; castPostProcess's SDAS and
// dimensionless Niyama maps read it).
struct FreezingRange {
  double solidus;   // K: fully solid below
  double liquidus;  // K: fully liquid above
  SourceLocation location;  // of 'liquidus'
};

struct Material {
  std::string name;
  SourceLocation location;  // of the material's name in its file
  std::string file;         // "constant/physicalProperties", for messages

  std::optional<TemperatureTable> density;            // rho_s(T), kg/m^3
  std::optional<TemperatureTable> viscosity;          // dynamic mu(T), Pa s, log-linear in T
  std::optional<TemperatureTable> conductivity;       // kappa(T), W/m/K
  std::optional<TemperatureTable> surfaceTension;     // Gamma_g(T), N/m, non-negative
  std::optional<InternalEnergyTable> internalEnergy;  // u(T), J/kg (or from cp(T))
  std::optional<double> emissivity;                   // beta of eq. (16), in [0, 1]
  std::optional<FreezingRange> freezingRange;         // solidus, liquidus
  // lambda_2 = coefficient t_f^exponent (m, t_f in s)
  struct DendriteArmSpacing {
    double coefficient;
    double exponent;
  };
  std::optional<DendriteArmSpacing> dendriteArmSpacing;

  // The keys a material may have.
  static const std::vector<std::string>& validKeys();

  // Reads the sub-dictionary `dict` named `name`; `file` names it in messages.
  static Material read(const Dictionary& dict, const std::string& name, const std::string& file);

  // Each throws a DictionaryError at the material's location when the property is absent:
  // "material 'AC4CH' in constant/physicalProperties has no 'conductivity', which heatTransfer
  // conduction needs" (neededBy: "heatTransfer conduction").
  const TemperatureTable& requireDensity(std::string_view neededBy) const;
  const TemperatureTable& requireViscosity(std::string_view neededBy) const;
  const TemperatureTable& requireConductivity(std::string_view neededBy) const;
  const TemperatureTable& requireSurfaceTension(std::string_view neededBy) const;
  const InternalEnergyTable& requireInternalEnergy(std::string_view neededBy) const;
  double requireEmissivity(std::string_view neededBy) const;
  const FreezingRange& requireFreezingRange(std::string_view neededBy) const;

 private:
  [[noreturn]] void missing(std::string_view key, std::string_view neededBy) const;
};

}  // namespace sphcast
