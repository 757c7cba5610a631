#include "solver/HeatSetup.h"

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
    const Dictionary& fixed = heat.subDict("fixedTemperature");
    fixed.checkKeys(setup.clouds);  // "did you mean", listing the heat clouds
    for (const std::string& cloud : fixed.keys()) {
      const double T = fixed.get<double>(cloud, temperature);
      if (!(T > 0) || !std::isfinite(T)) {
        throw DictionaryError(fixed.location(cloud), "the fixed temperature of '" + cloud +
                                                         "' in " + fixed.name() +
                                                         " must be positive (K)");
      }
      setup.fixedTemperature[cloud] = T;
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
