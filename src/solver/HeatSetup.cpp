#include "solver/HeatSetup.h"

#include <cstdint>
#include <filesystem>
#include <set>

#include "core/Error.h"
#include "solver/FlowSetup.h"

namespace sphcast {

namespace {
const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};
const Dimensions temperature{{0, 0, 0, 1, 0, 0, 0}};
}  // namespace

const Material& HeatSetup::materialOf(const std::string& cloud) const {
  return materials->get(materialOfCloud.at(cloud), materialNamedAt.at(cloud), "material");
}

HeatSetup readHeatSetup(const CaseFolder& caseFolder) {
  HeatSetup setup;
  const auto modelsFile = caseFolder.constantFile("physicsModels");
  if (!std::filesystem::exists(modelsFile)) return setup;
  const Dictionary models = Dictionary::read(modelsFile);
  if (!models.found("heatTransfer")) return setup;
  setup.enabled = true;
  setup.heatTransfer = models.subDict("heatTransfer");
  const Dictionary& heat = setup.heatTransfer;
  setup.clouds = heat.get<std::vector<std::string>>("clouds");
  setup.cloudsAt = heat.location("clouds");
  if (setup.clouds.empty()) {
    throw DictionaryError(setup.cloudsAt, "'clouds' in " + heat.name() + " names no cloud");
  }
  std::set<std::string> unique;
  for (const std::string& cloud : setup.clouds) {
    if (!unique.insert(cloud).second) {
      throw DictionaryError(setup.cloudsAt,
                            "'clouds' in " + heat.name() + " names '" + cloud + "' twice");
    }
  }
  if (heat.found("fixedTemperature")) {
    // a key is a heat cloud (held whole) or a patch of one, as constant/particles/patches
    // numbers the mold's patches (particleizeMold writes it)
    std::map<std::string, std::pair<std::string, std::int64_t>> patchOf;  // name -> (cloud, id)
    const auto patchesFile = caseFolder.constant() / "particles" / "patches";
    if (std::filesystem::exists(patchesFile)) {
      const Dictionary patches = Dictionary::read(patchesFile);
      for (const std::string& name : patches.keys()) {
        if (!patches.isDict(name)) continue;
        const Dictionary& patch = patches.subDict(name);
        const auto cloud = patch.get<std::string>("cloud");
        if (unique.contains(cloud)) patchOf[name] = {cloud, patch.get<std::int64_t>("id")};
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
      if (unique.contains(key)) {
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
  std::optional<Dictionary> mapping;
  if (models.found("materials")) mapping = models.subDict("materials");
  for (const std::string& cloud : setup.clouds) {
    if (mapping && mapping->found(cloud)) {
      setup.materialOfCloud[cloud] = mapping->get<std::string>(cloud);
      setup.materialNamedAt[cloud] = mapping->location(cloud);
    } else {
      setup.materialOfCloud[cloud] = cloud;
      setup.materialNamedAt[cloud] = setup.cloudsAt;
    }
  }
  setup.dimension = models.getOrDefault<int>("dimension", 3);
  setup.materials = MaterialLibrary::read(caseFolder.constantFile("physicalProperties"));
  for (const std::string& cloud : setup.clouds) setup.materialOf(cloud);  // fail now, not later
  const Dictionary schemes = Dictionary::read(caseFolder.systemFile("sphSchemes"));
  setup.supportRadius = schemes.get<Real>("supportRadius", length);
  if (!(setup.supportRadius > 0)) {
    throw DictionaryError(schemes.location("supportRadius"),
                          "'supportRadius' must be positive in " + schemes.name());
  }
  if (models.found("periodic")) {
    setup.periodic =
        readPeriodicBox(models.subDict("periodic"), setup.supportRadius, setup.dimension);
  }
  return setup;
}

}  // namespace sphcast
