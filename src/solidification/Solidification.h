#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/Real.h"
#include "materials/Material.h"
#include "parallel/Communicator.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// Solidification and shrinkage of the metal, after Cleary et al. as the paper uses them (§4.5,
// Fig. 11): the reference density rho_s(T) and the viscosity mu(T) of the material's tables follow
// each particle's temperature, so that the equation of state (3), p = c^2 (rho - rho_s(T)),
// contracts the melt as it cools, and the solid fraction is the share of the freezing range's
// heat a particle has given up,
//
//   f_s = (u(T_liq) - u(T)) / (u(T_liq) - u(T_sol)),  clamped to [0, 1],
//
// with u(T) the material's internal energy (its latent heat is the steep part between solidus
// and liquidus), so that f_s rises as the latent heat is released.
//
// Solid metal cannot be stepped with its viscosity (AC4CH reaches 4.9e4 Pa s: the explicit
// viscous limit 0.125 dx^2 rho / mu would be ~1e-7 s at dx = 1.5 mm, against the acoustic
// 1e-5 s). So (doc/physics.md §12):
// - a particle whose f_s reaches frozenSolidFraction is frozen (Monaghan, Huppert & Worster
//   2005): it stays where it is, with zero velocity, and becomes wall for the melt around it; its
//   density still follows the continuity equation (the melt that presses on it raises it, as a
//   wall particle of the dynamic boundary condition), and its rho_s stays the one it froze with,
//   so the solid's own contraction below that point moves nothing (it is not a cavity: a real
//   casting shrinks away from its mold as a whole, which a fixed mold of particles cannot show);
// - below that fraction mu(T) is capped at viscosityLimit, the viscosity whose explicit limit
//   equals the acoustic step (0.125 rho dx c / maxCo), so the step never falls below the
//   acoustic one; the mush flows more easily than its table says, which matters only while it
//   is below the frozen fraction.
// A frozen particle whose f_s falls back below frozenSolidFraction (remelted by hotter melt)
// flows again, with rho_s(T).
//
// Fields of the metal cloud: reads T and energyRate (where a heat model gives it); writes
// solidFraction, frozen (1 or 0), restDensity and viscosity (all written with the cloud, so a
// restart continues bit for bit: a frozen particle's rho_s is its history, not a function of T).
//
// It also records, at every update, each particle's solidification history for castPostProcess's
// maps (which need every heat step: a write every second would place a crossing only within a
// second); -1 until it happens:
//   liquidusTime   when u fell to u(T_liq)            (start of freezing)
//   criticalTime   when u fell to u(T_c), T_c = T_sol + criticalTemperatureFraction (T_liq -
//                  T_sol), the Niyama criterion's temperature (Carlson & Beckermann 2009)
//   coolingRate    -dT/dt there, K/s: -(du/dt) / (du/dT)(T_c), du/dT with the latent heat
//   solidusTime    when u fell to u(T_sol)             (end of freezing: the solidification time)
//   criticalGradient  |grad T| (K/m) when T_c was crossed: this model has no neighbours, so the
//                  solver writes it right after the update that set criticalTime
//                  (pendingCriticalGradients; sph/CorrectedGradient.h)
// A crossing inside a heat step is placed by the step's rate du/dt (linear in time), within the
// step. A particle that melts again (u above u(T_liq)) starts its history afresh.
struct SolidificationSettings {
  Real frozenSolidFraction = Real(0.5);
  Real viscosityLimit = 0;  // Pa s; 0: no cap
  Real criticalTemperatureFraction = Real(0.1);
};

// What the metal looks like after an update, for the log.
struct SolidificationSummary {
  std::size_t particles = 0;
  std::size_t liquid = 0;  // f_s = 0
  std::size_t frozen = 0;  // f_s >= frozenSolidFraction
  std::size_t solid = 0;   // f_s = 1
  std::size_t viscosityCapped = 0;
  double solidFraction = 0;  // mass-weighted mean of f_s
};

// f_s at temperature T of a material with a freezing range and u(T) (the formula above), for
// code without a cloud (castPostProcess's maps of a time written before the solver ran).
Real solidFraction(const Material& material, Real temperature);

// T_c = T_sol + fraction (T_liq - T_sol), the Niyama criterion's temperature (above).
double criticalTemperature(const FreezingRange& range,
                           double fraction = SolidificationSettings{}.criticalTemperatureFraction);

class Solidification {
 public:
  // material: the metal's, with liquidus, solidus, internalEnergy, density and viscosity.
  Solidification(SolidificationSettings settings, const Material& material, ParticleCloud& metal);

  // The fields of the metal cloud it writes (restart state: frozen particles' rho_s, the
  // histories).
  static const std::vector<std::string>& fields();
  // Of those, the solidification history (-1 until it happens).
  static const std::vector<std::string>& historyFields();

  // f_s, frozen, rho_s and mu from the particles' T, and the histories; call after every change
  // of T, with the time reached and the length of the heat step that reached it (0 at the start).
  void update(double time, double heatDeltaT);

  // The particles that crossed T_c and whose criticalGradient is not yet written (-1).
  std::vector<std::size_t> pendingCriticalGradients() const;

  const SolidificationSettings& settings() const { return settings_; }
  // The fraction at which a particle freezes, set by the rheology (its coherency); the next
  // update freezes by it.
  void setFrozenSolidFraction(Real fraction) { settings_.frozenSolidFraction = fraction; }
  // A rheology writes the fluid's viscosity before every flow step (rheology/RheologyModel.h):
  // the updates then leave it as that law set it, so the written field is what the flow took.
  void leaveViscosityToRheology() { rheologyWritesViscosity_ = true; }
  // Of the owned particles of every rank of comm in a decomposed run (collective).
  SolidificationSummary summary(const Communicator& comm = Communicator::self()) const;
  // Every particle fully solid (f_s = 1), on every rank of comm (collective).
  bool allSolid(const Communicator& comm = Communicator::self()) const;
  std::string description() const;

 private:
  SolidificationSettings settings_;
  Material material_;  // a copy: the tables it reads
  ParticleCloud& metal_;
  Real liquidusEnergy_, freezingRangeEnergy_;  // u(T_liq), u(T_liq) - u(T_sol)
  Real criticalEnergy_, solidusEnergy_;        // u(T_c), u(T_sol)
  Real criticalSpecificHeat_;                  // du/dT at T_c
  bool rheologyWritesViscosity_ = false;
};

}  // namespace sphcast
