#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/Real.h"
#include "particles/CellGrid.h"

namespace sphcast {

// For every particle i of a cloud A, the particles j of a cloud B with |x_i - x_j| < radius,
// the radius of B's CellGrid (normally the kernel's support radius h), the distance taken as the
// minimum image on periodic axes (PeriodicBox). Strictly less: a pair at exactly r = h adds
// nothing to any kernel sum or gradient, since W and dW/dr vanish there. A is B for fluid-fluid
// pairs (i itself left out), or another cloud, e.g. fluid A among wall B.
//
// Layout: rows of uint32 indices into B, each in its own range of one array:
//   offsets()   : A.size() + 1 entries (uint64), where each row's range begins,
//   ends()      : A.size() entries (uint64), where each row ends,
//   neighbours(): the indices; the neighbours of i are neighbours()[offsets()[i] .. ends()[i]).
// A searched list is compressed sparse rows (ends()[i] == offsets()[i + 1]); a list filtered
// from a wide one keeps the wide list's ranges, each row filling the start of its own, so that
// a row that stays between filters is not touched (filterFrom). pairCount() counts the pairs in
// the rows, not the room.
// Within one i they come in B's cell order (ascending j once B is reordered by its grid), so the
// pair loop reads B's fields almost sequentially. Each i owns its own range: a pair loop over i
// under OpenMP writes only to i (gather), no atomics.
//
// Building is gather style too: the i are cut into contiguous blocks (8 per thread, scheduled
// dynamically, so clustered particles balance); each block writes its neighbours into its own
// buffer in one pass over the 3 x 3 x 3 cell stencil (rows and end cells beyond the radius
// skipped), then the blocks are copied into place after a prefix sum of the counts. The result
// does not depend on the thread count. All buffers are kept between builds and only grow, so a
// rebuild every step allocates nothing once the largest list has been seen; the price is that
// the block buffers hold a second copy of the indices (memoryBytes() counts them).
//
// A pair loop (gather: each i writes only to itself, so it runs under OpenMP as it is):
//   const auto& x = cloud.positions();
//   const std::uint64_t* begins = list.offsets().data();
//   const std::uint64_t* ends = list.ends().data();
//   const std::uint32_t* neighbours = list.neighbours().data();
//   #pragma omp parallel for
//   for (std::size_t i = 0; i < x.size(); ++i) {
//     for (std::uint64_t n = begins[i]; n < ends[i]; ++n) {
//       const std::uint32_t j = neighbours[n];
//       const Vector xij = periodic.separation(x[i], x[j]);  // minimum image
//       const Real r = xij.norm();                          // 0 <= r < h
//       rate[i] += ... kernel.gradient(xij, r) ...;
//     }
//   }
class NeighbourList {
 public:
  // A == B: neighbours of each particle among the same cloud, binned in `grid` (built on exactly
  // these positions, or adopted after a reorder), self excluded.
  void buildWithin(const std::vector<Vector>& positions, const CellGrid& grid);

  // A != B: neighbours of each particle at positionsA among the particles at positionsB, binned
  // in gridB. Throws Error for a non-finite position in A.
  void buildBetween(const std::vector<Vector>& positionsA, const std::vector<Vector>& positionsB,
                    const CellGrid& gridB);

  // The pairs of `wide` (a list of the same clouds built with a larger radius, a skin) that are
  // closer than `radius` now, in wide's order: the list a search with `radius` would find,
  // without the search, as long as no pair has closed in by more than the skin since wide was
  // built (Neighbourhood checks that, and rebuilds instead for a non-finite position).
  // With movedA and movedB (per particle, nonzero: moved since this list was last filtered from
  // the same wide list), a row whose particle and wide neighbours all stayed keeps its pairs
  // from then where they are: frozen metal and molds at rest cost nothing within a cloud and a
  // flag per wide pair between two.
  void filterFrom(const NeighbourList& wide, const std::vector<Vector>& positionsA,
                  const std::vector<Vector>& positionsB, Real radius, const PeriodicBox& periodic,
                  const std::uint8_t* movedA = nullptr, const std::uint8_t* movedB = nullptr);

  std::size_t particleCount() const { return offsets_.size() - 1; }
  // How many times the list was built or filtered: a row read at two equal counts holds the
  // same pairs in the same order (a model that keeps what it computed from rows checks it).
  std::uint64_t changes() const { return changes_; }
  std::size_t pairCount() const { return pairCount_; }

  const std::vector<std::uint64_t>& offsets() const { return offsets_; }
  const std::vector<std::uint64_t>& ends() const { return ends_; }
  const std::vector<std::uint32_t>& neighbours() const { return neighbours_; }

  // The neighbours of particle i of A.
  std::span<const std::uint32_t> of(std::size_t i) const {
    return {neighbours_.data() + offsets_[i], neighbours_.data() + ends_[i]};
  }

  // Bytes the list holds now (capacity of offsets and neighbours plus the build buffers).
  std::size_t memoryBytes() const;

 private:
  void build(const std::vector<Vector>& positionsA, const std::vector<Vector>& positionsB,
             const CellGrid& gridB, bool sameCloud);
  void cutIntoBlocks(std::size_t count);
  void gatherBlocks();

  std::vector<std::uint64_t> offsets_{0};
  std::vector<std::uint64_t> ends_;
  std::vector<std::uint32_t> neighbours_;
  std::size_t pairCount_ = 0;
  std::uint64_t changes_ = 0;  // builds and filters so far
  bool filteredRooms_ = false;  // the rows lie in a wide list's ranges (filterFrom)
  std::vector<std::uint8_t> changedRows_;  // filterFrom's rows to filter again, within a cloud
  std::vector<std::uint32_t> counts_;                     // per particle of A
  std::vector<std::vector<std::uint32_t>> blockStorage_;  // per block of i, only grows
  std::vector<std::size_t> blockUsed_;                    // entries of blockStorage_ in use
  std::vector<std::size_t> blockBegin_;                   // first i of each block
};

}  // namespace sphcast
