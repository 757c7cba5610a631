#include "thermal/HeatSetup.h"

#include <cmath>
#include <cstdint>
#include <filesystem>

#include "core/Error.h"

namespace sphcast {

namespace {
const Dimensions temperature{{0, 0, 0, 1, 0, 0, 0}};
}  // namespace

HeatSetup readHeatSetup(const CaseDescription& description) {
  HeatSetup setup;
  const Dictionary* heatEntry = description.modelsEntry("heatTransfer");
  if (!heatEntry) return setup;
  setup.enabled = true;
  setup.heatTransfer = *heatEntry;
  const Dictionary& heat = setup.heatTransfer;
  setup.clouds = description.heatClouds();
  if (heat.found("fixedTemperature")) {
    // a key is a heat cloud (held whole) or a patch of one, as constant/particles/patches
    // numbers the mold's patches (particleizeMold writes it)
    std::map<std::string, std::pair<std::string, std::int64_t>> patchOf;  // name -> (cloud, id)
    const auto patchesFile = description.folder().constant() / "particles" / "patches";
    if (std::filesystem::exists(patchesFile)) {
      const Dictionary patches = Dictionary::read(patchesFile);
      for (const std::string& name : patches.keys()) {
        if (!patches.isDict(name)) continue;
        const Dictionary& patch = patches.subDict(name);
        const auto cloud = patch.get<std::string>("cloud");
        if (description.carriesHeat(cloud)) patchOf[name] = {cloud, patch.get<std::int64_t>("id")};
      }
    }
    const Dictionary& fixed = heat.subDict("fixedTemperature");
    std::vector<std::string> valid = setup.clouds;
    for (const auto& entry : patchOf) valid.push_back(entry.first);
    fixed.checkKeys(valid);  // "did you mean", listing the heat clouds and their patches
    for (const std::string& key : fixed.keys()) {
      const double T = fixed.get<double>(key, temperature);
      if (!(T > 0) || !std::isfinite(T)) {
        throw DictionaryError(fixed.location(key), "the fixed temperature of '" + key + "' in " +
                                                       fixed.name() + " must be positive (K)");
      }
      if (description.carriesHeat(key)) {
        setup.fixedTemperature[key] = T;
      } else {
        const auto& [cloud, id] = patchOf.at(key);
        setup.heldPatches[cloud].emplace_back(id, T);
        setup.heldPatchNames[cloud].push_back(key);
      }
    }
  }
  setup.heatEveryFlowStep =
      heat.getChoiceOrDefault("interval", {"auto", "everyStep"}, "auto") == "everyStep";
  // fail now, not later: the clouds' materials, h and the periodic axes
  for (const std::string& cloud : setup.clouds) description.heatCloudMaterial(cloud);
  description.supportRadius();
  description.periodic();
  return setup;
}

}  // namespace sphcast
