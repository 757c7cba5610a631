#pragma once

#include <string>
#include <vector>

#include "rheology/RheologyModel.h"
#include "sph/FluidForceModel.h"

namespace sphcast {

// Settings of the elasto-viscoplastic rheology (rheology { model elastoViscoplastic;
// elastoViscoplasticCoeffs { tau0 ..; k ..; n ..; G ..; etaS ..; } } in constant/physicsModels).
struct ElastoViscoplasticSettings {
  Real yieldStress = 0;       // tau0, Pa
  Real consistency = 0;       // k, Pa s^n: the plastic flow's Herschel-Bulkley consistency
  Real exponent = 1;          // n
  Real shearModulus = 0;      // G, Pa: below the yield stress the material is an elastic solid
  Real solventViscosity = 0;  // etaS, Pa s: a Newtonian part beside the stress (the flow's term)
};

// A yield-stress material that is an elastic solid below its yield stress and a
// Herschel-Bulkley fluid above it: Saramito's elasto-viscoplastic law (Saramito 2007, J.
// Non-Newtonian Fluid Mech. 145:1, eq. 3), with the corotational (Jaumann) rate that SPH for
// soils and solids uses (Gray, Monaghan & Swift 2001, Comput. Methods Appl. Mech. Eng.
// 190:6641, eq. 2.8) in place of the upper-convected one:
//   (1/G) dtau/dt = 2 D' - gammaDot_p tau / |tau| + (1/G) (Omega tau - tau Omega),
//   gammaDot_p = max(0, (|tau| - tau0) / k)^(1/n),   |tau| = sqrt(tau:tau / 2),
// tau the deviatoric extra stress, D' the deviatoric strain rate (tr D / d removed in d
// dimensions: a 2D run is incompressible plane strain, tau_zz = 0; with tr D / 3 the weakly
// compressible melt's divergence noise piled up in tau_zz, 45 Pa against a yield stress of 39 in
// the slump's top layer after 0.2 s), Omega the spin. In steady simple shear at a rate gammaDot the
// stress is tau0 + k gammaDot^n (Herschel-Bulkley) up to terms of order (gammaDot k / G)^2; below
// tau0 the strain is elastic, tau / G. The regularised viscous law (HerschelBulkley.h) cannot hold
// a plug in a weakly compressible melt: the column's acoustic ringing shears every particle at
// about g / c, so everything yields and creeps (doc/validation.md §1.3.2); here the ringing only
// flexes the solid elastically. Each flow step, before the rates, the stress is integrated over dt
// at the step's starting velocity gradient (rheology/ShearRate.h: kernel-normalised, with the
// walls): an explicit elastic trial, then the plastic flow's return to the law, backward Euler
// along tau (exact for the magnitude, unconditionally stable). The stress's divergence is a force
// on the fluid,
//   dv_i/dt += 1/rho_i sum_j V_j (tau_i + tau_j) grad_i W_ij,
// which conserves momentum pair by pair (the pressure's form with sigma = -p I + tau); a wall
// particle k carries tau_i at a no-slip wall and its mirror image (R tau_i R, R = I - 2 n n) at
// a slip wall, so that a slip wall passes the normal stress and no shear. The elastic waves
// (speed sqrt(4 G / (3 rho))) set a step limit at Courant 0.25 on the fluid's spacing.
// Reads U, rho, mass and frozen (a frozen particle's stress is held); writes viscosity (etaS),
// shearRate (1/s) and the stress as two vectors (stressDiagonal: xx yy zz; stressShear: xy yz
// zx, Pa), which a restart reads back.
class ElastoViscoplastic : public RheologyModel, public FluidForceModel {
 public:
  ElastoViscoplastic(const RheologyContext& context, const Dictionary& settings);
  ElastoViscoplastic(const RheologyContext& context, ElastoViscoplasticSettings settings);

  // RheologyModel: the stress over a step of dt, and the viscosity etaS.
  void update(double dt) override;
  std::vector<std::string> fields() const override;
  std::string description() const override;
  FluidForceModel* force() override { return this; }

  // FluidForceModel: the stress's divergence.
  std::string limitName() const override { return "elastic"; }
  void addAcceleration() override;
  double stableDeltaT() const override;
  double seconds() const override { return seconds_; }

  // The return to the law: |tau| after a step of dt from an elastic trial of magnitude
  // trialMagnitude (above tau0), solving s + dt G gammaDot_p(s) = trialMagnitude.
  Real plasticMagnitude(Real trialMagnitude, double dt) const;
  const ElastoViscoplasticSettings& settings() const { return settings_; }

 private:
  ParticleCloud& fluid_;
  const Neighbourhood& neighbourhood_;
  std::vector<ShearWall> walls_;
  int dimension_;
  Real supportRadius_;
  ElastoViscoplasticSettings settings_;
  std::vector<Matrix> gradient_;  // the velocity gradient, reused between steps
  double seconds_ = 0;
};

}  // namespace sphcast
