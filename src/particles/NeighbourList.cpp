#include "particles/NeighbourList.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <string>
#include <utility>

#include "core/Error.h"

namespace sphcast {
namespace {

// A cell next to (or at) x_i along one axis, the gap between x_i and that cell along the axis,
// squared, and the periodic image of the cell seen from x_i: period * k with k = -1 for the cell
// before cell 0 (cell n - 1), +1 for the cell after cell n - 1 (cell 0), 0 otherwise.
struct AxisCell {
  std::uint32_t cell;
  double gapSquared;
  Real imageShift = 0;
};

// How a search takes the periodic image of a candidate: none (no periodic axis), per candidate
// (PeriodicBox::separation), or per run of cells (the image shift of the stencil cell, the same
// value separation() would subtract for every pair closer than the radius; see imagesByCell).
enum class Images { none, perCandidate, perCell };

// The cells within one step of cell c along an axis of n cells, in increasing order (so that a
// row's cells are visited in memory order): clipped at the ends of a non-periodic axis, wrapped
// and never listed twice (n >= 2) on a periodic one. u is x_i's fraction in its cell, edge the
// cell edge.
int neighbourCells(std::uint32_t c, std::uint32_t n, bool periodic, double u, double edge,
                   Real period, AxisCell cells[3]) {
  const double below = u * edge * u * edge, above = (1 - u) * edge * (1 - u) * edge;
  int count = 0;
  if (!periodic) {
    if (c > 0) cells[count++] = {c - 1, below};
    cells[count++] = {c, 0.0};
    if (c + 1 < n) cells[count++] = {c + 1, above};
    return count;
  }
  if (n == 2) {  // the cell before is the cell after
    const AxisCell other{1 - c, std::min(below, above)};
    cells[0] = c == 0 ? AxisCell{0, 0.0} : other;
    cells[1] = c == 0 ? other : AxisCell{1, 0.0};
    return 2;
  }
  // period * (+-1) as separation() forms it, so the shifted difference is bit for bit its own
  cells[0] = {c == 0 ? n - 1 : c - 1, below, c == 0 ? period * Real(-1) : Real(0)};
  cells[1] = {c, 0.0, Real(0)};
  cells[2] = {c + 1 == n ? 0 : c + 1, above, c + 1 == n ? period * Real(1) : Real(0)};
  if (c == 0) std::rotate(cells, cells + 1, cells + 3);      // 0, 1, n - 1
  if (c + 1 == n) std::rotate(cells, cells + 2, cells + 3);  // 0, n - 2, n - 1
  return 3;
}

// Where a search writes: a block's buffer, grown (rarely: only beyond any earlier build) so that
// a whole row of candidates fits before the row is scanned without branches.
struct PairSink {
  std::vector<std::uint32_t>& storage;
  std::size_t used;

