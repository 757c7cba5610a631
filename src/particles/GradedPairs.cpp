#include "particles/GradedPairs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include "core/Error.h"

namespace sphcast {

namespace {

// The particles of one spacing, binned in cells of their own support radius.
struct LevelGrid {
  Real radius = 0;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells;

  static std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k) {
    constexpr std::int64_t offset = std::int64_t{1} << 20;
    return (static_cast<std::uint64_t>(i + offset) << 42) |
           (static_cast<std::uint64_t>(j + offset) << 21) | static_cast<std::uint64_t>(k + offset);
  }
  std::int64_t cellOf(Real x) const { return static_cast<std::int64_t>(std::floor(x / radius)); }
  std::uint64_t keyOf(const Vector& x) const {
    return key(cellOf(x[0]), cellOf(x[1]), cellOf(x[2]));
  }
};

struct Neighbour {
  std::uint32_t j;
  Real hij;
  bool operator<(const Neighbour& other) const { return j < other.j; }
};

}  // namespace

GradedPairs findGradedPairs(const std::vector<Vector>& x, const std::vector<Real>& localSpacing,
                            Real hOverDx, const PeriodicBox& periodic,
                            const std::vector<std::uint8_t>* wanted, PairSupport support) {
  const std::size_t n = x.size();
  std::vector<Real> spacings(localSpacing.begin(), localSpacing.end());
  std::sort(spacings.begin(), spacings.end());
  spacings.erase(std::unique(spacings.begin(), spacings.end()), spacings.end());
  std::vector<LevelGrid> grids(spacings.size());
  for (std::size_t l = 0; l < spacings.size(); ++l) grids[l].radius = hOverDx * spacings[l];
  // A particle within the widest reach of a periodic axis's ends is binned at its image too;
  // a pair's separation is the minimum image, the same bits from either end.
  const Real widest = spacings.empty() ? Real(0) : hOverDx * spacings.back();
  for (int axis = 0; axis < 3; ++axis) {
    if (periodic.isPeriodic(axis) && !(periodic.period(axis) > 2 * widest)) {
      throw Error(
          "a periodic axis is shorter than twice the coarsest support radius of a graded "
          "cloud (" +
          std::to_string(2 * widest) + " m)");
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto l = static_cast<std::size_t>(
        std::lower_bound(spacings.begin(), spacings.end(), localSpacing[i]) - spacings.begin());
    LevelGrid& grid = grids[l];
    std::vector<Vector> images{x[i]};
    for (int axis = 0; axis < 3; ++axis) {
      if (!periodic.isPeriodic(axis)) continue;
      const Real lower = periodic.lower(axis), period = periodic.period(axis);
      const std::size_t count = images.size();
      for (std::size_t m = 0; m < count; ++m) {
        Vector image = images[m];
        if (image[axis] < lower + widest) {
          image[axis] += period;
          images.push_back(image);
        } else if (image[axis] >= lower + period - widest) {
          image[axis] -= period;
          images.push_back(image);
        }
      }
    }
    for (const Vector& image : images) grid.cells[grid.keyOf(image)].push_back(std::uint32_t(i));
  }
  const auto rowOf = [&](std::size_t i, std::vector<Neighbour>& row) {
    row.clear();
    if (wanted != nullptr && !(*wanted)[i]) return;
    const Real hi = hOverDx * localSpacing[i];
    for (const LevelGrid& grid : grids) {
      const Real reach = support == PairSupport::row ? hi : Real(0.5) * (hi + grid.radius);
      const auto span = static_cast<std::int64_t>(std::ceil(reach / grid.radius));
      const std::int64_t ci = grid.cellOf(x[i][0]), cj = grid.cellOf(x[i][1]),
                         ck = grid.cellOf(x[i][2]);
      for (std::int64_t a = ci - span; a <= ci + span; ++a) {
        for (std::int64_t b = cj - span; b <= cj + span; ++b) {
          for (std::int64_t c = ck - span; c <= ck + span; ++c) {
            const auto cell = grid.cells.find(LevelGrid::key(a, b, c));
            if (cell == grid.cells.end()) continue;
            for (const std::uint32_t j : cell->second) {
              if (j != i && periodic.separation(x[j], x[i]).norm() < reach) {
                row.push_back({j, reach});
              }
            }
          }
        }
      }
    }
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end(),
                          [](const Neighbour& a, const Neighbour& b) { return a.j == b.j; }),
              row.end());
  };
  GradedPairs pairs;
  pairs.rowStart.assign(n + 1, 0);
#pragma omp parallel
  {
    std::vector<Neighbour> row;
#pragma omp for schedule(dynamic, 512)
    for (std::size_t i = 0; i < n; ++i) {
      rowOf(i, row);
      pairs.rowStart[i + 1] = row.size();
    }
  }
  for (std::size_t i = 0; i < n; ++i) pairs.rowStart[i + 1] += pairs.rowStart[i];
  pairs.neighbours.resize(pairs.rowStart[n]);
  pairs.supportRadii.resize(pairs.rowStart[n]);
#pragma omp parallel
  {
    std::vector<Neighbour> row;
#pragma omp for schedule(dynamic, 512)
    for (std::size_t i = 0; i < n; ++i) {
      rowOf(i, row);
      std::size_t slot = pairs.rowStart[i];
      for (const Neighbour& pair : row) {
        pairs.neighbours[slot] = pair.j;
        pairs.supportRadii[slot] = pair.hij;
        ++slot;
      }
    }
  }
  return pairs;
}

std::vector<Real> gradedSupportReach(const std::vector<Vector>& x,
                                     const std::vector<Real>& localSpacing, Real hOverDx,
                                     const PeriodicBox& periodic) {
  const std::size_t n = x.size();
  std::vector<Real> reach(n);
  Real finest = std::numeric_limits<Real>::max();
  for (std::size_t i = 0; i < n; ++i) {
    reach[i] = hOverDx * localSpacing[i];
    finest = std::min(finest, localSpacing[i]);
  }
  // the finest particles' supports reach no one farther than their own: only the coarser rows
  std::vector<std::uint8_t> coarser(n, 0);
  for (std::size_t i = 0; i < n; ++i) coarser[i] = localSpacing[i] > Real(1.001) * finest ? 1 : 0;
  const GradedPairs rows =
      findGradedPairs(x, localSpacing, hOverDx, periodic, &coarser, PairSupport::row);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t s = rows.rowStart[i]; s < rows.rowStart[i + 1]; ++s) {
      Real& r = reach[rows.neighbours[s]];
      r = std::max(r, rows.supportRadii[s]);
    }
  }
  return reach;
}

}  // namespace sphcast
