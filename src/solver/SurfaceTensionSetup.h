#pragma once

#include <optional>

#include "core/CaseFolder.h"
#include "solver/FlowSetup.h"
#include "surface/SurfaceEnergyTension.h"

namespace sphcast {

// What constant/physicsModels asks of the surface tension (surface/SurfaceEnergyTension.h):
//
//   surfaceTension
//   {
//       model         surfaceEnergy;  // none | surfaceEnergy (the paper's §3)
//       energyFactor  calibrated;     // R_d of eq. (10): calibrated (a flat lattice face carries
//                                     // Gamma_g per unit area) or a number (the paper's:
//                                     // 41.4 in 2D, 41.3 in 3D)
//       contactAngle  180;            // degrees, at every wall (cos theta = -Gamma_s/Gamma_g);
//                                     // or solidTension 0.45 (Gamma_s, N/m); 180 by default
//       wallSmoothing 0.0045;         // eps of eq. (9), m; supportRadius by default
//       coreRadius    1;              // r0 of the granularity kernel, in spacings (1 by default)
//       densityCoupling on;           // on | off: the energy's change through the densities
//                                     // as a pressure (on by default; off only to compare)
//   }
//
// Gamma_g(T) is the fluid material's surfaceTension (constant/physicalProperties). The surface
// tension acts on the flow's fluid, among the flow's walls: it needs the flow.
struct SurfaceTensionSetup {
  bool enabled = false;
  SurfaceTensionSettings settings;  // spacing is the fluid cloud's, set by the solver
};

SurfaceTensionSetup readSurfaceTensionSetup(const CaseFolder& caseFolder,
                                            const FlowSetup& flow);

}  // namespace sphcast
