#pragma once

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/dictionary/Dictionary.h"
#include "thermal/HeatTransferModel.h"

namespace sphcast {

// Heat transfer between particles of two materials in contact (metal and mold) through a
// contact coefficient omega (W/m^2/K), eq. (14) of the paper, normalised so that a flat
// interface of area A between two lattices passes exactly omega A (T_i - T_k):
//
//   du_i/dt = -1/rho_i sum_k omega_ik V_k W_ik (T_i - T_k) / l_W,
//   l_W = (sum_{i in A} sum_{k in B} V_i V_k W_ik) / A  on a flat interface of a cubic lattice
//         with spacing dx, each side's first layer dx/2 from the interface (contactLength()).
//
// As printed, (14) weighs each pair with 2 pi h^2 (V_i + V_k): the area of the kernel's sphere
// rather than the particle's face, so a flat interface would pass 4 pi h^2 l_W / dx^3 times
// omega A dT: 30 times at h = 3 dx in 3D (l_W = 0.267 dx), 6.4 times at h = 2 dx
// (doc/physics.md §10.2.2). A coefficient calibrated with the paper's form (150 W/m^2/K for its
// press) stands for that many times more here. The pair term is antisymmetric: heat moves
// from one cloud to the other, none is lost.
//
// constant/physicsModels:
//   heatTransfer { moldContact { coefficients ((AC4CH iron 150)); } }   // W/m^2/K per pair
// A pair of materials not listed exchanges heat by conduction (perfect contact).
//
// Step limit: no particle's temperature may relax by more than a quarter of its difference
// in a step, dt <= 0.25 rho_i c_min l_W / omega (sum_k V_k W_ik <= 1).
class MoldContactTransfer : public HeatTransferModel {
 public:
  MoldContactTransfer(const HeatTransferContext& context, const Dictionary& dict);

  const char* name() const override { return "moldContact"; }
  std::string description() const override;
  void addEnergyRates() override;
  double stableDeltaT() const override { return stableDeltaT_; }

  // The coefficient of each material pair, both orders, of `dict` (moldContact's settings),
  // checked: every material a heat cloud's, omega positive, two materials a pair. Its pairs are
  // the exchange this model takes over from conduction.
  static std::map<std::pair<std::string, std::string>, double> readCoefficients(
      const HeatTransferContext& context, const Dictionary& dict);

  // l_W for the kernel of this dimension and h/dx (m).
  static Real contactLength(int dimension, Real supportRadius, Real spacing);

 private:
  template <int Dim>
  void addRatesIn();
  double coefficient(std::size_t a, std::size_t b) const;  // 0: no contact transfer

  const HeatTransferContext& context_;
  std::map<std::pair<std::string, std::string>, double> coefficients_;
  Real contactLength_;
  double stableDeltaT_;
};

}  // namespace sphcast
