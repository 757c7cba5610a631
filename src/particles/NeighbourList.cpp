#include "particles/NeighbourList.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "core/Error.h"

namespace sphcast {
namespace {

// A run of consecutive cells [first, last] along one axis.
struct CellSpan {
  std::uint32_t first;
  std::uint32_t last;
};

// The cells within one step of cell c along an axis of n cells, as at most three spans in
// increasing order: clipped at the ends of a non-periodic axis, wrapped (and never visited
// twice, n >= 2) on a periodic one.
int neighbourSpans(std::uint32_t c, std::uint32_t n, bool periodic, CellSpan spans[3]) {
  if (!periodic || (c > 0 && c + 1 < n)) {
    spans[0] = {c > 0 ? c - 1 : 0, c + 1 < n ? c + 1 : c};
    return 1;
  }
  if (n == 2) {
    spans[0] = {0, 1};
    return 1;
  }
  if (c == 0) {  // wraps to n - 1
    spans[0] = {0, 1};
    spans[1] = {n - 1, n - 1};
    return 2;
  }
  spans[0] = {0, 0};  // c == n - 1 wraps to 0
  spans[1] = {c - 1, c};
  return 2;
}

// Appends to `out` the particles j of B near x_i (|x_i - x_j| < radius, minimum image when
// Periodic), visiting the cell stencil row by row: along x the cells of a span are contiguous
// in the grid's cell order, so each row is one range of particlesByCell. Returns the count.
template <bool Periodic>
std::uint32_t appendNeighbours(std::size_t i, const Vector& xi, const Vector* positionsB,
                               const CellGrid& grid, bool excludeSelf,
                               std::vector<std::uint32_t>& out) {
  const PeriodicBox& box = grid.periodicBox();
  const Real radiusSquared = grid.radius() * grid.radius();
  const std::array<std::uint32_t, 3> cell = grid.cellCoordinates(xi);
  const std::array<std::uint32_t, 3> n = grid.cellCounts();
  std::array<std::array<CellSpan, 3>, 3> spans;
  std::array<int, 3> spanCount;
  for (int a = 0; a < 3; ++a) {
    spanCount[a] = neighbourSpans(cell[a], n[a], box.isPeriodic(a), spans[a].data());
  }
  const std::uint32_t* cellStart = grid.cellStart().data();
  const std::uint32_t* byCell = grid.particlesByCell().data();
  const std::size_t before = out.size();
  for (int sz = 0; sz < spanCount[2]; ++sz) {
    for (std::uint32_t cz = spans[2][sz].first; cz <= spans[2][sz].last; ++cz) {
      for (int sy = 0; sy < spanCount[1]; ++sy) {
        for (std::uint32_t cy = spans[1][sy].first; cy <= spans[1][sy].last; ++cy) {
          const std::uint32_t row = n[0] * (cy + n[1] * cz);
          for (int sx = 0; sx < spanCount[0]; ++sx) {
            const std::uint32_t end = cellStart[row + spans[0][sx].last + 1];
            for (std::uint32_t k = cellStart[row + spans[0][sx].first]; k < end; ++k) {
              const std::uint32_t j = byCell[k];
              const Vector d = Periodic ? box.separation(xi, positionsB[j]) : xi - positionsB[j];
              if (d.squaredNorm() < radiusSquared && !(excludeSelf && j == i)) out.push_back(j);
            }
          }
        }
      }
    }
  }
  return static_cast<std::uint32_t>(out.size() - before);
}

void checkFinite(const std::vector<Vector>& positions) {
  std::size_t nonFinite = 0;
  const std::size_t count = positions.size();
#pragma omp parallel for reduction(+ : nonFinite)
  for (std::size_t i = 0; i < count; ++i) nonFinite += positions[i].allFinite() ? 0 : 1;
  if (nonFinite == 0) return;
  std::size_t first = 0;
  while (positions[first].allFinite()) ++first;
  throw Error("NeighbourList: " + std::to_string(nonFinite) +
              " query particle(s) with a non-finite position, the first is particle " +
              std::to_string(first));
}

}  // namespace

void NeighbourList::buildWithin(const std::vector<Vector>& positions, const CellGrid& grid) {
  build(positions, positions, grid, true);
}

void NeighbourList::buildBetween(const std::vector<Vector>& positionsA,
                                 const std::vector<Vector>& positionsB, const CellGrid& gridB) {
  checkFinite(positionsA);
  build(positionsA, positionsB, gridB, false);
}

void NeighbourList::build(const std::vector<Vector>& positionsA,
                          const std::vector<Vector>& positionsB, const CellGrid& gridB,
                          bool sameCloud) {
  if (gridB.cellCount() == 0) throw Error("NeighbourList: the cell grid has not been built");
  if (positionsB.size() != gridB.particleCount()) {
    throw Error("NeighbourList: the grid holds " + std::to_string(gridB.particleCount()) +
                " particles but the cloud has " + std::to_string(positionsB.size()) +
                " (rebuild the grid after the cloud changed)");
  }
  const std::size_t count = positionsA.size();
  // Contiguous blocks of i, several per thread so that clustered particles balance; the result
  // does not depend on how many there are.
  const std::size_t blocks = std::max<std::size_t>(
      1, std::min<std::size_t>(count / 64, 8 * std::size_t(omp_get_max_threads())));
  if (threadLists_.size() < blocks) threadLists_.resize(blocks);
  threadBegin_.resize(blocks + 1);
  for (std::size_t b = 0; b <= blocks; ++b) threadBegin_[b] = count * b / blocks;
  counts_.resize(count);
  const bool periodic = gridB.periodicBox().anyPeriodic();
  const Vector* xB = positionsB.data();

#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t b = 0; b < blocks; ++b) {
    std::vector<std::uint32_t>& list = threadLists_[b];
    list.clear();
    for (std::size_t i = threadBegin_[b]; i < threadBegin_[b + 1]; ++i) {
      counts_[i] = periodic ? appendNeighbours<true>(i, positionsA[i], xB, gridB, sameCloud, list)
                            : appendNeighbours<false>(i, positionsA[i], xB, gridB, sameCloud, list);
    }
  }
  gatherBlocks();
}

// Prefix sum of the counts into offsets, then every block's list copied to its place.
void NeighbourList::gatherBlocks() {
  const std::size_t count = counts_.size();
  offsets_.resize(count + 1);
  offsets_[0] = 0;
  for (std::size_t i = 0; i < count; ++i) offsets_[i + 1] = offsets_[i] + counts_[i];
  neighbours_.resize(offsets_[count]);
  const std::size_t blocks = threadBegin_.size() - 1;
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::vector<std::uint32_t>& list = threadLists_[b];
    if (!list.empty()) {
      std::memcpy(neighbours_.data() + offsets_[threadBegin_[b]], list.data(),
                  list.size() * sizeof(std::uint32_t));
    }
  }
}

std::size_t NeighbourList::memoryBytes() const {
  std::size_t bytes = offsets_.capacity() * sizeof(std::uint64_t) +
                      neighbours_.capacity() * sizeof(std::uint32_t) +
                      counts_.capacity() * sizeof(std::uint32_t) +
                      threadBegin_.capacity() * sizeof(std::size_t);
  for (const auto& list : threadLists_) bytes += list.capacity() * sizeof(std::uint32_t);
  return bytes;
}

}  // namespace sphcast
