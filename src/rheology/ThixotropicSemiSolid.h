#pragma once

#include <string>
#include <vector>

#include "rheology/RheologyModel.h"

namespace sphcast {

// Settings of the thixotropic semi-solid rheology (rheology { model thixotropicSemiSolid;
// thixotropicSemiSolidCoeffs { ... } } in constant/physicsModels).
struct ThixotropicSemiSolidSettings {
  // The structure's kinetics, d lambda/dt = a (1 - lambda) - b lambda gammaDot^m:
  Real buildUp = Real(0.05);    // a, 1/s: the structure rebuilds at rest over 1/a = 20 s
  Real breakDown = Real(0.01);  // b, s^(m-1): at 100 1/s it breaks down within 1/(b 100^m) = 1 s
  Real exponent = Real(1);      // m
  // f_max, the solid fraction at which the broken suspension jams (its viscosity diverges):
  // the mush stops flowing there, and a particle freezes.
  Real maxPacking = Real(0.6);
};

// A semi-solid metal as a suspension of solid globules whose structure (agglomerates, bonds
// between globules) breaks down under shear and rebuilds at rest (Flemings 1991; reviews:
// Atkinson 2005, Prog. Mater. Sci. 50:341; Modigell, Pola & Tocci 2018, Metals 8:245). Per
// particle a structure parameter lambda in [0, 1] (1: fully built) follows Moore's kinetics
//   d lambda / dt = a (1 - lambda) - b lambda gammaDot^m,
// integrated exactly over each flow step at the step's shear rate gammaDot = sqrt(2 D:D)
// (D the SPH strain rate of the fluid neighbours, rheology/ShearRate.h):
//   lambda' = lambda_e + (lambda - lambda_e) exp(-k dt),  k = a + b gammaDot^m,
//   lambda_e = a / k.
// The viscosity lies between the fully built and the fully broken structure, as OpenFOAM's
// thixotropicViscosity (after Barnes 1997, J. Non-Newtonian Fluid Mech. 70:1):
//   mu = mu_inf / (1 - K lambda)^2,  K = 1 - sqrt(mu_inf / mu_0),
// so lambda = 1 gives mu_0 and lambda = 0 gives mu_inf, with
//   mu_0   = the material's mu(T): the mush at rest (the paper's Table 1, 186 to 4.9e4 Pa s
//            over AC4CH's freezing range),
//   mu_inf = mu_l (1 - f_s / f_max)^(-2.5 f_max): the broken suspension of globules in the
//            liquid of viscosity mu_l = mu(T_liq) (Krieger & Dougherty 1959, Trans. Soc. Rheol.
//            3:137), at most mu_0.
// Liquid metal (f_s = 0) takes mu(T); a frozen particle keeps mu_0 (it does not flow). The
// mush freezes at f_max (coherentSolidFraction), where mu_inf diverges.
// The kinetics' defaults are set to the time scales the reviews report for aluminium slurries
// (breakdown within about a second at 100 1/s, rebuilding over tens of seconds at rest), not a
// fit: the A356 fits (e.g. Modigell & Koke; Burgos, Alexandrou & Entov 2001, J. Mater. Process.
// Technol. 110:164) were not available to us with their tables; set them from rheometry.
//
// Fields of the fluid: reads T, solidFraction and frozen (when the metal solidifies) and U;
// writes viscosity, structure (lambda) and shearRate (1/s).
class ThixotropicSemiSolid : public RheologyModel {
 public:
  ThixotropicSemiSolid(const RheologyContext& context, const Dictionary& settings);
  ThixotropicSemiSolid(const RheologyContext& context, ThixotropicSemiSolidSettings settings);

  void update(double dt) override;
  std::vector<std::string> fields() const override;
  std::string description() const override;
  Real coherentSolidFraction() const override { return settings_.maxPacking; }

  // mu at solid fraction fs, temperature T and structure lambda (the law above).
  Real viscosity(Real solidFraction, Real temperature, Real structure) const;
  // lambda_e at a steady shear rate.
  Real equilibriumStructure(Real shearRate) const;
  const ThixotropicSemiSolidSettings& settings() const { return settings_; }

 private:
  ParticleCloud& fluid_;
  const Neighbourhood& neighbourhood_;
  std::vector<ShearWall> walls_;
  int dimension_;
  Real supportRadius_;
  TemperatureTable mu_;   // the material's mu(T)
  Real liquidViscosity_;  // mu(T_liq)
  ThixotropicSemiSolidSettings settings_;
};

}  // namespace sphcast
