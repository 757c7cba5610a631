#include "castAnalysis/HotSpots.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <sstream>

#include "core/AtomicFile.h"
#include "core/Log.h"
#include "particles/CellGrid.h"
#include "particles/FieldNames.h"
#include "particles/NeighbourList.h"
#include "sph/ParticleVolumes.h"

namespace sphcast {

namespace {

// Union-find with path halving.
std::size_t root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

HotSpots::HotSpots(const std::string& name, const Dictionary& dict, const AnalysisContext& context)
    : CastAnalysis(name, dict, context, {"cloud", "feedingSolidFraction"}) {
  cloud_ = readCloud();
  feeding_ = dict.getOrDefault<double>("feedingSolidFraction", 0.5);
  if (!(feeding_ > 0 && feeding_ <= 1)) {
    throw DictionaryError(dict.location("feedingSolidFraction"),
                          "'feedingSolidFraction' must lie in (0, 1] in " + dict.name());
  }
}

void HotSpots::add(const WrittenTime& time) {
  const ParticleCloud* metal = time.find(cloud_);
  if (!metal || !metal->hasScalarField(field::solidFraction) || !metal->hasIdField(field::id))
    return;
  const auto spacing = metal->attributes().find("spacing");
  if (spacing == metal->attributes().end()) return;
  const auto& fs = metal->scalarField(field::solidFraction);
  const auto& ids = metal->idField(field::id);
  std::vector<std::size_t> feeding;
  std::vector<Vector> positions;
  for (std::size_t i = 0; i < metal->size(); ++i) {
    if (fs[i] < feeding_) {
      feeding.push_back(i);
      positions.push_back(metal->positions()[i]);
    }
  }
  const double t = time.folder.value;
  std::vector<std::vector<std::size_t>> regions;  // indices into feeding, largest first
  if (!feeding.empty()) {
    CellGrid grid(Real(1.5 * spacing->second));
    grid.build(positions);
    NeighbourList list;
    list.buildWithin(positions, grid);
    std::vector<std::size_t> parent(feeding.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    for (std::size_t a = 0; a < feeding.size(); ++a) {
      for (const std::uint32_t b : list.of(a)) parent[root(parent, a)] = root(parent, b);
    }
    std::map<std::size_t, std::vector<std::size_t>> byRoot;
    for (std::size_t a = 0; a < feeding.size(); ++a) byRoot[root(parent, a)].push_back(a);
    for (auto& [r, members] : byRoot) regions.push_back(std::move(members));
    std::sort(regions.begin(), regions.end(),
              [](const auto& x, const auto& y) { return x.size() > y.size(); });
  }
  const std::vector<Real> volumes = particleVolumes(*metal, context_.dimension);
  const auto volumeOf = [&](const std::vector<std::size_t>& members, Vector& centroid) {
    double volume = 0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const std::size_t a : members) {
      const std::size_t i = feeding[a];
      volume += double(volumes[i]);
      sum += metal->positions()[i].cast<double>();
    }
    centroid = (sum / double(members.size())).cast<Real>();
    return volume;
  };
  // isolated regions: every one but the largest; matched to the hot spots of the last write
  std::vector<std::size_t> seen;
  double isolatedVolume = 0;
  for (std::size_t r = 1; r < regions.size(); ++r) {
    std::set<std::int64_t> regionIds;
    for (const std::size_t a : regions[r]) regionIds.insert(ids[feeding[a]]);
    Vector centroid;
    const double volume = volumeOf(regions[r], centroid);
    isolatedVolume += volume;
    std::size_t match = spots_.size();
    for (const std::size_t s : open_) {
      const auto& known = spots_[s].ids;
      if (std::any_of(regionIds.begin(), regionIds.end(),
                      [&](std::int64_t id) { return known.contains(id); })) {
        match = s;
        break;
      }
    }
    if (match == spots_.size()) {
      Spot spot;
      spot.closedAfter = previousTime_ < 0 ? t : previousTime_;
      spot.closedBy = t;
      spot.volume = volume;
      spot.centroid = centroid;
      spot.particles = regions[r].size();
      spots_.push_back(spot);
    }
    spots_[match].ids = std::move(regionIds);
    spots_[match].lastSeen = t;
    if (std::find(seen.begin(), seen.end(), match) == seen.end()) seen.push_back(match);
  }
  open_ = seen;
  if (!feeding.empty()) {
    lastFeedingTime_ = t;
    lastFeedingParticles_ = feeding.size();
    std::vector<std::size_t> all(feeding.size());
    std::iota(all.begin(), all.end(), std::size_t(0));
    volumeOf(all, lastFeedingCentroid_);
  }
  if (rows_.empty()) rows_ = "time,feedingParticles,regions,isolated,isolatedVolume\n";
  rows_ += formatNumber(t, 12) + "," + std::to_string(feeding.size()) + "," +
           std::to_string(regions.size()) + "," +
           std::to_string(regions.empty() ? 0 : regions.size() - 1) + "," +
           formatNumber(isolatedVolume, 10) + "\n";
  previousTime_ = t;
}

ReportSection HotSpots::finish() {
  const auto out = folder();
  writeFileAtomically(out / "hotSpots.csv", rows_);
  std::ostringstream list;
  list << "hotSpot,closedAfter,closedBy,particles,volume,centroidX,centroidY,centroidZ,lastSeen\n";
  for (std::size_t s = 0; s < spots_.size(); ++s) {
    const Spot& spot = spots_[s];
    list << s + 1 << ',' << formatNumber(spot.closedAfter, 10) << ','
         << formatNumber(spot.closedBy, 10) << ',' << spot.particles << ','
         << formatNumber(spot.volume, 10) << ',' << formatNumber(spot.centroid.x(), 8) << ','
         << formatNumber(spot.centroid.y(), 8) << ',' << formatNumber(spot.centroid.z(), 8) << ','
         << formatNumber(spot.lastSeen, 10) << '\n';
  }
  writeFileAtomically(out / "hotSpotList.csv", list.str());
  info() << "    " << name_ << ": wrote " << (out / "hotSpots.csv").string() << " and "
         << (out / "hotSpotList.csv").string() << '\n';
  std::ostringstream text;
  const double unit = context_.dimension == 2 ? 1e6 : 1e6;
  const char* unitName = context_.dimension == 2 ? "mm^2" : "cm^3";
  text << spots_.size() << " isolated liquid region" << (spots_.size() == 1 ? "" : "s")
       << " (below f_s " << feeding_ << ", cut off from the largest region) seen at the "
       << "written times.\n";
  if (!spots_.empty()) {
    const auto worst =
        std::max_element(spots_.begin(), spots_.end(),
                         [](const Spot& a, const Spot& b) { return a.volume < b.volume; });
    text << "- The largest: " << formatNumber(worst->volume * unit, 4) << ' ' << unitName << " ("
         << worst->particles << " particles) at " << formatPoint(worst->centroid)
         << ", cut off between " << formatNumber(worst->closedAfter, 5) << " and "
         << formatNumber(worst->closedBy, 5) << " s, last seen at "
         << formatNumber(worst->lastSeen, 5) << " s.\n";
  }
  if (lastFeedingTime_ >= 0) {
    text << "- Last feeding metal seen at " << formatNumber(lastFeedingTime_, 5)
         << " s: " << lastFeedingParticles_ << " particles around "
         << formatPoint(lastFeedingCentroid_) << ".\n";
  }
  ReportSection section;
  section.markdown = text.str();
  return section;
}

}  // namespace sphcast
