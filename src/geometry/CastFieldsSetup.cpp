#include "geometry/CastFieldsSetup.h"

#include <cmath>
#include <memory>
#include <sstream>

#include "core/Error.h"
#include "core/Log.h"
#include "core/dictionary/Dictionary.h"
#include "geometry/FillRegion.h"
#include "geometry/LatticeFill.h"
#include "geometry/LatticeSolid.h"
#include "geometry/WallParticles.h"
#include "io/VtpCloud.h"

namespace sphcast {

namespace {

constexpr double defaultMaxParticles = 2e7;
constexpr double defaultWallClearance = 0.75;  // x spacing; see CastFieldsSetup.h
const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};

struct RegionFill {
  std::unique_ptr<FillRegion> region;
  bool ownLattice;  // a top-level box: today's lattice centred in the box
};

struct CloudPlan {
  std::string name;
  std::vector<RegionFill> regions;
};

// Lattice points of the shared lattice inside the region.
std::vector<Vector> fillOnSharedLattice(const FillRegion& region, double spacing) {
  std::vector<Vector> centres;
  const Eigen::Vector3d lower = region.lower(), upper = region.upper();
  for (std::int64_t k = latticeIndex(lower.z(), spacing) - 1; k <= latticeIndex(upper.z(), spacing) + 1; ++k) {
    for (std::int64_t j = latticeIndex(lower.y(), spacing) - 1; j <= latticeIndex(upper.y(), spacing) + 1; ++j) {
      for (std::int64_t i = latticeIndex(lower.x(), spacing) - 1; i <= latticeIndex(upper.x(), spacing) + 1; ++i) {
        const Eigen::Vector3d p(latticeCoordinate(i, spacing), latticeCoordinate(j, spacing),
                                latticeCoordinate(k, spacing));
        if (region.contains(p)) centres.push_back(p.cast<Real>());
      }
    }
  }
  return centres;
}

// Sets U, T, rho on the particles where `selected` is true (all when it is empty).
void setFieldValues(const Dictionary& fields, ParticleCloud& cloud, const std::vector<bool>& selected) {
  fields.checkKeys({"U", "T", "rho"});
  auto chosen = [&](std::size_t i) { return selected.empty() || selected[i]; };
  if (fields.found("U")) {
    const Vector velocity = fields.get<Vector>("U", Dimensions{{0, 1, -1, 0, 0, 0, 0}});
    auto& u = cloud.addVectorField("U");
    for (std::size_t i = 0; i < u.size(); ++i) {
      if (chosen(i)) u[i] = velocity;
    }
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
    for (std::size_t i = 0; i < field.size(); ++i) {
      if (chosen(i)) field[i] = static_cast<Real>(value);
    }
  }
}

// Positions of every mold particle written by particleizeMold (none when there are none).
std::vector<Eigen::Vector3d> moldParticlePositions(const CaseFolder& caseFolder) {
  std::vector<Eigen::Vector3d> positions;
  const auto folder = caseFolder.constantFile("particles");
  if (!std::filesystem::is_directory(folder)) return positions;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".vtp") continue;
    const ParticleCloud cloud = readCloudVtp(entry.path(), entry.path().stem().string());
    for (const Vector& p : cloud.positions()) positions.push_back(p.cast<double>());
  }
  return positions;
}

ParticleCloud fillCloud(const CloudPlan& plan, double spacing,
                        const std::vector<Eigen::Vector3d>& moldParticles, double clearance) {
  std::vector<Vector> centres;
  for (const auto& fill : plan.regions) {
    const auto more = fill.ownLattice
                          ? fillBoxOnLattice(fill.region->lower().cast<Real>(),
                                             fill.region->upper().cast<Real>(), spacing)
                          : fillOnSharedLattice(*fill.region, spacing);
    centres.insert(centres.end(), more.begin(), more.end());
  }
  std::size_t removed = 0;
  if (!moldParticles.empty()) {
    std::vector<Eigen::Vector3d> points;
    points.reserve(centres.size());
    for (const Vector& c : centres) points.push_back(c.cast<double>());
    const auto close = closerThan(points, moldParticles, clearance);
    std::vector<Vector> kept;
    for (std::size_t i = 0; i < centres.size(); ++i) {
      if (!close[i]) kept.push_back(centres[i]);
    }
    removed = centres.size() - kept.size();
    centres = std::move(kept);
  }
  ParticleCloud cloud(plan.name);
  cloud.resize(centres.size());
  std::copy(centres.begin(), centres.end(), cloud.positions().begin());
  cloud.addVectorField("U");
  auto& volume = cloud.addScalarField("volume");
  for (Real& v : volume) v = static_cast<Real>(spacing * spacing * spacing);
  auto& id = cloud.addIdField("id");
  for (std::size_t i = 0; i < id.size(); ++i) id[i] = static_cast<std::int64_t>(i);
  cloud.attributes()["spacing"] = spacing;
  if (!moldParticles.empty()) {
    info() << "Cloud " << plan.name << ": left out " << removed
           << " particles closer than wallClearance " << clearance << " m to a mold particle\n";
  }
  return cloud;
}

}  // namespace

