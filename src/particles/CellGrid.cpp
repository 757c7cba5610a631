#include "particles/CellGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "core/Error.h"

namespace sphcast {
namespace {

// The cell edge is the radius times this margin, so that a pair closer than the radius never
// lands two cells apart through round-off in (x - origin) / cellSize (evaluated in double; the
// relative error of a float Real is ~1e-7).
constexpr double cellMargin = 1.0 + 1e-6;

// Below this many particles the light per-particle loops run on one thread: a parallel region
// costs more than the loop (and much more on a machine whose cores other jobs share).
constexpr std::size_t parallelThreshold = 32768;

const char* axisName(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

std::string formatVector(const Vector& x) {
  std::ostringstream text;
  text.precision(9);
  text << '(' << x[0] << ' ' << x[1] << ' ' << x[2] << ')';
  return text.str();
}

struct BoundingBox {
  Vector lower;
  Vector upper;
  std::size_t nonFinite = 0;  // how many particles
  std::size_t firstNonFinite = std::numeric_limits<std::size_t>::max();
};

// One parallel pass: bounding box of the finite positions and the count of non-finite ones.
BoundingBox scanPositions(const std::vector<Vector>& positions) {
  constexpr Real big = std::numeric_limits<Real>::max();
  Real lo0 = big, lo1 = big, lo2 = big, hi0 = -big, hi1 = -big, hi2 = -big;
  std::size_t nonFinite = 0, firstNonFinite = std::numeric_limits<std::size_t>::max();
  const std::size_t count = positions.size();
#pragma omp parallel for if (count > parallelThreshold)                        \
    reduction(min : lo0, lo1, lo2, firstNonFinite) reduction(max : hi0, hi1, hi2) \
    reduction(+ : nonFinite)
  for (std::size_t i = 0; i < count; ++i) {
    const Vector& x = positions[i];
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) {
      ++nonFinite;
      firstNonFinite = std::min(firstNonFinite, i);
      continue;
    }
    lo0 = std::min(lo0, x[0]), lo1 = std::min(lo1, x[1]), lo2 = std::min(lo2, x[2]);
    hi0 = std::max(hi0, x[0]), hi1 = std::max(hi1, x[1]), hi2 = std::max(hi2, x[2]);
  }
  return {Vector(lo0, lo1, lo2), Vector(hi0, hi1, hi2), nonFinite, firstNonFinite};
}

}  // namespace

CellGrid::CellGrid(Real radius, const PeriodicBox& periodic, std::size_t maxCellCount)
    : radius_(radius),
      periodic_(periodic),
      // cell indices and cell offsets are 32-bit
      maxCellCount_(
          std::min<std::size_t>(maxCellCount, std::numeric_limits<std::uint32_t>::max() - 1)) {
  if (!std::isfinite(radius) || !(radius > Real(0))) {
    throw Error("CellGrid: the search radius must be finite and > 0, got " +
                std::to_string(radius));
  }
  for (int a = 0; a < 3; ++a) {
    if (!periodic.isPeriodic(a)) continue;
    const double period = double(periodic.period(a));
    const double cells = std::floor(period / (double(radius) * cellMargin));
    if (cells < 2.0) {
      throw Error(std::string("CellGrid: periodic axis ") + axisName(a) + " has period " +
                  std::to_string(period) + ", which must exceed twice the search radius " +
                  std::to_string(radius) + " (minimum image)");
    }
    if (cells > double(maxCellCount)) {
      throw Error(std::string("CellGrid: periodic axis ") + axisName(a) + " would need " +
                  std::to_string(cells) +
                  " cells, more than the limit maxCellCount = " + std::to_string(maxCellCount));
    }
    cellCounts_[a] = static_cast<std::uint32_t>(cells);
    origin_[a] = periodic.lower(a);
    cellSize_[a] = Real(period / cells);
    inverseCellSize_[a] = Real(cells / period);
  }
}

void CellGrid::setDomain(const Vector& lower, const Vector& upper) {
  if (!lower.allFinite() || !upper.allFinite() || (upper.array() < lower.array()).any()) {
    throw Error("CellGrid: domain " + formatVector(lower) + " to " + formatVector(upper) +
                " is not a finite box with lower <= upper");
  }
  fixedDomain_ = true;
  domainLower_ = lower;
  domainUpper_ = upper;
}

void CellGrid::useBoundingBox() { fixedDomain_ = false; }

void CellGrid::build(const std::vector<Vector>& positions) {
  const std::size_t count = positions.size();
  if (count >= std::numeric_limits<std::uint32_t>::max()) {
    throw Error("CellGrid: " + std::to_string(count) +
                " particles do not fit 32-bit particle indices (one grid per MPI rank)");
  }
  const BoundingBox box = scanPositions(positions);
  if (box.nonFinite > 0) {
    throw Error("CellGrid: " + std::to_string(box.nonFinite) +
                " particle(s) with a non-finite position, the first is particle " +
                std::to_string(box.firstNonFinite) + " at " +
                formatVector(positions[box.firstNonFinite]));
  }
  if (count == 0) {
    fitAxes(Vector::Zero(), Vector::Zero());
    imagesByCell_ = imagesByCell(origin_, origin_);
  } else {
    fitAxes(box.lower, box.upper);
    imagesByCell_ = imagesByCell(box.lower, box.upper);
  }

  cellOfParticle_.resize(count);
#pragma omp parallel for if (count > parallelThreshold)
  for (std::size_t i = 0; i < count; ++i) {
    cellOfParticle_[i] = cellIndex(cellCoordinates(positions[i]));
  }
  countingSort();
}

void CellGrid::fitAxes(const Vector& boxLower, const Vector& boxUpper) {
  const Vector lower = fixedDomain_ ? domainLower_ : boxLower;
  const Vector upper = fixedDomain_ ? domainUpper_ : boxUpper;
  const double edge = double(radius_) * cellMargin;
  double total = 1.0;
  std::array<double, 3> cells{};
  for (int a = 0; a < 3; ++a) {
    cells[a] = periodic_.isPeriodic(a)
                   ? double(cellCounts_[a])
                   : std::floor((double(upper[a]) - double(lower[a])) / edge) + 1.0;
    total *= cells[a];
  }
  if (!(total <= double(maxCellCount_))) {
    throw Error("CellGrid: the box " + formatVector(lower) + " to " + formatVector(upper) +
                " with cell size " + std::to_string(edge) + " would need " +
                std::to_string(cells[0]) + " x " + std::to_string(cells[1]) + " x " +
                std::to_string(cells[2]) + " = " + std::to_string(total) +
                " cells, more than the limit maxCellCount = " + std::to_string(maxCellCount_) +
                " (a particle far away from the others?)");
  }
  for (int a = 0; a < 3; ++a) {
    if (periodic_.isPeriodic(a)) continue;
    cellCounts_[a] = static_cast<std::uint32_t>(cells[a]);
    origin_[a] = lower[a];
    cellSize_[a] = Real(edge);
    inverseCellSize_[a] = Real(1.0 / edge);
  }
}

bool CellGrid::imagesByCell(const Vector& lower, const Vector& upper) const {
  for (int a = 0; a < 3; ++a) {
    if (!periodic_.isPeriodic(a)) continue;
    if (cellCounts_[a] < 3) return false;  // with 2 cells, the cell before is the cell after
    // (x - origin) / edge is monotone in x, as cellCoordinates evaluates it: the box's corners
    // bound every point's unwrapped cell
    const double first =
        std::floor((double(lower[a]) - double(origin_[a])) * double(inverseCellSize_[a]));
    const double last =
        std::floor((double(upper[a]) - double(origin_[a])) * double(inverseCellSize_[a]));
    if (!(first >= 0.0 && last <= double(cellCounts_[a]) - 1.0)) return false;
  }
  return true;
}

std::array<std::uint32_t, 3> CellGrid::cellCoordinates(const Vector& x) const {
  std::array<double, 3> fraction;
  return cellCoordinates(x, fraction);
}

std::array<std::uint32_t, 3> CellGrid::cellCoordinates(const Vector& x,
                                                       std::array<double, 3>& fraction) const {
  std::array<std::uint32_t, 3> cell{};
  for (int a = 0; a < 3; ++a) {
    const double cells = double(cellCounts_[a]);
    const double scaled = (double(x[a]) - double(origin_[a])) * double(inverseCellSize_[a]);
    double c = std::floor(scaled);
    fraction[a] = std::clamp(scaled - c, 0.0, 1.0);
    if (periodic_.isPeriodic(a)) c -= cells * std::floor(c / cells);  // wrap into [0, n)
    cell[a] = static_cast<std::uint32_t>(std::clamp(c, 0.0, cells - 1.0));
  }
  return cell;
}

// Counting sort by cell (Knuth, TAOCP vol. 3, 5.2 "distribution counting"): histogram, running
// sum (each entry the end of its cell), then a backward scatter that leaves every entry at the
// start of its cell and keeps particles of a cell in increasing index order (stable).
void CellGrid::countingSort() {
  const std::size_t cells =
      std::size_t(cellCounts_[0]) * std::size_t(cellCounts_[1]) * std::size_t(cellCounts_[2]);
  const std::size_t count = cellOfParticle_.size();
  cellStart_.assign(cells + 1, 0);
  for (std::size_t i = 0; i < count; ++i) ++cellStart_[cellOfParticle_[i]];
  for (std::size_t c = 1; c < cells; ++c) cellStart_[c] += cellStart_[c - 1];
  particlesByCell_.resize(count);
  bool identity = true;  // every particle stays where it is: the cloud is in cell order
  for (std::size_t i = count; i-- > 0;) {
    const std::uint32_t k = --cellStart_[cellOfParticle_[i]];
    particlesByCell_[k] = static_cast<std::uint32_t>(i);
    identity = identity && k == i;
  }
  cellStart_[cells] = static_cast<std::uint32_t>(count);
  inCellOrder_ = identity;
}

const std::vector<std::size_t>& CellGrid::sortPermutation() {
  permutation_.assign(particlesByCell_.begin(), particlesByCell_.end());
  return permutation_;
}

void CellGrid::adoptCellOrder() {
  const std::size_t cells = cellCount();
#pragma omp parallel for schedule(static, 1024) if (particleCount() > parallelThreshold)
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::uint32_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
      particlesByCell_[k] = k;
      cellOfParticle_[k] = static_cast<std::uint32_t>(c);
    }
  }
  inCellOrder_ = true;
}

std::size_t CellGrid::memoryBytes() const {
  return (cellOfParticle_.capacity() + cellStart_.capacity() + particlesByCell_.capacity()) *
             sizeof(std::uint32_t) +
         permutation_.capacity() * sizeof(std::size_t);
}

}  // namespace sphcast
