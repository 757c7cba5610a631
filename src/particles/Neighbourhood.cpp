#include "particles/Neighbourhood.h"

#include "core/Error.h"

namespace sphcast {

Neighbourhood::Neighbourhood(Real radius, const PeriodicBox& periodic)
    : radius_(radius), periodic_(periodic) {}

void Neighbourhood::addCloud(ParticleCloud& cloud, Motion motion) {
  if (has(cloud)) {
    Entry& entry = entries_[entryOf(cloud)];
    if (motion == Motion::rigid && !entry.movable) entry.moves = true;
    return;
  }
  Entry entry;
  entry.cloud = &cloud;
  entry.movable = motion == Motion::moving ? &cloud : nullptr;
  entry.moves = motion != Motion::fixed;
  entry.grid = std::make_unique<CellGrid>(radius_, periodic_);
  entries_.push_back(std::move(entry));
}

void Neighbourhood::addFixedCloud(const ParticleCloud& cloud) {
  if (has(cloud)) return;
  Entry entry;
  entry.cloud = &cloud;
  entry.grid = std::make_unique<CellGrid>(radius_, periodic_);
  entries_.push_back(std::move(entry));
}

bool Neighbourhood::has(const ParticleCloud& cloud) const {
  for (const Entry& entry : entries_) {
    if (entry.cloud == &cloud) return true;
  }
  return false;
}

std::size_t Neighbourhood::entryOf(const ParticleCloud& cloud) const {
  for (std::size_t e = 0; e < entries_.size(); ++e) {
    if (entries_[e].cloud == &cloud) return e;
  }
  throw Error("neighbourhood: cloud '" + cloud.name() + "' was never registered");
}

void Neighbourhood::requestPairs(const ParticleCloud& a, const ParticleCloud& b) {
  const std::size_t ea = entryOf(a), eb = entryOf(b);
  for (const Pairs& pairs : pairs_) {
    if (pairs.a == ea && pairs.b == eb) return;
  }
  pairs_.push_back({ea, eb, NeighbourList(), false});
}

void Neighbourhood::update(CloudOrder order) {
  for (Entry& entry : entries_) {
    entry.movedNow = !entry.binned;
    if (entry.binned && !entry.moves) continue;  // a fixed cloud's grid stays valid
    if (entry.binned && !entry.movable) {
      // a rigid cloud: re-binned only when it moved (a body held, resting or at its stop
      // keeps its grid and lists)
      if (entry.cloud->positions() == entry.binnedPositions) continue;
      entry.binnedPositions = entry.cloud->positions();
    } else if (entry.moves && !entry.movable) {
      entry.binnedPositions = entry.cloud->positions();
    }
    entry.movedNow = true;
    entry.grid->build(entry.cloud->positions());
    // a cloud still in cell order (no particle changed cell) needs no reorder, which would copy
    // every field
    if (entry.movable && order == CloudOrder::byCell && !entry.grid->inCellOrder()) {
      entry.movable->reorder(entry.grid->sortPermutation());
      entry.grid->adoptCellOrder();
    }
    entry.binned = true;
  }
  for (Pairs& pairs : pairs_) {
    const Entry& a = entries_[pairs.a];
    const Entry& b = entries_[pairs.b];
    if (pairs.built && !a.movedNow && !b.movedNow) continue;
    // a rigid cloud's own pairs keep their partners as it moves (distances are kept)
    if (pairs.built && pairs.a == pairs.b && !a.movable) continue;
    if (pairs.a == pairs.b) {
      pairs.list.buildWithin(a.cloud->positions(), *a.grid);
    } else {
      pairs.list.buildBetween(a.cloud->positions(), b.cloud->positions(), *b.grid);
    }
    pairs.built = true;
  }
}

const NeighbourList& Neighbourhood::pairs(const ParticleCloud& a, const ParticleCloud& b) const {
  const std::size_t ea = entryOf(a), eb = entryOf(b);
  for (const Pairs& pairs : pairs_) {
    if (pairs.a == ea && pairs.b == eb) return pairs.list;
  }
  throw Error("neighbourhood: the pairs of cloud '" + a.name() + "' among cloud '" + b.name() +
              "' were never requested");
}

const CellGrid& Neighbourhood::grid(const ParticleCloud& cloud) const {
  return *entries_[entryOf(cloud)].grid;
}

std::size_t Neighbourhood::pairCount() const {
  std::size_t count = 0;
  for (const Pairs& pairs : pairs_) count += pairs.list.pairCount();
  return count;
}

}  // namespace sphcast
