#include "thermal/RadiationTransfer.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.h"
#include "thermal/SurfaceLoss.h"

namespace sphcast {

namespace {
const Dimensions temperature{{0, 0, 0, 1, 0, 0, 0}};
}  // namespace

RadiationTransfer::RadiationTransfer(const HeatTransferContext& context, const Dictionary& dict)
    : context_(context), emissivityOfCloud_(context.clouds.size(), 0.0) {
  dict.checkKeys({"T", "materials"});
  surroundingTemperature_ = dict.get<double>("T", temperature);
  if (!(surroundingTemperature_ > 0)) {
    throw DictionaryError(dict.location("T"), "'T' (K) must be positive in " + dict.name());
  }
  std::vector<std::string> materials;
  if (dict.found("materials")) {
    materials = dict.get<std::vector<std::string>>("materials");
  } else {
    for (const HeatCloud& heat : context_.clouds) materials.push_back(heat.material->name);
  }
  for (const std::string& material : materials) {
    for (const std::size_t c : cloudsOfMaterial(context_, material, dict, "materials")) {
      const Material& properties = *context_.clouds[c].material;
      emissivityOfCloud_[c] = properties.requireEmissivity("heatTransfer radiation");
      properties.requireInternalEnergy("heatTransfer radiation");
    }
  }
}

std::string RadiationTransfer::description() const {
  std::ostringstream line;
  line << "radiation (eq. 16, beta sigma (T^4 - T_atm^4)) to " << surroundingTemperature_
       << " K, emissivity:";
  for (std::size_t c = 0; c < context_.clouds.size(); ++c) {
    line << " " << context_.clouds[c].cloud->name() << " " << emissivityOfCloud_[c];
  }
  return line.str();
}

void RadiationTransfer::addEnergyRates() {
  const double surrounding4 = std::pow(surroundingTemperature_, 4);
  powerLeaving_ = addSurfaceLoss(context_, emissivityOfCloud_, [surrounding4](double T) {
    return stefanBoltzmann * (T * T * T * T - surrounding4);
  });
}

double RadiationTransfer::stableDeltaT() const {
  return surfaceLossStableDeltaT(context_, emissivityOfCloud_,
                                 [](double T) { return 4 * stefanBoltzmann * T * T * T; });
}

}  // namespace sphcast