  std::uint32_t* roomFor(std::size_t candidates) {
    const std::size_t needed = used + candidates;
    if (storage.size() < needed) storage.resize(needed + needed / 4 + 1024);
    return storage.data();
  }
};

// Below this many particles the light loops (finiteness check, copy) run on one thread.
constexpr std::size_t parallelThreshold = 32768;

// No particle of B has this index: nothing is excluded between two clouds.
constexpr std::uint32_t noSelf = std::numeric_limits<std::uint32_t>::max();

// |x_i - x_j|^2, the minimum image unless Images::none (with Images::perCell the image shift
// of the candidate's cell); written out on scalars so that x_i stays in registers in the
// candidate loop.
template <Images Image>
inline Real squaredDistance(const Vector& xi, const Vector& xj, const PeriodicBox& box,
                            const std::array<Real, 3>& shift) {
  if constexpr (Image == Images::perCell) {
    const Real dx = (xi[0] - xj[0]) - shift[0], dy = (xi[1] - xj[1]) - shift[1],
               dz = (xi[2] - xj[2]) - shift[2];
    return dx * dx + dy * dy + dz * dz;
  } else if constexpr (Image == Images::perCandidate) {
    const Real dx = box.minimumImage(xi[0] - xj[0], 0), dy = box.minimumImage(xi[1] - xj[1], 1),
               dz = box.minimumImage(xi[2] - xj[2], 2);
    return dx * dx + dy * dy + dz * dz;
  } else {
    const Real dx = xi[0] - xj[0], dy = xi[1] - xj[1], dz = xi[2] - xj[2];
    return dx * dx + dy * dy + dz * dz;
  }
}

// Within one cloud, particle i itself is always among its candidates at distance 0 and was
// appended exactly once: it is taken out afterwards rather than tested for in every candidate.
// The list is ascending when B is in cell order (binary search), else it is searched linearly.
template <bool InCellOrder>
void removeSelf(std::uint32_t self, std::uint32_t* first, PairSink& sink) {
  std::uint32_t* last = sink.storage.data() + sink.used;
  std::uint32_t* found =
      InCellOrder ? std::lower_bound(first, last, self) : std::find(first, last, self);
  if (found == last) return;  // cannot happen: distance 0 is always below the radius
  std::copy(found + 1, last, found);
  --sink.used;
}

// Appends the particles j of B with |x_i - x_j| < radius (the minimum image on periodic axes,
// taken as Image says) to the sink. The stencil of 3 x 3 x 3 cells is visited row by row (y, z
// fixed); a row whose gap to x_i already reaches the radius is skipped, and along x only the
// cells within the remaining reach sqrt(h^2 - gy^2 - gz^2) are scanned. Consecutive cells of a
// row (of one periodic image) are contiguous in the grid's cell order, so each run is one range
// of particlesByCell (of B's particles themselves when InCellOrder). Every candidate is stored
// and the end advanced only for a neighbour, which keeps the loop free of unpredictable
// branches. Returns the count.
template <Images Image, bool InCellOrder>
std::uint32_t appendNeighbours(const Vector xi, std::uint32_t self, const Vector* positionsB,
                               const CellGrid& grid, PairSink& sink) {
  const PeriodicBox& box = grid.periodicBox();
  const Real radiusSquared = grid.radius() * grid.radius();
  // pruning compares gaps with a radius grown by the cell margin: round-off never prunes a pair
  const double reachSquared = double(grid.radius()) * double(grid.radius()) * (1 + 4e-6);
  std::array<double, 3> fraction;
  const std::array<std::uint32_t, 3> home = grid.cellCoordinates(xi, fraction);
  const std::array<std::uint32_t, 3> n = grid.cellCounts();
  std::array<std::array<AxisCell, 3>, 3> cells;
  std::array<int, 3> cellCount;
  for (int a = 0; a < 3; ++a) {
    cellCount[a] = neighbourCells(home[a], n[a], box.isPeriodic(a), fraction[a],
                                  double(grid.cellSize()[a]), box.period(a), cells[a].data());
  }
  const std::uint32_t* cellStart = grid.cellStart().data();
  const std::uint32_t* byCell = grid.particlesByCell().data();
  const std::size_t before = sink.used;
  for (int z = 0; z < cellCount[2]; ++z) {
    for (int y = 0; y < cellCount[1]; ++y) {
      const double reachX = reachSquared - cells[2][z].gapSquared - cells[1][y].gapSquared;
      if (reachX <= 0) continue;
      const std::uint32_t row = n[0] * (cells[1][y].cell + n[1] * cells[2][z].cell);
      for (int x = 0; x < cellCount[0]; ++x) {
        if (cells[0][x].gapSquared >= reachX) continue;
        const std::uint32_t first = cells[0][x].cell;
        const std::array<Real, 3> shift{cells[0][x].imageShift, cells[1][y].imageShift,
                                        cells[2][z].imageShift};
        while (x + 1 < cellCount[0] && cells[0][x + 1].gapSquared < reachX &&
               cells[0][x + 1].cell == cells[0][x].cell + 1 &&
               cells[0][x + 1].imageShift == shift[0]) {
          ++x;  // extend the run of consecutive cells (of one periodic image)
        }
        const std::uint32_t begin = cellStart[row + first];
        const std::uint32_t end = cellStart[row + cells[0][x].cell + 1];
        std::uint32_t* out = sink.roomFor(end - begin);
        std::size_t used = sink.used;
        auto scan = [&]<Images RunImage>() {
          for (std::uint32_t k = begin; k < end; ++k) {
            const std::uint32_t j = InCellOrder ? k : byCell[k];
            out[used] = j;
            used += squaredDistance<RunImage>(xi, positionsB[j], box, shift) < radiusSquared;
          }
        };
        // most runs of a periodic grid are not across a boundary: no shift to subtract there
        if (Image == Images::perCell && shift[0] == 0 && shift[1] == 0 && shift[2] == 0) {
          scan.template operator()<Images::none>();
        } else {
          scan.template operator()<Image>();
        }
        sink.used = used;
      }
    }
  }
  if (self != noSelf) removeSelf<InCellOrder>(self, sink.storage.data() + before, sink);
  return static_cast<std::uint32_t>(sink.used - before);
}

using SearchFunction = std::uint32_t (*)(Vector, std::uint32_t, const Vector*, const CellGrid&,
                                         PairSink&);

template <Images Image>
SearchFunction searchFor(bool inCellOrder) {
  return inCellOrder ? appendNeighbours<Image, true> : appendNeighbours<Image, false>;
}

SearchFunction searchFor(bool periodic, bool imagesByCell, bool inCellOrder) {
  if (!periodic) return searchFor<Images::none>(inCellOrder);
  return imagesByCell ? searchFor<Images::perCell>(inCellOrder)
                      : searchFor<Images::perCandidate>(inCellOrder);
}

// The bounding box of the query points (all finite).
std::pair<Vector, Vector> boundingBox(const std::vector<Vector>& positions) {
  constexpr Real big = std::numeric_limits<Real>::max();
  Real lo0 = big, lo1 = big, lo2 = big, hi0 = -big, hi1 = -big, hi2 = -big;
  const std::size_t count = positions.size();
#pragma omp parallel for if (count > parallelThreshold) reduction(min : lo0, lo1, lo2) \
    reduction(max : hi0, hi1, hi2)
  for (std::size_t i = 0; i < count; ++i) {
    const Vector& x = positions[i];
    lo0 = std::min(lo0, x[0]), lo1 = std::min(lo1, x[1]), lo2 = std::min(lo2, x[2]);
    hi0 = std::max(hi0, x[0]), hi1 = std::max(hi1, x[1]), hi2 = std::max(hi2, x[2]);
  }
  return {Vector(lo0, lo1, lo2), Vector(hi0, hi1, hi2)};
}

void checkFinite(const std::vector<Vector>& positions) {
  std::size_t nonFinite = 0;
  const std::size_t count = positions.size();
#pragma omp parallel for reduction(+ : nonFinite) if (count > parallelThreshold)
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
  ++changes_;
  if (positionsB.size() != gridB.particleCount()) {
    throw Error("NeighbourList: the grid holds " + std::to_string(gridB.particleCount()) +
                " particles but the cloud has " + std::to_string(positionsB.size()) +
                " (rebuild the grid after the cloud changed)");
  }
  const std::size_t count = positionsA.size();
  cutIntoBlocks(count);
  const std::size_t blocks = blockBegin_.size() - 1;
  // one search per (periodic images how?, B in cell order?), chosen once, not per pair
  const bool periodic = gridB.periodicBox().anyPeriodic();
  bool imagesByCell = periodic && gridB.imagesByCell();
  if (imagesByCell && !sameCloud && count > 0) {
    const auto [lower, upper] = boundingBox(positionsA);
    imagesByCell = gridB.imagesByCell(lower, upper);
  }
  const SearchFunction search = searchFor(periodic, imagesByCell, gridB.inCellOrder());
  const Vector* xB = positionsB.data();

  // A block's buffer grows inside the parallel loop, where an exception (bad_alloc, when the
  // particles pile up) cannot leave: it is kept and thrown after the loop, for the solver to stop
  // the run with its last good state.
  std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic, 1) if (blocks > 1)
  for (std::size_t b = 0; b < blocks; ++b) {
    try {
      PairSink sink{blockStorage_[b], 0};
      for (std::size_t i = blockBegin_[b]; i < blockBegin_[b + 1]; ++i) {
        const std::uint32_t self = sameCloud ? static_cast<std::uint32_t>(i) : noSelf;
        counts_[i] = search(positionsA[i], self, xB, gridB, sink);
      }
      blockUsed_[b] = sink.used;
    } catch (...) {
#pragma omp critical(neighbourListFailure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  gatherBlocks();
}

void NeighbourList::filterFrom(const NeighbourList& wide, const std::vector<Vector>& positionsA,
                               const std::vector<Vector>& positionsB, Real radius,
                               const PeriodicBox& periodic, const std::uint8_t* movedA,
                               const std::uint8_t* movedB) {
  ++changes_;
  const std::size_t count = positionsA.size();
  if (wide.particleCount() != count) {
    throw Error("NeighbourList: the wide list holds " + std::to_string(wide.particleCount()) +
                " particles but the cloud has " + std::to_string(count));
  }
  // Each row is filtered into wide's room for it, so a row that stays needs no work at all.
  // Rows kept from the last filter must be that filter's, from this same wide list (a search
  // filters every row afresh: it passes no moved flags).
  const bool keepStill = movedA && movedB && filteredRooms_ && offsets_.size() == count + 1;
  if (!keepStill) {
    offsets_ = wide.offsets_;
    ends_.resize(count);
    neighbours_.resize(wide.pairCount());
    filteredRooms_ = true;
  }
  const Real radiusSquared = radius * radius;
  const std::uint64_t* offsets = wide.offsets_.data();
  const std::uint32_t* wideNeighbours = wide.neighbours_.data();
  const Vector* xB = positionsB.data();
  // A row's pairs take the plain difference when x_i lies at least the radius inside every
  // periodic face and all of B lies in the box: then a j closer than the radius by the minimum
  // image is that close as it is (the ball around x_i lies in the box, where each point has
  // one image), and any other j is at least as far by the plain difference. The same test as a
  // search's; the minimum image (three roundings) costs about twice the plain difference.
  Vector interiorLower = Vector::Constant(-std::numeric_limits<Real>::max());
  Vector interiorUpper = Vector::Constant(std::numeric_limits<Real>::max());
  bool plainInside = !periodic.anyPeriodic();
  if (!plainInside) {
    plainInside = true;
    for (const Vector& x : positionsB) plainInside = plainInside && periodic.wrap(x) == x;
    for (int a = 0; a < 3; ++a) {
      if (!periodic.isPeriodic(a)) continue;
      const Real margin = radius * Real(1.000001);  // round-off in x_i +- h
      interiorLower[a] = periodic.lower(a) + margin;
      interiorUpper[a] = periodic.lower(a) + periodic.period(a) - margin;
    }
  }
  std::uint32_t* out = neighbours_.data();
  auto keepCloser = [&](std::size_t i, auto separation) {
    const Vector xi = positionsA[i];
    std::uint64_t used = offsets[i];
    for (std::uint64_t n = offsets[i]; n < offsets[i + 1]; ++n) {
      const std::uint32_t j = wideNeighbours[n];
      out[used] = j;
      used += separation(xi, xB[j]) < radiusSquared;
    }
    return used;
  };
  const auto plain = [](const Vector& xi, const Vector& xj) {
    const Real dx = xi[0] - xj[0], dy = xi[1] - xj[1], dz = xi[2] - xj[2];
    return dx * dx + dy * dy + dz * dz;
  };
  const auto minimumImage = [&periodic](const Vector& xi, const Vector& xj) {
    const Real dx = periodic.minimumImage(xi[0] - xj[0], 0),
               dy = periodic.minimumImage(xi[1] - xj[1], 1),
               dz = periodic.minimumImage(xi[2] - xj[2], 2);
    return dx * dx + dy * dy + dz * dz;
  };
  // Which rows changed. Within one cloud without periodic axes the wide list is symmetric (j is
  // i's wide neighbour exactly when i is j's: the same squared distance both ways), so the
  // particles that moved mark their own rows and their wide neighbours' rows, at a cost of the
  // rows that move; otherwise each still particle's row reads its wide neighbours' flags.
  const bool byScatter = keepStill && &positionsA == &positionsB && !periodic.anyPeriodic();
  if (byScatter) {
    changedRows_.assign(count, 0);
    std::uint8_t* changed = changedRows_.data();
#pragma omp parallel for schedule(dynamic, 1024) if (count > 1024)
    for (std::size_t i = 0; i < count; ++i) {
      if (movedA[i] == 0) continue;
      std::atomic_ref<std::uint8_t>(changed[i]).store(1, std::memory_order_relaxed);
      for (std::uint64_t n = offsets[i]; n < offsets[i + 1]; ++n) {
        std::atomic_ref<std::uint8_t>(changed[wideNeighbours[n]])
            .store(1, std::memory_order_relaxed);
      }
    }
  }
  auto rowStill = [&](std::size_t i) {
    if (!keepStill || movedA[i] != 0) return false;
    if (byScatter) return changedRows_[i] == 0;
    std::uint8_t anyMoved = 0;
    for (std::uint64_t n = offsets[i]; n < offsets[i + 1]; ++n) {
      anyMoved |= movedB[wideNeighbours[n]];
    }
    return anyMoved == 0;
  };
  std::uint64_t pairs = 0;
#pragma omp parallel for schedule(dynamic, 1024) reduction(+ : pairs) if (count > 1024)
  for (std::size_t i = 0; i < count; ++i) {
    if (rowStill(i)) {
      pairs += ends_[i] - offsets_[i];
      continue;
    }
    const Vector& xi = positionsA[i];
    const bool inside = plainInside && (xi.array() >= interiorLower.array()).all() &&
                        (xi.array() <= interiorUpper.array()).all();
    ends_[i] = inside ? keepCloser(i, plain) : keepCloser(i, minimumImage);
    pairs += ends_[i] - offsets_[i];
  }
  pairCount_ = pairs;
}

// Contiguous blocks of i, several per thread so that clustered particles balance; the result
// does not depend on how many there are.
void NeighbourList::cutIntoBlocks(std::size_t count) {
  const std::size_t blocks = std::max<std::size_t>(
      1, std::min<std::size_t>(count / 64, 8 * std::size_t(omp_get_max_threads())));
  if (blockStorage_.size() < blocks) blockStorage_.resize(blocks);
  blockUsed_.resize(blocks);
  blockBegin_.resize(blocks + 1);
  for (std::size_t b = 0; b <= blocks; ++b) blockBegin_[b] = count * b / blocks;
  counts_.resize(count);
}

// Prefix sum of the counts into offsets, then every block's list copied to its place.
void NeighbourList::gatherBlocks() {
  const std::size_t count = counts_.size();
  offsets_.resize(count + 1);
  offsets_[0] = 0;
  for (std::size_t i = 0; i < count; ++i) offsets_[i + 1] = offsets_[i] + counts_[i];
  ends_.assign(offsets_.begin() + 1, offsets_.end());
  pairCount_ = offsets_[count];
  filteredRooms_ = false;
  neighbours_.resize(offsets_[count]);
  const std::size_t blocks = blockBegin_.size() - 1;
#pragma omp parallel for schedule(dynamic, 1) if (count > parallelThreshold)
  for (std::size_t b = 0; b < blocks; ++b) {
    if (blockUsed_[b] > 0) {
      std::memcpy(neighbours_.data() + offsets_[blockBegin_[b]], blockStorage_[b].data(),
                  blockUsed_[b] * sizeof(std::uint32_t));
    }
  }
}

std::size_t NeighbourList::memoryBytes() const {
  std::size_t bytes = (offsets_.capacity() + ends_.capacity()) * sizeof(std::uint64_t) +
                      neighbours_.capacity() * sizeof(std::uint32_t) +
                      counts_.capacity() * sizeof(std::uint32_t) + changedRows_.capacity() +
                      (blockBegin_.capacity() + blockUsed_.capacity()) * sizeof(std::size_t);
  for (const auto& block : blockStorage_) bytes += block.capacity() * sizeof(std::uint32_t);
  return bytes;
}

}  // namespace sphcast
