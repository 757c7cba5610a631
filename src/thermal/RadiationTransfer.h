#pragma once

#include <string>
#include <vector>

#include "core/dictionary/Dictionary.h"
#include "thermal/HeatTransferModel.h"

namespace sphcast {

// Radiation to the surroundings through each particle's exposed area, Stefan-Boltzmann,
// eq. (16) with the physical law:
//
//   du_i/dt = -beta sigma A_i (T_i^4 - T_atm^4) / m_i,
//
// beta the material's emissivity, sigma = 5.670374419e-8 W/m^2/K^4. The paper prints
// (T_i - T_atm)^4, which is not the law (it radiates as much to a hotter surrounding as to a
// colder one, doc/physics.md §10.2.3). A_i from sph/ExposedArea.h.
//
// constant/physicsModels:
//   heatTransfer { radiation { T 300; materials (iron); } }   // materials: optional, default
//                                                              // every heat cloud's material
// Clouds held at a fixed temperature do not radiate.
//
// Step limit: as AtmosphereTransfer's with the linearised coefficient 4 beta sigma T_i^3.
class RadiationTransfer : public HeatTransferModel {
 public:
  static constexpr double stefanBoltzmann = 5.670374419e-8;

  RadiationTransfer(const HeatTransferContext& context, const Dictionary& dict);

  const char* name() const override { return "radiation"; }
  bool readsExposedAreaOf(std::size_t cloud) const override {
    return emissivityOfCloud_[cloud] != 0 && !context_.clouds[cloud].fixedTemperature;
  }
  std::string description() const override;
  void addEnergyRates() override;
  std::vector<double> powerLeaving() const override { return powerLeaving_; }
  double stableDeltaT() const override;

 private:
  const HeatTransferContext& context_;
  double surroundingTemperature_;
  std::vector<double> emissivityOfCloud_;  // 0: does not radiate
  std::vector<double> powerLeaving_;       // W, by cloud
};

}  // namespace sphcast
