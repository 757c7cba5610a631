#include "case/CaseDescription.h"

#include <algorithm>
#include <set>
#include <sstream>

#include "core/Error.h"
#include "core/Gravity.h"

namespace sphcast {

namespace {
const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};
const Dimensions speed{{0, 1, -1, 0, 0, 0, 0}};

// The entry `key` of `dict`, of these dimensions, positive; else an error at it with its value.
Real positive(const Dictionary& dict, const std::string& key, const Dimensions& dimensions) {
  const Real value = dict.get<Real>(key, dimensions);
  if (!(value > 0)) {
    std::ostringstream message;
    message << "'" << key << "' is " << value << " in " << dict.name()
            << "; it must be positive (valid range: > 0)";
    throw DictionaryError(dict.location(key), message.str());
  }
  return value;
}
}  // namespace

CaseDescription::CaseDescription(const CaseFolder& caseFolder)
    : folder_(caseFolder), gravity_(readGravityIfPresent(caseFolder)) {
  const auto modelsFile = folder_.constantFile("physicsModels");
  if (!std::filesystem::exists(modelsFile)) return;
  hasModels_ = true;
  models_ = Dictionary::read(modelsFile);
  models_.checkKeys({"dimension", "periodic", "materials", "flow", "rheology", "heatTransfer",
                     "surfaceTension", "solidification"});
  dimension_ = models_.getOrDefault<int>("dimension", 3);
  if (dimension_ != 2 && dimension_ != 3) {
    throw DictionaryError(models_.location("dimension"),
                          "'dimension' must be 2 or 3 in " + models_.name());
  }
  if (const Dictionary* flow = modelsEntry("flow")) {
    flow->checkKeys({"model", "fluid", "walls"});
    if (flow->get<std::string>("model") != "none") {
      fluidCloud_ = flow->get<std::string>("fluid");
      // a list of the wall clouds, or a dictionary of them with each wall's own conditions
      if (flow->isDict("walls")) {
        wallClouds_ = flow->subDict("walls").keys();
      } else {
        wallClouds_ = flow->getOrDefault<std::vector<std::string>>("walls", {});
      }
    }
  }
  if (const Dictionary* heat = modelsEntry("heatTransfer")) {
    heatClouds_ = heat->get<std::vector<std::string>>("clouds");
    heatCloudsAt_ = heat->location("clouds");
    if (heatClouds_.empty()) {
      throw DictionaryError(heatCloudsAt_, "'clouds' in " + heat->name() + " names no cloud");
    }
    std::set<std::string> unique;
    for (const std::string& cloud : heatClouds_) {
      if (!unique.insert(cloud).second) {
        throw DictionaryError(heatCloudsAt_,
                              "'clouds' in " + heat->name() + " names '" + cloud + "' twice");
      }
    }
  }
}

const Dictionary* CaseDescription::modelsEntry(std::string_view key) const {
  return models_.found(key) ? &models_.subDict(key) : nullptr;
}

bool CaseDescription::hasSchemes() const {
  return schemes_ || std::filesystem::exists(folder_.systemFile("sphSchemes"));
}

const Dictionary& CaseDescription::schemes() const {
  if (!schemes_) schemes_ = Dictionary::read(folder_.systemFile("sphSchemes"));
  return *schemes_;
}

const MaterialLibrary& CaseDescription::materials() const {
  if (!materials_) materials_ = MaterialLibrary::read(folder_.constantFile("physicalProperties"));
  return *materials_;
}

Real CaseDescription::supportRadius() const { return positive(schemes(), "supportRadius", length); }

Real CaseDescription::soundSpeed() const { return positive(schemes(), "soundSpeed", speed); }

SourceLocation CaseDescription::supportRadiusAt() const {
  return schemes().location("supportRadius");
}

std::vector<std::pair<std::string, const Dictionary*>> CaseDescription::wallEntries() const {
  std::vector<std::pair<std::string, const Dictionary*>> entries;
  const Dictionary* flow = modelsEntry("flow");
  if (!hasFlow() || !flow->isDict("walls")) return entries;
  const Dictionary& walls = flow->subDict("walls");
  for (const std::string& cloud : wallClouds_) {
    if (!walls.isDict(cloud)) {
      throw DictionaryError(walls.location(cloud),
                            "'" + cloud + "' in " + walls.name() +
                                " must be a dictionary of the wall's conditions ({} for none)");
    }
    const Dictionary& entry = walls.subDict(cloud);
    entry.checkKeys({"wallSlip", "wallDissipation"});
    entries.emplace_back(cloud, &entry);
  }
  return entries;
}

PeriodicBox CaseDescription::periodic() const {
  const Dictionary* periodic = modelsEntry("periodic");
  return periodic ? readPeriodicBox(*periodic, supportRadius(), dimension_) : PeriodicBox();
}

SourceLocation CaseDescription::fluidCloudAt() const {
  return models_.subDict("flow").location("fluid");
}

bool CaseDescription::carriesHeat(const std::string& cloud) const {
  return std::find(heatClouds_.begin(), heatClouds_.end(), cloud) != heatClouds_.end();
}

const Material& CaseDescription::materialOf(const std::string& cloud, const SourceLocation& namedAt,
                                            std::string_view key) const {
  if (const Dictionary* mapping = modelsEntry("materials"); mapping && mapping->found(cloud)) {
    return materials().get(mapping->get<std::string>(cloud), mapping->location(cloud), "materials");
  }
  return materials().get(cloud, namedAt, key);
}

const Material& CaseDescription::heatCloudMaterial(const std::string& cloud) const {
  return materialOf(cloud, heatCloudsAt_, "clouds");
}

const Material& CaseDescription::fluidMaterial() const {
  return materialOf(fluidCloud_, fluidCloudAt(), "fluid");
}

}  // namespace sphcast
