#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/dictionary/Dictionary.h"
#include "sph/ExposedArea.h"
#include "thermal/HeatTransferModel.h"

namespace sphcast {

// The energy equation (17) of the paper, rho_i du_i/dt = Q_hc + Q_ht + Q_ha + Q_hr, over the
// heat clouds, with u the specific internal energy (J/kg) and T = T(u) from each material's
// u(T) table (latent heat is its steep part: materials/InternalEnergyTable.h). Each term is a
// HeatTransferModel built from its switch in constant/physicsModels (HeatTransferRegistration
// .cpp); this class holds the fields and integrates u like the flow integrates the density:
//
//   halfKick(dt)              u += dt/2 du/dt (the rates of the current state); T = T(u),
//                             kappa = kappa(T)
//   ... the flow's drift and the neighbourhood's update ...
//   computeRates()            du/dt of every path at the new positions, T of the half step
//   halfKick(dt)              u += dt/2 du/dt; T = T(u), kappa = kappa(T)
//
// With the particles at rest this is forward Euler on the half steps (each rate serves the
// end of one step and the start of the next), first order in time: the diffusion limit keeps
// lambda dt <= 0.4 for the finest mode and (2 pi dx / L)^2 / 10 for a mode of wavelength L.
//
// Fields of each heat cloud: T, u, energyRate (restart state: u and energyRate; T follows from
// u bit for bit), conductivity, and rho and mass (a mold cloud gets them from its material's
// density at its start temperature and its particles' `volume`; its density stays that).
// Particles held at a fixed temperature keep T and u; the heat they take in is counted as
// leaving the system.
//
// Energy accounting, for the energyBalance function object, as attributes of each cloud
// (written with it, so they survive a restart): heatLost.<path> (J since the run's first
// start, with the same half-kick weights as u, so that E(t) - E(0) + sum of heatLost is
// round-off), heatLossRate.<path> (W, of the last rates), internalEnergyAtStart (J).
// Paths: atmosphere, radiation, fixedTemperature.
class EnergyEquation {
 public:
  // heatTransfer: the sub-dictionary of constant/physicsModels (its model switches);
  // context.clouds and neighbourhood set, every heat cloud registered in the neighbourhood
  // (the owner knows which move); the paths request their pairs here.
  EnergyEquation(HeatTransferContext context, const Dictionary& heatTransfer);
  ~EnergyEquation();

  // The paths' preparations (HeatTransferModel::start) and the rates of the start state (after
  // the first neighbourhood update and exposed area), unless the clouds came with them (a
  // restart). Returns the paths' lines for the log.
  std::vector<std::string> start();
  bool restarted() const { return restarted_; }
  // The fields of a heat cloud a restart reads back instead of computing: T, conductivity,
  // rho and mass follow from them or from the start (the accounts are cloud attributes).
  static const std::vector<std::string>& restartFields();

  void halfKick(double deltaT);
  void computeRates();

  // True when a path reads the exposed area A_i (the solver computes it before computeRates),
  // and the form heatTransfer's `exposedArea` asks for.
  bool needsExposedArea() const { return needsExposedArea_; }
  // Whether a path reads the exposed area of heat cloud c (context().clouds[c]): a surface
  // loss with a coefficient for its material, the cloud not held.
  bool readsExposedAreaOf(std::size_t c) const;
  ExposedAreaForm exposedAreaForm() const { return exposedAreaForm_; }
  const HeatTransferContext& context() const { return context_; }
  double stableDeltaT(std::string& limiter) const;
  std::vector<std::string> descriptions() const;

 private:
  void prepareFields(HeatCloud& heat);
  void kickEnergy(double deltaT);
  void updateTemperatures();
  void accountLosses(double duration);

  HeatTransferContext context_;
  std::vector<std::unique_ptr<HeatTransferModel>> paths_;
  bool needsExposedArea_ = false;
  ExposedAreaForm exposedAreaForm_ = ExposedAreaForm::gradient;
  bool restarted_ = false;
};

}  // namespace sphcast
