#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "boundaries/PeriodicBox.h"
#include "core/Real.h"

namespace sphcast {

// A uniform grid of cubic-ish cells of edge >= the search radius h, with the particles of one
// cloud binned into it by a counting sort (linear in particles + cells, no comparison sort).
// Cells are numbered c = cx + nx (cy + ny cz), x fastest ("cell order"). After build():
//   particles of cell c = particlesByCell()[cellStart()[c] .. cellStart()[c + 1]),
// in increasing particle index within a cell (the sort is stable). Cell order, not Morton
// order: the counting sort needs nothing but the linear index, and the cells of one stencil row
// (fixed y, z) are then adjacent, so the search reads a row as one contiguous range. With ~8
// (h/dx = 2) to ~27 (h/dx = 3) particles per cell, the rows of a stencil are a few kB apart at
// rank-sized grids; Morton order would shorten the y/z strides of very large grids, at the price
// of a key per cell and broken rows.
//
// Extent per axis: a periodic axis is cut into n = floor(period / h') cells of edge
// period / n >= h' (h' = h (1 + 1e-6), a margin against round-off); it needs period > 2 h. A
// non-periodic axis spans the particles' bounding box (recomputed each build), or the domain
// given by setDomain(); n = floor(extent / h') + 1 cells of edge h', so an axis of zero extent
// (z in 2D) has exactly one cell and the neighbour stencil stays 3 x 3. Positions outside the
// grid (outside a fixed domain, or query points of another cloud) are clamped into the edge
// cells; that keeps every neighbour within h reachable from the clamped cell, only slower.
//
// Buffers are kept between builds: a rebuild allocates only when it needs more than any earlier
// build did. build() throws Error for non-finite positions (naming the first one and how many)
// and for a grid of more than maxCellCount cells (default 2^26 = 67,108,864, i.e. 256 MiB of
// cell offsets), e.g. when one particle has flown far away.
class CellGrid {
 public:
  static constexpr std::size_t defaultMaxCellCount = std::size_t(1) << 26;

  // radius: the neighbour search radius (the kernel's support radius h); > 0 and finite.
  explicit CellGrid(Real radius, const PeriodicBox& periodic = PeriodicBox(),
                    std::size_t maxCellCount = defaultMaxCellCount);

  // Fixes the non-periodic extent to [lower, upper] instead of the bounding box of each build.
  void setDomain(const Vector& lower, const Vector& upper);
  // Goes back to the bounding box of the particles (the default).
  void useBoundingBox();

  // Bins the particles; parallel where it pays (OpenMP), the scatter is serial and stable.
  void build(const std::vector<Vector>& positions);

  // The permutation that orders the particles by cell (stable): entry k is the index of the
  // particle that comes k-th. Use as cloud.reorder(grid.sortPermutation()), then call
  // adoptCellOrder() (or build() again) so the grid matches the reordered cloud.
  const std::vector<std::size_t>& sortPermutation();
  // After the cloud was reordered with sortPermutation(): particle k is now the k-th in cell
  // order, so the grid is renumbered (O(N), no re-binning).
  void adoptCellOrder();

  Real radius() const { return radius_; }
  const PeriodicBox& periodicBox() const { return periodic_; }
  std::size_t particleCount() const { return cellOfParticle_.size(); }
  std::array<std::uint32_t, 3> cellCounts() const { return cellCounts_; }
  std::size_t cellCount() const { return cellStart_.empty() ? 0 : cellStart_.size() - 1; }
  Vector origin() const { return origin_; }
  Vector cellSize() const { return cellSize_; }

  // Cell coordinates (cx, cy, cz) of any point, wrapped on periodic axes and clamped into the
  // grid on the others. Needs a finite x.
  std::array<std::uint32_t, 3> cellCoordinates(const Vector& x) const;
  // The same, and where x lies along each axis in its cell, as a fraction of the cell edge in
  // [0, 1). For a clamped point it is the fraction in its unclamped cell, so distances from it
  // to the grid's cells are underestimated, never over (the search prunes with them).
  std::array<std::uint32_t, 3> cellCoordinates(const Vector& x,
                                               std::array<double, 3>& fraction) const;
  std::uint32_t cellIndex(const std::array<std::uint32_t, 3>& cell) const {
    return cell[0] + cellCounts_[0] * (cell[1] + cellCounts_[1] * cell[2]);
  }
  // The cell of particle i of the last build.
  std::uint32_t cellOfParticle(std::size_t i) const { return cellOfParticle_[i]; }

  // Bytes the grid holds now (capacities of its arrays).
  std::size_t memoryBytes() const;

  const std::vector<std::uint32_t>& cellStart() const { return cellStart_; }
  const std::vector<std::uint32_t>& particlesByCell() const { return particlesByCell_; }
  // True when particlesByCell() is the identity (the cloud is in cell order: after
  // adoptCellOrder(), or a build() that found it so); the neighbour search then reads the
  // positions of a cell range directly, without the index indirection.
  bool inCellOrder() const { return inCellOrder_; }

  // True when a neighbour search may take the periodic image of a whole stencil cell instead of
  // rounding every pair's separation: every periodic axis has >= 3 cells and the particles of
  // the last build lie in their cells without wrapping (inside [lower, lower + period)). Then
  // for each pair closer than the radius, separation() subtracts exactly the image shift of
  // x_j's cell in x_i's stencil (period * -1 for cell n - 1 seen from cell 0, period * +1 for
  // cell 0 from cell n - 1, else 0): the unwrapped distance to the stencil image is < 2 edges,
  // any other image is > period - 2 edges >= 1 edge > the radius away.
  bool imagesByCell() const { return imagesByCell_; }
  // The same for query points (of another cloud) inside the box [lower, upper].
  bool imagesByCell(const Vector& lower, const Vector& upper) const;

 private:
  void fitAxes(const Vector& boxLower, const Vector& boxUpper);
  void countingSort();

  Real radius_;
  PeriodicBox periodic_;
  std::size_t maxCellCount_;
  bool fixedDomain_ = false;
  Vector domainLower_ = Vector::Zero();
  Vector domainUpper_ = Vector::Zero();

  Vector origin_ = Vector::Zero();
  Vector cellSize_ = Vector::Ones();
  Vector inverseCellSize_ = Vector::Ones();
  std::array<std::uint32_t, 3> cellCounts_{1, 1, 1};

  std::vector<std::uint32_t> cellOfParticle_;   // per particle
  std::vector<std::uint32_t> cellStart_;        // per cell, + 1
  std::vector<std::uint32_t> particlesByCell_;  // per particle
  std::vector<std::size_t> permutation_;        // per particle, filled by sortPermutation()
  bool inCellOrder_ = true;
  bool imagesByCell_ = false;
};

}  // namespace sphcast
