#include "parallel/DomainDecomposition.h"

#include <algorithm>
#include <sstream>

#include "core/Error.h"
#include "particles/CellGrid.h"
#include "particles/FieldNames.h"

namespace sphcast {

DomainDecomposition::DomainDecomposition(const Communicator& comm, DecompositionSettings settings,
                                         double haloRadius, const PeriodicBox& periodic,
                                         int dimension)
    : comm_(comm),
      settings_(std::move(settings)),
      haloRadius_(haloRadius),
      periodic_(periodic),
      dimension_(dimension) {
  if (settings_.subdomains != comm_.size()) {
    throw DictionaryError(settings_.subdomainsAt,
                          "numberOfSubdomains " + std::to_string(settings_.subdomains) + " for " +
                              std::to_string(comm_.size()) + " ranks");
  }
}

void DomainDecomposition::distribute(std::vector<Cloud> clouds) {
  clouds_ = std::move(clouds);
  halos_.assign(clouds_.size(), HaloExchange());
  decompose();
  for (std::size_t c = 0; c < clouds_.size(); ++c) redistribute(c);
  for (std::size_t c = 0; c < clouds_.size(); ++c) buildHalo(c);
}

void DomainDecomposition::buildHalo(std::size_t c) {
  const Cloud& entry = clouds_[c];
  const double radius = entry.haloRadius > 0 ? entry.haloRadius : haloRadius_;
  const std::vector<Real>* reach =
      entry.perParticleReach ? &entry.cloud->scalarField(field::supportReach) : nullptr;
  halos_[c].build(*entry.cloud, bisection_, radius, periodic_, comm_, reach, entry.skin);
}

// The bisection of every cloud's owned particles, wherever they are (at the start a serial
// file's are all on rank 0).
void DomainDecomposition::decompose() {
  std::vector<Vector> points;
  std::vector<std::int64_t> weights;
  for (const Cloud& entry : clouds_) {
    const ParticleCloud& cloud = *entry.cloud;
    const auto& x = cloud.positions();
    points.insert(points.end(), x.begin(), x.begin() + static_cast<long>(cloud.ownedSize()));
    weights.insert(weights.end(), cloud.ownedSize(), entry.weight);
  }
  RecursiveBisection::AxisCuts cuts{settings_.counts, settings_.order};
  bisection_ = RecursiveBisection::build(comm_, points, weights, comm_.size(), dimension_,
                                         settings_.method == "hierarchical" ? &cuts : nullptr);
}

void DomainDecomposition::redistribute(std::size_t c) {
  ParticleCloud& cloud = *clouds_[c].cloud;
  halos_[c].remove(cloud);
  migrateParticles(cloud, bisection_, comm_);
  // neighbours close in memory, as the serial search's reorder leaves them
  if (cloud.size() > 1) {
    CellGrid grid(static_cast<Real>(haloRadius_), periodic_);
    grid.build(cloud.positions());
    if (!grid.inCellOrder()) cloud.reorder(grid.sortPermutation());
  }
}

double DomainDecomposition::imbalance() const {
  std::int64_t mine = 0;
  for (const Cloud& entry : clouds_) {
    mine += static_cast<std::int64_t>(entry.cloud->ownedSize()) * entry.weight;
  }
  const std::vector<std::int64_t> all = comm_.gather(mine);
  std::int64_t total = 0, largest = 0;
  for (std::int64_t w : all) {
    total += w;
    largest = std::max(largest, w);
  }
  return total > 0 ? static_cast<double>(largest) * comm_.size() / static_cast<double>(total) : 1.0;
}

void DomainDecomposition::dropHalo(ParticleCloud& cloud) {
  halos_[indexOf(cloud)].remove(cloud);
  rebuildPending_ = true;
}

void DomainDecomposition::update(Neighbourhood& neighbourhood, bool rebuild) {
  rebuild = rebuild || rebuildPending_;  // the same on every rank: dropHalo is collective
  rebuildPending_ = false;
  // the halo as its owners moved it: the displacements the rebuild's test measures are theirs
  // (a rebuild asked for replaces the halo: no refresh; `rebuild` is the same on every rank)
  if (!rebuild) {
    for (std::size_t c = 0; c < clouds_.size(); ++c) {
      if (clouds_[c].moves) halos_[c].refresh(*clouds_[c].cloud, comm_);
    }
  }
  if (!comm_.any(rebuild || neighbourhood.rebuildDue())) {
    neighbourhood.update(CloudOrder::keep, false);
    return;
  }
  const bool rebalance = comm_.size() > 1 && imbalance() > 1 + settings_.maxImbalance;
  if (rebalance) {
    for (std::size_t c = 0; c < clouds_.size(); ++c) halos_[c].remove(*clouds_[c].cloud);
    decompose();
    ++rebalances_;
  }
  for (std::size_t c = 0; c < clouds_.size(); ++c) {
    if (!rebalance && !clouds_[c].moves) continue;
    redistribute(c);
    buildHalo(c);
  }
  neighbourhood.update(CloudOrder::keep, true);
}

std::size_t DomainDecomposition::indexOf(const ParticleCloud& cloud) const {
  for (std::size_t c = 0; c < clouds_.size(); ++c) {
    if (clouds_[c].cloud == &cloud) return c;
  }
  throw Error("domain decomposition: cloud '" + cloud.name() + "' is not decomposed");
}

void DomainDecomposition::refresh(const ParticleCloud& cloud, void* values,
                                  std::size_t bytesPerParticle, const std::source_location& where) {
  halos_[indexOf(cloud)].refresh(cloud, values, bytesPerParticle, comm_, where);
}

void DomainDecomposition::refresh(ParticleCloud& cloud, const std::vector<std::string>& fields,
                                  const std::source_location& where) {
  halos_[indexOf(cloud)].refresh(cloud, fields, comm_, where);
}

std::string DomainDecomposition::describe() const {
  std::vector<std::int64_t> counts{0, 0};
  for (const Cloud& entry : clouds_) {
    counts[0] += static_cast<std::int64_t>(entry.cloud->ownedSize());
    counts[1] += static_cast<std::int64_t>(entry.cloud->haloSize());
  }
  comm_.sum(counts);
  std::ostringstream text;
  text.precision(3);
  text << comm_.size() << " subdomains by " << describeMethod(settings_) << " ("
       << bisection_.describe() << "); halos " << counts[1] << " particles, "
       << (counts[0] > 0 ? 100.0 * static_cast<double>(counts[1]) / static_cast<double>(counts[0])
                         : 0.0)
       << " % of the " << counts[0] << " owned; imbalance " << imbalance();
  return text.str();
}

}  // namespace sphcast
