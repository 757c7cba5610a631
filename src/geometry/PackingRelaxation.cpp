#include "geometry/PackingRelaxation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "particles/CellGrid.h"
#include "particles/NeighbourList.h"
#include "particles/WendlandKernel.h"

namespace sphcast {

namespace {

constexpr double stepFraction = 0.25;  // of the stable step 1 / K of one displaced particle
constexpr double maxStep = 0.1;        // x dx per iteration

// The moving particles followed by the fixed ones, with their volumes, and every moving
// particle's neighbours among all of them (itself included, at r = 0).
class RelaxationPairs {
 public:
  RelaxationPairs(const FixedNeighbours& fixed, double spacing, double supportRadius)
      : grid_(static_cast<Real>(supportRadius)),
        fixed_(fixed),
        volume_(static_cast<Real>(spacing * spacing * spacing)) {}

  void build(const std::vector<Vector>& moving) {
    all_.assign(moving.begin(), moving.end());
    all_.insert(all_.end(), fixed_.positions.begin(), fixed_.positions.end());
    volumes_.assign(moving.size(), volume_);
    volumes_.insert(volumes_.end(), fixed_.volumes.begin(), fixed_.volumes.end());
    grid_.build(all_);
    list_.buildBetween(moving, all_, grid_);
  }
  const std::vector<Vector>& all() const { return all_; }
  const std::vector<Real>& volumes() const { return volumes_; }
  const NeighbourList& list() const { return list_; }

 private:
  CellGrid grid_;
  NeighbourList list_;
  const FixedNeighbours& fixed_;
  Real volume_;
  std::vector<Vector> all_;
  std::vector<Real> volumes_;
};

PackingStatistics measure(const RelaxationPairs& pairs, std::size_t movingCount,
                          const WendlandC2Kernel3D& kernel) {
  PackingStatistics statistics;
  if (movingCount == 0) return statistics;
  const auto& x = pairs.all();
  const auto& volumes = pairs.volumes();
  std::vector<double> sigma(movingCount), nearest(movingCount);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < movingCount; ++i) {
    double sum = 0.0;
    double closest = std::numeric_limits<double>::infinity();
    for (const std::uint32_t j : pairs.list().of(i)) {
      const Real r = (x[i] - x[j]).norm();
      sum += static_cast<double>(volumes[j] * kernel.value(r));
      if (j != i) closest = std::min(closest, static_cast<double>(r));
    }
    sigma[i] = sum;
    nearest[i] = closest;
  }
  const double count = static_cast<double>(movingCount);
  double sum = 0.0, squares = 0.0, nearestSum = 0.0;
  statistics.densityMin = statistics.nearestMin = std::numeric_limits<double>::infinity();
  statistics.densityMax = statistics.nearestMax = 0.0;
  for (std::size_t i = 0; i < movingCount; ++i) {
    sum += sigma[i];
    squares += sigma[i] * sigma[i];
    statistics.densityMin = std::min(statistics.densityMin, sigma[i]);
    statistics.densityMax = std::max(statistics.densityMax, sigma[i]);
    statistics.nearestMin = std::min(statistics.nearestMin, nearest[i]);
    statistics.nearestMax = std::max(statistics.nearestMax, nearest[i]);
    nearestSum += nearest[i];
  }
  statistics.densityMean = sum / count;
  const double variance =
      std::max(0.0, squares / count - statistics.densityMean * statistics.densityMean);
  statistics.densityDeviation = std::sqrt(variance) / statistics.densityMean;
  statistics.nearestMean = nearestSum / count;
  return statistics;
}

// Moves back (to old[i]) every moved particle that ended closer than `limit` to another one,
// until none does; each pass only moves particles back, so it ends, at worst where it began.
void keepApart(std::vector<Vector>& positions, const std::vector<Vector>& old,
               std::vector<bool>& moved, Real limit, CellGrid& grid) {
  NeighbourList list;
  for (bool changed = true; changed;) {
    changed = false;
    grid.build(positions);
    list.buildWithin(positions, grid);
    std::vector<std::size_t> back;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      if (!moved[i]) continue;
      for (const std::uint32_t j : list.of(i)) {
        if ((positions[i] - positions[j]).norm() < limit) {
          back.push_back(i);
          break;
        }
      }
    }
    for (const std::size_t i : back) {
      positions[i] = old[i];
      moved[i] = false;
      changed = true;
    }
  }
}

}  // namespace

PackingStatistics packingStatistics(const std::vector<Vector>& positions,
                                    const FixedNeighbours& fixed, double spacing,
                                    double supportRadius) {
  RelaxationPairs pairs(fixed, spacing, supportRadius);
  pairs.build(positions);
  return measure(pairs, positions.size(), WendlandC2Kernel3D(static_cast<Real>(supportRadius)));
}

std::array<PackingStatistics, 2> relaxPacking(
    std::vector<Vector>& positions, const FixedNeighbours& fixed,
    const std::function<std::vector<bool>(const std::vector<Vector>&)>& allowed,
    const RelaxationSettings& settings) {
  const double dx = settings.spacing, h = settings.supportRadius;
  const WendlandC2Kernel3D kernel(static_cast<Real>(h));
  RelaxationPairs pairs(fixed, dx, h);
  pairs.build(positions);
  std::array<PackingStatistics, 2> statistics{measure(pairs, positions.size(), kernel), {}};

  // K = V |dW/dr / r| at r = 0 = 20 alpha dx^3 / h^2 (see the header).
  const double stiffness =
      20.0 * static_cast<double>(kernel.normalisation()) * dx * dx * dx / (h * h);
  const Real gamma = static_cast<Real>(stepFraction / stiffness);
  const Real longestStep = static_cast<Real>(maxStep * dx);
  std::vector<Vector> trial(positions.size());
  CellGrid approach(
      static_cast<Real>(settings.closestApproach > 0.0 ? settings.closestApproach : h));
  for (int iteration = 0; iteration < settings.iterations; ++iteration) {
    if (iteration > 0) pairs.build(positions);
    const auto& x = pairs.all();
    const auto& volumes = pairs.volumes();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < positions.size(); ++i) {
      Vector push = Vector::Zero();
      for (const std::uint32_t j : pairs.list().of(i)) {
        const Vector xij = x[i] - x[j];
        push -= volumes[j] * kernel.gradient(xij, xij.norm());  // background pressure force
      }
      Vector step = gamma * push;
      const Real length = step.norm();
      if (length > longestStep) step *= longestStep / length;
      trial[i] = positions[i] + step;
    }
    const std::vector<bool> ok = allowed(trial);
    std::vector<bool> moved(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
      moved[i] = ok[i];
      if (ok[i]) trial[i].swap(positions[i]);  // trial keeps the old place
    }
    if (settings.closestApproach > 0.0) {
      keepApart(positions, trial, moved, static_cast<Real>(settings.closestApproach), approach);
    }
  }
  pairs.build(positions);
  statistics[1] = measure(pairs, positions.size(), kernel);
  return statistics;
}

}  // namespace sphcast