std::vector<ParticleCloud> buildCastClouds(const CaseFolder& caseFolder) {
  const Dictionary dict = Dictionary::read(caseFolder.systemFile("setCastFieldsDict"));
  dict.checkKeys({"spacing", "maxParticles", "wallClearance", "clouds", "setFields"});
  const double spacing = dict.get<double>("spacing", length);
  if (!(spacing > 0.0)) {
    throw DictionaryError(dict.location("spacing"), "'spacing' must be positive in " + dict.name());
  }
  const double maxParticles = dict.getOrDefault<double>("maxParticles", defaultMaxParticles);
  const double clearance = dict.found("wallClearance") ? dict.get<double>("wallClearance", length)
                                                       : defaultWallClearance * spacing;
  const auto geometryFolder = caseFolder.constant() / "geometry";
  const Dictionary noClouds;
  const Dictionary& cloudsDict = dict.found("clouds") ? dict.subDict("clouds") : noClouds;

  // Read every region and count first: a spacing that makes 10^9 particles is refused before
  // any memory is taken.
  double total = 0.0;
  std::vector<CloudPlan> plans;
  for (const std::string& cloudName : cloudsDict.keys()) {
    const Dictionary& cloudDict = cloudsDict.subDict(cloudName);
    cloudDict.checkKeys({"regions", "fields"});
    const Dictionary& regions = cloudDict.subDict("regions");
    CloudPlan plan{cloudName, {}};
    for (const std::string& regionName : regions.keys()) {
      const Dictionary& regionDict = regions.subDict(regionName);
      RegionFill fill{readFillRegion(regionDict, spacing, geometryFolder),
                      regionDict.get<std::string>("type") == "box"};
      total += fill.ownLattice ? latticeCountInBox(fill.region->lower().cast<Real>(),
                                                   fill.region->upper().cast<Real>(), spacing)
                               : fill.region->volumeBound() / (spacing * spacing * spacing);
      plan.regions.push_back(std::move(fill));
    }
    plans.push_back(std::move(plan));
  }
  if (total > maxParticles) {
    std::ostringstream message;
    message << "spacing " << spacing << " m would make " << total << " particles, more than "
            << "maxParticles " << maxParticles << " (raise maxParticles in " << dict.name()
            << " if you mean it)";
    throw DictionaryError(dict.location("spacing"), message.str());
  }

  const auto moldParticles = moldParticlePositions(caseFolder);
  std::vector<ParticleCloud> clouds;
  for (const CloudPlan& plan : plans) {
    ParticleCloud cloud = fillCloud(plan, spacing, moldParticles, clearance);
    const Dictionary& cloudDict = cloudsDict.subDict(plan.name);
    if (cloudDict.found("fields")) setFieldValues(cloudDict.subDict("fields"), cloud, {});
    clouds.push_back(std::move(cloud));
  }

  // Fields on existing clouds, as OpenFOAM's setFields: all particles, or those in regions.
  if (dict.found("setFields")) {
    const Dictionary& setFields = dict.subDict("setFields");
    for (const std::string& cloudName : setFields.keys()) {
      const Dictionary& entry = setFields.subDict(cloudName);
      entry.checkKeys({"fields", "regions"});
      const auto file = caseFolder.constantFile("particles") / (cloudName + ".vtp");
      if (!std::filesystem::is_regular_file(file)) {
        throw DictionaryError(setFields.location(cloudName),
                              "cloud '" + cloudName + "' has no file '" + file.string() +
                                  "' (run particleizeMold first)");
      }
      ParticleCloud cloud = readCloudVtp(file, cloudName);
      std::vector<bool> selected;
      if (entry.found("regions")) {
        const Dictionary& regions = entry.subDict("regions");
        selected.assign(cloud.size(), false);
        for (const std::string& regionName : regions.keys()) {
          const auto region = readFillRegion(regions.subDict(regionName), spacing, geometryFolder);
          for (std::size_t i = 0; i < cloud.size(); ++i) {
            selected[i] = selected[i] || region->contains(cloud.positions()[i].cast<double>());
          }
        }
      }
      setFieldValues(entry.subDict("fields"), cloud, selected);
      clouds.push_back(std::move(cloud));
    }
  }
  return clouds;
}

}  // namespace sphcast
