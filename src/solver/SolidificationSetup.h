#pragma once

#include <optional>

#include "core/CaseFolder.h"
#include "materials/Material.h"
#include "solidification/Solidification.h"
#include "solver/FlowSetup.h"
#include "solver/HeatSetup.h"

namespace sphcast {

// What constant/physicsModels asks of the solidification (solidification/Solidification.h):
//
//   solidification
//   {
//       model               frozenSolid;  // none | frozenSolid
//       frozenSolidFraction 0.5;          // f_s from which a particle is frozen, in (0, 1];
//                                         // 0.5 by default
//       cavitationPressure  0;            // Pa (gauge): the lowest pressure the melt holds
//                                         // before it opens a cavity; 0 by default
//   }
//
// It needs the flow (its fluid solidifies) and the heat transfer carrying the fluid's cloud; the
// fluid's material needs liquidus, solidus, internalEnergy (or specificHeat), density and
// viscosity (constant/physicalProperties). The solver caps the mush's viscosity at the acoustic
// step's viscous limit, 0.125 rho_s(T_liq) dx c / maxCo.
struct SolidificationSetup {
  bool enabled = false;
  SolidificationSettings settings;
  Real cavitationPressure = 0;
  std::optional<Material> material;  // the fluid's
};

SolidificationSetup readSolidificationSetup(const CaseFolder& caseFolder, const FlowSetup& flow,
                                            const HeatSetup& heat);

}  // namespace sphcast
