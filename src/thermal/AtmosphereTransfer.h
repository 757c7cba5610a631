#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/dictionary/Dictionary.h"
#include "thermal/HeatTransferModel.h"

namespace sphcast {

// Newton cooling to the surrounding air through each particle's exposed area, eq. (15):
//
//   du_i/dt = -omega_a A_i (T_i - T_atm) / m_i,
//
// A_i from sph/ExposedArea.h (eq. (11), calibrated so that a flat surface counts its area).
//
// constant/physicsModels:
//   heatTransfer { atmosphere { T 300; coefficients ((iron 80) (AC4CH 10)); } }  // W/m^2/K
// Clouds whose material is not listed exchange no heat with the air; clouds held at a fixed
// temperature neither.
//
// Step limit: dt <= 0.25 m_i c_min / (omega_a A_i), over the particles of the step.
class AtmosphereTransfer : public HeatTransferModel {
 public:
  AtmosphereTransfer(const HeatTransferContext& context, const Dictionary& dict);

  const char* name() const override { return "atmosphere"; }
  bool readsExposedAreaOf(std::size_t cloud) const override {
    return coefficientOfCloud_[cloud] != 0 && !context_.clouds[cloud].fixedTemperature;
  }
  std::string description() const override;
  void addEnergyRates() override;
  std::vector<double> powerLeaving() const override { return powerLeaving_; }
  double stableDeltaT() const override;

 private:
  const HeatTransferContext& context_;
  double airTemperature_;
  std::vector<double> coefficientOfCloud_;  // W/m^2/K, 0: none
  std::vector<double> powerLeaving_;        // W, by cloud
};

}  // namespace sphcast
