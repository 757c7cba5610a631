#pragma once

#include <string>
#include <vector>

#include "rheology/RheologyModel.h"

namespace sphcast {

// Settings of the Herschel-Bulkley rheology (rheology { model herschelBulkley;
// herschelBulkleyCoeffs { tau0 ..; k ..; n ..; mu0 ..; } } in constant/physicsModels), named as
// OpenFOAM's HerschelBulkley viscosity model names them, with mu0 a dynamic viscosity (Pa s)
// where OpenFOAM's nu0 is kinematic.
struct HerschelBulkleySettings {
  Real yieldStress = 0;    // tau0, Pa
  Real consistency = 0;    // k, Pa s^n
  Real exponent = 1;       // n: < 1 shear-thinning, 1 Bingham (with tau0) or Newtonian
  Real restViscosity = 0;  // mu0, Pa s: the viscosity at rest and the largest the law gives
};

// A yield-stress fluid (Herschel & Bulkley 1926): tau = tau0 + k gammaDot^n where it flows,
// rigid below tau0. As OpenFOAM's HerschelBulkley, regularised by a bi-viscosity cap,
//   mu = min(mu0, (tau0 + k gammaDot^n) / gammaDot),
// so that unyielded material moves at mu0 (a plug that creeps at tau / mu0): mu0 must be large
// against the flowing viscosity (1e3 times it keeps a Bingham plug's velocity within 0.1 % of
// rigid; the implicit viscosity makes any mu0 cost one solve per step). gammaDot =
// sqrt(2 D:D) from rheology/ShearRate.h, at the state each flow step starts from. tau0 = 0 gives
// a power law (Ostwald-de Waele), n = 1 a Bingham plastic.
// For slurries and pastes, and a semi-solid metal at a fixed structure; the viscosity does not
// depend on temperature here (a solidifying metal's frozen particles are held rigid by the
// solidification). Reads U; writes viscosity and shearRate (1/s).
class HerschelBulkley : public RheologyModel {
 public:
  HerschelBulkley(const RheologyContext& context, const Dictionary& settings);
  HerschelBulkley(const RheologyContext& context, HerschelBulkleySettings settings);

  void update(double dt) override;
  std::vector<std::string> fields() const override;
  std::string description() const override;

  // mu at a shear rate (the law above).
  Real viscosity(Real shearRate) const;
  const HerschelBulkleySettings& settings() const { return settings_; }

 private:
  ParticleCloud& fluid_;
  const Neighbourhood& neighbourhood_;
  std::vector<ShearWall> walls_;
  int dimension_;
  Real supportRadius_;
  HerschelBulkleySettings settings_;
};

}  // namespace sphcast
