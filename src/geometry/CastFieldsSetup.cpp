#include "geometry/CastFieldsSetup.h"

#include <cmath>
#include <sstream>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "geometry/LatticeFill.h"

namespace sphcast {

namespace {

constexpr double defaultMaxParticles = 2e7;

struct BoxRegion {
  Vector lower;
  Vector upper;
};

BoxRegion readBox(const Dictionary& region) {
  region.checkKeys({"type", "min", "max"});
  region.getChoice("type", {"box"});
  const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};
  BoxRegion box{region.get<Vector>("min", length), region.get<Vector>("max", length)};
  if ((box.upper - box.lower).minCoeff() < 0) {
    throw DictionaryError(region.location("max"),
                          "box 'max' is below 'min' on some axis in " + region.name());
  }
  return box;
}

void setInitialFields(const Dictionary& fields, ParticleCloud& cloud) {
  fields.checkKeys({"U", "T", "rho"});
  if (fields.found("U")) {
    const Vector velocity = fields.get<Vector>("U", Dimensions{{0, 1, -1, 0, 0, 0, 0}});
    for (Vector& u : cloud.vectorField("U")) u = velocity;
  }
  const std::pair<const char*, Dimensions> scalars[] = {{"T", {{0, 0, 0, 1, 0, 0, 0}}},
                                                        {"rho", {{1, -3, 0, 0, 0, 0, 0}}}};
  for (const auto& [fieldName, dimensions] : scalars) {
    if (!fields.found(fieldName)) continue;
    const double value = fields.get<double>(fieldName, dimensions);
    if (!(value > 0.0)) {
      throw DictionaryError(fields.location(fieldName),
                            "'" + std::string(fieldName) + "' must be positive in " + fields.name());
    }
    auto& field = cloud.addScalarField(fieldName);
    for (Real& x : field) x = static_cast<Real>(value);
  }
}

}  // namespace

std::vector<ParticleCloud> buildCastClouds(const CaseFolder& caseFolder) {
  const Dictionary dict = Dictionary::read(caseFolder.systemFile("setCastFieldsDict"));
  dict.checkKeys({"spacing", "maxParticles", "clouds"});
  const double spacing = dict.get<double>("spacing", Dimensions{{0, 1, 0, 0, 0, 0, 0}});
  if (!(spacing > 0.0)) {
    throw DictionaryError(dict.location("spacing"), "'spacing' must be positive in " + dict.name());
  }
  const double maxParticles = dict.getOrDefault<double>("maxParticles", defaultMaxParticles);
  const Dictionary& cloudsDict = dict.subDict("clouds");

  // Count first: a spacing that makes 10^9 particles is refused before any memory is taken.
  double total = 0.0;
  std::vector<std::pair<std::string, std::vector<BoxRegion>>> plan;
  for (const std::string& cloudName : cloudsDict.keys()) {
    const Dictionary& cloudDict = cloudsDict.subDict(cloudName);
    cloudDict.checkKeys({"regions", "fields"});
    const Dictionary& regions = cloudDict.subDict("regions");
    std::vector<BoxRegion> boxes;
    for (const std::string& regionName : regions.keys()) {
      boxes.push_back(readBox(regions.subDict(regionName)));
      total += latticeCountInBox(boxes.back().lower, boxes.back().upper, spacing);
    }
    plan.emplace_back(cloudName, std::move(boxes));
  }
  if (total > maxParticles) {
    std::ostringstream message;
    message << "spacing " << spacing << " m would make " << total << " particles, more than "
            << "maxParticles " << maxParticles << " (raise maxParticles in " << dict.name()
            << " if you mean it)";
    throw DictionaryError(dict.location("spacing"), message.str());
  }

  std::vector<ParticleCloud> clouds;
  for (const auto& [cloudName, boxes] : plan) {
    ParticleCloud cloud(cloudName);
    cloud.addVectorField("U");
    cloud.addIdField("id");
    for (const BoxRegion& box : boxes) {
      const auto centres = fillBoxOnLattice(box.lower, box.upper, spacing);
      const std::size_t first = cloud.size();
      cloud.resize(first + centres.size());
      std::copy(centres.begin(), centres.end(), cloud.positions().begin() + static_cast<long>(first));
    }
    auto& id = cloud.idField("id");
    for (std::size_t i = 0; i < id.size(); ++i) id[i] = static_cast<std::int64_t>(i);
    cloud.attributes()["spacing"] = spacing;
    const Dictionary& cloudDict = cloudsDict.subDict(cloudName);
    if (cloudDict.found("fields")) setInitialFields(cloudDict.subDict("fields"), cloud);
    clouds.push_back(std::move(cloud));
  }
  return clouds;
}

}  // namespace sphcast
