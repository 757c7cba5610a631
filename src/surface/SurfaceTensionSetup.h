#pragma once

#include <optional>
#include <string>

#include "case/CaseDescription.h"
#include "surface/SurfaceTensionModel.h"

namespace sphcast {

// What constant/physicsModels asks of the surface tension (surface/SurfaceTensionModel.h):
//
//   surfaceTension
//   {
//       model         continuumSurfaceForce;  // the default; none | continuumSurfaceForce |
//                                             // surfaceEnergy (the paper's §3)
//       contactAngle  150;    // degrees, in [0, 180], at every wall; 180 by default
//       gapMeniscus   on;     // continuumSurfaceForce: Young-Laplace's curvature in gaps
//                             // narrower than the kernel (off by default: the kernel's)
//   }
//
// sigma (Gamma_g(T)) is the fluid material's surfaceTension (constant/physicalProperties).
// surfaceEnergy takes these as well (surface/SurfaceEnergyTension.h), and refuses a wetting
// wall (contactAngle below 90):
//       energyFactor  calibrated;     // R_d of eq. (10): calibrated (a flat lattice face carries
//                                     // Gamma_g per unit area) or a number (the paper's:
//                                     // 41.4 in 2D, 41.3 in 3D)
//       solidTension  0.45;           // Gamma_s, N/m, instead of contactAngle
//       wallSmoothing 0.0045;         // eps of eq. (9), m; supportRadius by default
//       coreRadius    1;              // r0 of the granularity kernel, in spacings (1 by default)
// A key of the other model is an error. The surface tension acts on the flow's fluid, among
// the flow's walls: it needs the flow.
struct SurfaceTensionSetup {
  bool enabled = false;
  std::string model;                // a name of surfaceTensionModels(), or none
  SurfaceTensionSettings settings;  // spacing is the fluid cloud's, set by the solver
};

SurfaceTensionSetup readSurfaceTensionSetup(const CaseDescription& description);

}  // namespace sphcast
