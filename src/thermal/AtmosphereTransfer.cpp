#include "thermal/AtmosphereTransfer.h"

#include <cmath>
#include <set>
#include <sstream>
#include <tuple>

#include "core/Error.h"
#include "thermal/SurfaceLoss.h"

namespace sphcast {

namespace {
const Dimensions temperature{{0, 0, 0, 1, 0, 0, 0}};
const Dimensions heatTransferCoefficient{{1, 0, -3, -1, 0, 0, 0}};
}  // namespace

AtmosphereTransfer::AtmosphereTransfer(const HeatTransferContext& context, const Dictionary& dict)
    : context_(context), coefficientOfCloud_(context.clouds.size(), 0.0) {
  dict.checkKeys({"T", "coefficients"});
  airTemperature_ = dict.get<double>("T", temperature);
  if (!(airTemperature_ > 0)) {
    throw DictionaryError(dict.location("T"), "'T' (K) must be positive in " + dict.name());
  }
  using Row = std::tuple<std::string, double>;
  const auto rows = dict.get<std::vector<Row>>("coefficients", heatTransferCoefficient);
  for (const auto& [material, omega] : rows) {
    if (!(omega >= 0) || !std::isfinite(omega)) {
      throw DictionaryError(dict.location("coefficients"), "the coefficient of " + material +
                                                               " in " + dict.name() +
                                                               " must not be negative (W/m^2/K)");
    }
    for (const std::size_t c : cloudsOfMaterial(context_, material, dict, "coefficients")) {
      coefficientOfCloud_[c] = omega;
      context_.clouds[c].material->requireInternalEnergy("heatTransfer atmosphere");
    }
  }
}

std::string AtmosphereTransfer::description() const {
  std::ostringstream line;
  line << "atmosphere (eq. 15) at " << airTemperature_ << " K:";
  for (std::size_t c = 0; c < context_.clouds.size(); ++c) {
    line << " " << context_.clouds[c].cloud->name() << " " << coefficientOfCloud_[c];
  }
  line << " W/m^2/K";
  return line.str();
}

void AtmosphereTransfer::addEnergyRates() {
  const double air = airTemperature_;
  powerLeaving_ =
      addSurfaceLoss(context_, coefficientOfCloud_, [air](double T) { return T - air; });
}

double AtmosphereTransfer::stableDeltaT() const {
  return surfaceLossStableDeltaT(context_, coefficientOfCloud_, [](double) { return 1.0; });
}

}  // namespace sphcast
