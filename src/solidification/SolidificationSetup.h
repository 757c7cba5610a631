#pragma once

#include <optional>

#include "case/CaseDescription.h"
#include "materials/Material.h"
#include "solidification/Solidification.h"

namespace sphcast {

// What constant/physicsModels asks of the solidification (solidification/Solidification.h):
//
//   solidification
//   {
//       model               frozenSolid;  // none | frozenSolid
//       cloud               metal;        // without a flow: the heat cloud that solidifies
//                                         // (with a flow it is the flow's fluid)
//       frozenSolidFraction 0.5;          // f_s from which a particle is frozen, in (0, 1];
//                                         // 0.5 by default
//       cavitationPressure  0;            // Pa (gauge): the lowest pressure the melt holds
//                                         // before it opens a cavity; 0 by default
//       endWhenSolid        yes;          // optional: the run ends (written) once every
//                                         // particle is fully solid (f_s = 1); no by default
//       cooling                           // optional: once the melt is still, steps of the
//       {                                 // heat's stable length, each followed by
//           flowStepsPerHeatStep 10;      // this many flow steps of the acoustic length
//           maxCo                0.25;    // their Courant number c dt / dx, in (0, 1];
//                                         // controlDict's maxCo by default
//           stillSpeed           0.02;    // m/s: cooling starts once max|U| of the melt is
//                                         // below this
//           stillFraction        0;       // optional: ... or all but this share of the
//                                         // melt's particles (0.01: its 99th percentile;
//                                         // a pressed melt's acoustic jitter)
//           movingSpeed          0.5;     // m/s: back to every acoustic step above this (a
//       }                                 // collapse); the melt's flow steps, compressed in
//                                         // time, feed the shrinkage faster than stillSpeed
//   }
//
// It needs the heat transfer carrying the cloud; its material needs liquidus, solidus,
// internalEnergy (or specificHeat), density and viscosity
// (constant/physicalProperties). Without a flow (a casting that only conducts: Chvorinov's
// plates, cooling curves) it computes f_s, rho_s and the solidification history, and cooling and
// cavitationPressure are errors. The solver caps the mush's viscosity at 0.9 times the
// acoustic step's viscous limit, 0.9 x 0.125 rho_s(T_liq) dx c / maxCo (0.9: melt a few per cent
// lighter than rho_s(T_liq), in a cavity, still steps at the acoustic limit), with the larger of
// controlDict's maxCo and the cooling mode's, where the flow steps the viscosity explicitly
// (viscositySolver explicit); solved implicitly (auto, implicit) the mush keeps its mu(T).
// A rheology that knows where the mush stops flowing (rheology thixotropicSemiSolid's maxPacking)
// sets frozenSolidFraction, which is then not written here.
// Cooling to the end in fewer steps (CastingSolver::evolveCooling): the flow's time runs
// slower than the heat's by heat step / (flowStepsPerHeatStep acoustic steps). What feeds the
// shrinkage is the flow time per heat step, flowStepsPerHeatStep x maxCo dx / c: a still melt
// takes it in fewer, longer steps with the same result (doc/physics.md §10.5), where a moving
// one (pouring, an impact) needs controlDict's shorter steps.
struct CoolingAcceleration {
  int flowStepsPerHeatStep = 10;
  double maxCo = 0;          // 0: controlDict's maxCo
  double stillSpeed = 0.02;  // m/s
  double stillFraction = 0;  // the melt's particles allowed above stillSpeed, as a share
  double movingSpeed = 0.5;  // m/s
};

struct SolidificationSetup {
  bool enabled = false;
  std::optional<CoolingAcceleration> cooling;
  SolidificationSettings settings;
  Real cavitationPressure = 0;
  bool endWhenSolid = false;
  std::string cloud;                 // that solidifies
  std::optional<Material> material;  // its
  // where frozenSolidFraction is written, when it is (a rheology that sets it refuses it)
  std::optional<SourceLocation> frozenSolidFractionAt;
};

SolidificationSetup readSolidificationSetup(const CaseDescription& description);

}  // namespace sphcast
