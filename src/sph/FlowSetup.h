#pragma once

#include <string>
#include <vector>

#include <optional>

#include "case/CaseDescription.h"
#include "core/Real.h"
#include "materials/TemperatureTable.h"
#include "parallel/Communicator.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {

// What constant/physicsModels, system/sphSchemes and constant/physicalProperties ask of the flow
// (the roles, the dimension, h and the periodic axes are the case's: case/CaseDescription.h):
//
//   constant/physicsModels:  flow { model weaklyCompressible; fluid metal; walls (mold); }
//                            (model none, or no flow entry: clouds move ballistically;
//                            model incompressible: the pressure solved for rho_s,
//                            IncompressiblePressure.h, with pressureSolverCoeffs in
//                            system/sphSchemes)
//   system/sphSchemes:       densityScheme riemann;      // riemann | standard | deltaSPH
//                            kernelCorrection on;        // optional, off by default
//                            deltaSPHCoeffs { delta 0.1; alpha 0.02; }  // optional (deltaSPH)
//                            viscousForm   Morris;       // Morris | Cleary
//                            supportRadius 0.0045;       // h, m
//                            soundSpeed    50;           // c of eq. (3), m/s
//   constant/physicalProperties:  metal { density 2400; viscosity 1.28e-3; }
//                            (a material of materials/MaterialLibrary.h: rho_s in kg/m^3,
//                            dynamic viscosity in Pa s, each a constant or a table in T;
//                            e.g. metal { #includeEtc "materials/AC4CH" })
struct FlowSetup {
  bool enabled = false;
  std::string fluidCloud;
  std::vector<std::string> wallClouds;
  FlowSettings settings;
  std::optional<TemperatureTable> restDensity;  // rho_s(T), or a constant
  std::optional<TemperatureTable> viscosity;    // dynamic mu(T), log-linear, or a constant
  SourceLocation supportRadiusAt;               // for the check of h against the fluid's spacing
};

// The Mach number the flow will reach, foreseen at its start: the largest speed the metal can
// gain, from its largest initial speed |U0| and its fall under g from its top to the lowest
// wall particle (or its own bottom), v = sqrt(|U0|^2 + 2 |g| H), against soundSpeed c. Weakly
// compressible SPH holds the density within about Ma^2 of rho_s, so above Ma = 0.1 (1 %) the
// log warns and names the c that would do (10 v). (Inlets, when they come, add their speed.)
struct SoundSpeedCheck {
  double fallHeight = 0;    // H, m
  double initialSpeed = 0;  // largest |U0|, m/s
  double largestSpeed = 0;  // v, m/s
  double mach = 0;          // v / c
  bool tooLow = false;      // mach > maxStartMach
  std::string message;      // the log's line(s)
};
constexpr double maxStartMach = 0.1;
// Over every rank of comm in a decomposed run.
SoundSpeedCheck checkSoundSpeed(const FlowSettings& settings, const ParticleCloud& fluid,
                                const std::vector<const ParticleCloud*>& walls,
                                const Communicator& comm = Communicator::self());

// Reads and checks the flow's entries (errors name file, line and key). A flow needs gravity
// (constant/g): without it, an error at the flow's entry.
FlowSetup readFlowSetup(const CaseDescription& description);

// Gives the fluid cloud the fields the flow needs that the start time lacks: restDensity and
// viscosity (rho_s and mu, at each particle's T where they are tables: the cloud must then
// have T), rho (rho_s), mass (rho volume). Returns what it added, for the log. rho_s and mu
// keep these start values while the heat moves T (they will follow T with solidification). The
// cloud must have the attribute spacing (dx), with supportRadius/spacing in [1.2, 6]. (The reader,
// VtpCloud.h, has refused non-positive rho, mass, volume and viscosity already.)
std::vector<std::string> prepareFluidFields(const FlowSetup& setup, ParticleCloud& fluid);

// The pressure the flow starts `fluid` with: eq. (3), p = c^2 (rho - rho_s), on the fields
// prepareFluidFields gives a copy of it. setCastFields writes it to 0/ so that the first frame
// of the series carries p as the later ones do; the solver computes the same p at its start.
std::vector<Real> startPressure(const FlowSetup& setup, const ParticleCloud& fluid);

}  // namespace sphcast
