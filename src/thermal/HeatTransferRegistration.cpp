#include "thermal/HeatTransferRegistration.h"

#include <set>
#include <utility>

#include "core/Error.h"
#include "thermal/AtmosphereTransfer.h"
#include "thermal/HeatConduction.h"
#include "thermal/MoldContactTransfer.h"
#include "thermal/RadiationTransfer.h"

namespace sphcast {

namespace {

// Whether `key` switches a path on: a sub-dictionary or a switch (on, yes, true).
bool switchedOn(const Dictionary& heatTransfer, const std::string& key) {
  if (!heatTransfer.found(key)) return false;
  if (heatTransfer.isDict(key)) return true;
  return heatTransfer.get<bool>(key);
}

// A path whose coefficients must be given: `on` alone is not enough.
const Dictionary& settingsOf(const Dictionary& heatTransfer, const std::string& key,
                             const std::string& example) {
  if (!heatTransfer.isDict(key)) {
    throw DictionaryError(heatTransfer.location(key),
                          "'" + key + "' in " + heatTransfer.name() +
                              " needs its settings as a sub-dictionary, e.g. " + key + " { " +
                              example + " }");
  }
  return heatTransfer.subDict(key);
}

const char* const contactExample = "coefficients ((AC4CH iron 150));";

}  // namespace

HeatTransferPaths& heatTransferPaths() {
  static HeatTransferPaths paths = [] {
    HeatTransferPaths registry("heat path");
    registry.add("conduction",
                 [](const HeatTransferContext& context, const Dictionary& heatTransfer) {
                   // between the materials moldContact joins, the exchange is the contact's
                   std::set<std::pair<std::string, std::string>> contactPairs;
                   if (switchedOn(heatTransfer, "moldContact")) {
                     for (const auto& entry : MoldContactTransfer::readCoefficients(
                              context, settingsOf(heatTransfer, "moldContact", contactExample))) {
                       contactPairs.insert(entry.first);
                     }
                   }
                   return std::make_unique<HeatConduction>(context, std::move(contactPairs));
                 });
    registry.add("moldContact",
                 [](const HeatTransferContext& context, const Dictionary& heatTransfer) {
                   return std::make_unique<MoldContactTransfer>(
                       context, settingsOf(heatTransfer, "moldContact", contactExample));
                 });
    registry.add(
        "atmosphere", [](const HeatTransferContext& context, const Dictionary& heatTransfer) {
          return std::make_unique<AtmosphereTransfer>(
              context, settingsOf(heatTransfer, "atmosphere", "T 300; coefficients ((iron 80));"));
        });
    registry.add("radiation",
                 [](const HeatTransferContext& context, const Dictionary& heatTransfer) {
                   return std::make_unique<RadiationTransfer>(
                       context, settingsOf(heatTransfer, "radiation", "T 300;"));
                 });
    return registry;
  }();
  return paths;
}

std::vector<std::string> heatTransferKeys() {
  std::vector<std::string> keys{"clouds", "fixedTemperature"};
  for (const std::string& path : heatTransferPaths().names()) keys.push_back(path);
  keys.insert(keys.end(), {"exposedArea", "interval"});
  return keys;
}

std::vector<std::unique_ptr<HeatTransferModel>> buildHeatTransferPaths(
    const HeatTransferContext& context, const Dictionary& heatTransfer, bool& needsExposedArea) {
  heatTransfer.checkKeys(heatTransferKeys());
  std::vector<std::unique_ptr<HeatTransferModel>> paths;
  needsExposedArea = false;
  for (const std::string& name : heatTransferPaths().names()) {
    if (!switchedOn(heatTransfer, name)) continue;
    paths.push_back(heatTransferPaths().build(name, context, heatTransfer));
    for (std::size_t c = 0; c < context.clouds.size(); ++c) {
      needsExposedArea = needsExposedArea || paths.back()->readsExposedAreaOf(c);
    }
  }
  return paths;
}

}  // namespace sphcast
