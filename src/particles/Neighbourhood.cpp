#include "particles/Neighbourhood.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/Error.h"

namespace sphcast {

namespace {

// The skin, cut where a periodic axis could not hold a search with h + s (the grid needs a
// period above twice its radius; 1 % kept as margin).
Real fittedSkin(Real radius, const PeriodicBox& periodic, Real skin) {
  if (!(skin >= 0) || !std::isfinite(skin)) {
    throw Error("neighbourhood: the skin must be finite and >= 0, not " + std::to_string(skin));
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (periodic.isPeriodic(axis)) {
      skin = std::min(skin, std::max(Real(0), Real(0.99) * periodic.period(axis) / 2 - radius));
    }
  }
  return skin;
}

// The largest |x - x0| over a cloud, the minimum image on periodic axes (a particle wrapped
// across a periodic face has moved by its step, not by the period), infinite when a position is
// not finite.
Real largestDisplacement(const std::vector<Vector>& positions, const std::vector<Vector>& from,
                         const PeriodicBox& periodic) {
  Real largest = 0;
  const std::size_t count = positions.size();
#pragma omp parallel for reduction(max : largest) if (count > 32768)
  for (std::size_t i = 0; i < count; ++i) {
    const Real d = periodic.separation(positions[i], from[i]).squaredNorm();
    largest = std::max(largest, std::isfinite(d) ? d : std::numeric_limits<Real>::infinity());
  }
  return std::sqrt(largest);
}

}  // namespace

Neighbourhood::Neighbourhood(Real radius, const PeriodicBox& periodic, Real skin)
    : radius_(radius), skin_(fittedSkin(radius, periodic, skin)), periodic_(periodic) {}

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
  entry.grid = std::make_unique<CellGrid>(radius_ + skin_, periodic_);
  entries_.push_back(std::move(entry));
}

void Neighbourhood::addFixedCloud(const ParticleCloud& cloud) {
  if (has(cloud)) return;
  Entry entry;
  entry.cloud = &cloud;
  entry.grid = std::make_unique<CellGrid>(radius_ + skin_, periodic_);
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
  pairs_.push_back({ea, eb, NeighbourList(), NeighbourList(), false});
}

void Neighbourhood::update(CloudOrder order, bool rebuild) {
  for (Entry& entry : entries_) {
    entry.movedNow = entry.movable || !entry.binned;
    if (entry.moves && !entry.movable) {  // a rigid cloud: moved when its positions changed
      const bool changed = entry.cloud->positions() != entry.lastPositions;
      if (changed) entry.lastPositions = entry.cloud->positions();
      entry.movedNow = entry.movedNow || changed;
    }
  }
  if (rebuild || rebuildDue()) {
    this->rebuild(order);
    ++rebuilds_;
  } else {
    filter();
    ++reuses_;
  }
  if (skin_ > 0) {
    for (Entry& entry : entries_) {
      if (entry.movable) entry.lastPositions = entry.cloud->positions();
    }
  }
}

bool Neighbourhood::keptForever(const Pairs& pairs) const {
  return pairs.built && pairs.a == pairs.b && !entries_[pairs.a].movable;
}

// Whether a pair of some list may have come closer than h without being in its wide list: it
// was at least h + s apart at the rebuild and has closed in by at most the displacements.
bool Neighbourhood::rebuildDue() {
  if (skin_ == 0) return true;
  std::vector<Real> displacement(entries_.size(), 0);
  for (std::size_t e = 0; e < entries_.size(); ++e) {
    const Entry& entry = entries_[e];
    if (!entry.binned) return true;
    // a fixed cloud re-distributed over the ranks of a decomposed run (a re-balance)
    if (entry.cloud->layoutVersion() != entry.binnedLayout) return true;
    if (!entry.moves) continue;
    if (entry.cloud->layoutVersion() != entry.binnedLayout ||
        entry.cloud->size() != entry.binnedPositions.size()) {
      return true;
    }
    displacement[e] =
        largestDisplacement(entry.cloud->positions(), entry.binnedPositions, periodic_);
  }
  for (const Pairs& pairs : pairs_) {
    if (keptForever(pairs)) continue;
    if (!pairs.built) return true;
    const Real closing = pairs.a == pairs.b ? 2 * displacement[pairs.a]
                                            : displacement[pairs.a] + displacement[pairs.b];
    if (!(closing < skin_)) return true;
  }
  return false;
}

