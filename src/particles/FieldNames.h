#pragma once

// The particle fields by name: the one list of the names the models and the tools read and
// write (ParticleCloud's named arrays; the arrays of the .vtp files, which ParaView lists), what
// each is and its unit. Code asks for a field as cloud.scalarField(field::rho), never by a
// literal of its own, so that a misspelling is a compile error and a new field is added here.
namespace sphcast::field {

// Every cloud
inline constexpr const char* id = "id";          // particle number, kept across restarts
inline constexpr const char* volume = "volume";  // m^3 (m^2 in 2D: per metre of depth)
inline constexpr const char* mass = "mass";      // kg (kg/m in 2D)

// The flow (sph/WeaklyCompressibleFlow.h)
inline constexpr const char* U = "U";                        // velocity, m/s
inline constexpr const char* rho = "rho";                    // density, kg/m^3
inline constexpr const char* p = "p";                        // pressure (gauge), Pa
inline constexpr const char* restDensity = "restDensity";    // rho_s(T) of eq. (3), kg/m^3
inline constexpr const char* viscosity = "viscosity";        // dynamic mu(T), Pa s
inline constexpr const char* acceleration = "acceleration";  // dU/dt, m/s^2 (restart state)
inline constexpr const char* densityRate = "densityRate";    // drho/dt, kg/m^3/s (restart state)

// Walls (particleizeMold; sph/WallClearance.h, particles/WallSurfaceDistance.h)
inline constexpr const char* normal = "normal";              // unit normal of the wall surface
inline constexpr const char* wallDistance = "wallDistance";  // m, behind the wall surface
inline constexpr const char* patch = "patch";                // the patch's number (patches file)
// m, a graded mold's particle's own spacing (geometry/GradedVolume.h); absent: the case's dx
inline constexpr const char* localSpacing = "localSpacing";
// m, a graded mold's particle: the largest support radius among the particles whose support
// holds it, its own included (GradedPairs.h); a decomposed run sends it that far as a halo
inline constexpr const char* supportReach = "supportReach";
inline constexpr const char* wallPatchRadius = "wallPatchRadius";  // m, surface the foot stands for
// a second foot, on a face no first foot stands for near it (geometry/WallSurfacePatches.h)
inline constexpr const char* secondNormal = "secondNormal";
inline constexpr const char* secondWallDistance = "secondWallDistance";        // m
inline constexpr const char* secondWallPatchRadius = "secondWallPatchRadius";  // m, 0: none
inline constexpr const char* wallPatchAtRim = "wallPatchAtRim";  // 1: the patch reaches an open rim

// Rigid bodies (bodies/RigidBody.h): a particle's place and normal in the body's frame
inline constexpr const char* restPosition = "restPosition";  // m
inline constexpr const char* restNormal = "restNormal";
inline constexpr const char* restSecondNormal = "restSecondNormal";

// Heat (thermal/EnergyEquation.h)
inline constexpr const char* T = "T";                              // temperature, K
inline constexpr const char* u = "u";                              // specific internal energy, J/kg
inline constexpr const char* energyRate = "energyRate";            // du/dt, W/kg (restart state)
inline constexpr const char* conductivity = "conductivity";        // kappa(T), W/m/K
inline constexpr const char* heldTemperature = "heldTemperature";  // K, of a held particle
inline constexpr const char* exposedArea = "exposedArea";          // A_i of eq. (11), m^2
inline constexpr const char* granularity = "granularity";          // s_i of eq. (10)

// Surface tension (surface/)
inline constexpr const char* curvature = "curvature";          // of the free surface, 1/m
inline constexpr const char* surfaceEnergy = "surfaceEnergy";  // the paper's phi_i, J

// Solidification (solidification/Solidification.h) and its history, which castPostProcess reads
inline constexpr const char* solidFraction = "solidFraction";        // f_s
inline constexpr const char* frozen = "frozen";                      // 1: held in place
inline constexpr const char* liquidusTime = "liquidusTime";          // s (-1: not yet)
inline constexpr const char* criticalTime = "criticalTime";          // s, T_c crossed
inline constexpr const char* solidusTime = "solidusTime";            // s
inline constexpr const char* coolingRate = "coolingRate";            // -dT/dt at T_c, K/s
inline constexpr const char* criticalGradient = "criticalGradient";  // |grad T| at T_c, K/m

// rheology (rheology/ThixotropicSemiSolid.h)
inline constexpr const char* structure = "structure";  // lambda: 1 fully built, 0 broken
inline constexpr const char* shearRate = "shearRate";  // sqrt(2 D:D), 1/s

// Pouring (inlets/PouringInlet.h) and the first contact with the mold (sph/FillTime.h)
inline constexpr const char* inlet = "inlet";  // in an inlet's buffer: 1 + its number; 0 once out
inline constexpr const char* fillTime = "fillTime";  // s (-1: no contact yet)

// castPostProcess's maps (castAnalysis/SolidificationMaps.h)
inline constexpr const char* solidificationTime = "solidificationTime";          // s
inline constexpr const char* localFreezingTime = "localFreezingTime";            // s
inline constexpr const char* temperatureGradient = "temperatureGradient";        // K/m
inline constexpr const char* niyama = "niyama";                                  // (K s)^0.5/mm
inline constexpr const char* dimensionlessNiyama = "dimensionlessNiyama";        // Ny*
inline constexpr const char* secondaryArmSpacing = "secondaryArmSpacing";        // lambda_2, m
inline constexpr const char* mushyZoneSpacings = "mushyZoneSpacings";            // dT_f / (G dx)
inline constexpr const char* temperatureAtFillEnd = "temperatureAtFillEnd";      // K
inline constexpr const char* solidFractionAtFillEnd = "solidFractionAtFillEnd";  // f_s

}  // namespace sphcast::field
