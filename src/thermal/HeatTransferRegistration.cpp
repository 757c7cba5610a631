#include "thermal/HeatTransferRegistration.h"

#include "core/Error.h"
#include "thermal/AtmosphereTransfer.h"
#include "thermal/HeatConduction.h"
#include "thermal/MoldContactTransfer.h"
#include "thermal/RadiationTransfer.h"

namespace sphcast {

namespace {

// Whether `key` switches a path on: a sub-dictionary or `on`.
bool switchedOn(const Dictionary& heatTransfer, const std::string& key) {
  if (!heatTransfer.found(key)) return false;
  if (heatTransfer.isDict(key)) return true;
  return heatTransfer.getChoice(key, {"on", "off"}) == "on";
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

}  // namespace

std::vector<std::string> heatTransferKeys() {
  return {"clouds",     "fixedTemperature", "conduction",  "moldContact",
          "atmosphere", "radiation",        "exposedArea", "interval"};
}

std::vector<std::unique_ptr<HeatTransferModel>> buildHeatTransferPaths(
    const HeatTransferContext& context, const Dictionary& heatTransfer, bool& needsExposedArea) {
  heatTransfer.checkKeys(heatTransferKeys());
  std::vector<std::unique_ptr<HeatTransferModel>> paths;
  needsExposedArea = false;
  std::set<std::pair<std::string, std::string>> contactPairs;
  std::unique_ptr<MoldContactTransfer> contact;
  if (switchedOn(heatTransfer, "moldContact")) {
    contact = std::make_unique<MoldContactTransfer>(
        context, settingsOf(heatTransfer, "moldContact", "coefficients ((AC4CH iron 150));"));
    contactPairs = contact->materialPairs();
  }
  if (switchedOn(heatTransfer, "conduction")) {
    paths.push_back(std::make_unique<HeatConduction>(context, contactPairs));
  }
  if (contact) paths.push_back(std::move(contact));
  if (switchedOn(heatTransfer, "atmosphere")) {
    paths.push_back(std::make_unique<AtmosphereTransfer>(
        context, settingsOf(heatTransfer, "atmosphere", "T 300; coefficients ((iron 80));")));
    needsExposedArea = true;
  }
  if (switchedOn(heatTransfer, "radiation")) {
    paths.push_back(std::make_unique<RadiationTransfer>(
        context, settingsOf(heatTransfer, "radiation", "T 300;")));
    needsExposedArea = true;
  }
  return paths;
}

}  // namespace sphcast