void Neighbourhood::rebuild(CloudOrder order) {
  std::vector<bool> rebinned(entries_.size(), false);
  std::vector<bool> relaid(entries_.size(), false);  // particles added, removed or reordered
  for (std::size_t e = 0; e < entries_.size(); ++e) {
    Entry& entry = entries_[e];
    relaid[e] = entry.binned && entry.cloud->layoutVersion() != entry.binnedLayout;
    // a fixed cloud's grid stays valid (unless a decomposed run re-distributed it)
    if (entry.binned && !entry.moves && entry.cloud->layoutVersion() == entry.binnedLayout) {
      continue;
    }
    // a rigid cloud is re-binned only when it moved (a body held, resting or at its stop keeps
    // its grid and lists)
    if (entry.binned && entry.moves && !entry.movable &&
        entry.cloud->positions() == entry.binnedPositions) {
      continue;
    }
    entry.grid->build(entry.cloud->positions());
    // a cloud still in cell order (no particle changed cell) needs no reorder, which would copy
    // every field
    if (entry.movable && order == CloudOrder::byCell && !entry.grid->inCellOrder()) {
      entry.movable->reorder(entry.grid->sortPermutation());
      entry.grid->adoptCellOrder();
    }
    if (entry.moves) entry.binnedPositions = entry.cloud->positions();
    entry.binnedLayout = entry.cloud->layoutVersion();
    entry.binned = true;
    rebinned[e] = true;
  }
  for (Pairs& pairs : pairs_) {
    if (keptForever(pairs) && !relaid[pairs.a]) continue;
    const Entry& a = entries_[pairs.a];
    const Entry& b = entries_[pairs.b];
    const bool search = !pairs.built || rebinned[pairs.a] || rebinned[pairs.b];
    if (!search && !a.movedNow && !b.movedNow) continue;
    // with no skin the list is the search's; with one the search fills the wide list, and a
    // list whose grids still hold (a rigid cloud back where it was binned) is only filtered
    NeighbourList& searched = skin_ > 0 ? pairs.wide : pairs.list;
    if (search || skin_ == 0) {
      if (pairs.a == pairs.b) {
        searched.buildWithin(a.cloud->positions(), *a.grid);
      } else {
        searched.buildBetween(a.cloud->positions(), b.cloud->positions(), *b.grid);
      }
    }
    if (skin_ > 0) {
      pairs.list.filterFrom(pairs.wide, a.cloud->positions(), b.cloud->positions(), radius_,
                            periodic_);
    }
    pairs.built = true;
  }
}

// Between searches a list changes only in the rows where something moved: the rest keep their
// pairs (NeighbourList::filterFrom), which in a casting's cooling, most of it frozen and held,
// is most rows.
void Neighbourhood::filter() {
  flagMovedParticles();
  for (Pairs& pairs : pairs_) {
    if (keptForever(pairs)) continue;
    const Entry& a = entries_[pairs.a];
    const Entry& b = entries_[pairs.b];
    if (!a.movedNow && !b.movedNow) continue;
    pairs.list.filterFrom(pairs.wide, a.cloud->positions(), b.cloud->positions(), radius_,
                          periodic_, a.moved.data(), b.moved.data());
  }
}

// Per particle, whether it moved since the last update: a moving cloud's compared bit for bit
// (held frozen metal has exactly its old position), a rigid cloud's all or none, a fixed one's
// none.
void Neighbourhood::flagMovedParticles() {
  for (Entry& entry : entries_) {
    const std::vector<Vector>& x = entry.cloud->positions();
    const std::size_t count = x.size();
    if (!entry.movable || entry.lastPositions.size() != count) {
      entry.moved.assign(count, entry.movedNow ? 1 : 0);
      continue;
    }
    entry.moved.resize(count);
    const Vector* last = entry.lastPositions.data();
    std::uint8_t* moved = entry.moved.data();
#pragma omp parallel for if (count > 32768)
    for (std::size_t i = 0; i < count; ++i) moved[i] = x[i] != last[i] ? 1 : 0;
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
