#include "geometry/LatticeFill.h"

#include <array>
#include <cmath>

namespace sphcast {

namespace {

// Cells along one axis: round(extent / spacing), at least one (a flat axis is one layer).
std::size_t cellsAlong(double extent, double spacing) {
  const double cells = std::round(extent / spacing);
  return cells < 1.0 ? 1 : static_cast<std::size_t>(cells);
}

}  // namespace

double latticeCountInBox(const Vector& lower, const Vector& upper, double spacing) {
  double count = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    count *= static_cast<double>(
        cellsAlong(static_cast<double>(upper[axis] - lower[axis]), spacing));
  }
  return count;
}

std::vector<Vector> fillBoxOnLattice(const Vector& lower, const Vector& upper, double spacing) {
  std::array<std::size_t, 3> cells{};
  std::array<double, 3> first{};
  for (int axis = 0; axis < 3; ++axis) {
    const double extent = static_cast<double>(upper[axis] - lower[axis]);
    cells[axis] = cellsAlong(extent, spacing);
    // Centre the lattice in the box: exact when the extent is a multiple of the spacing.
    first[axis] = static_cast<double>(lower[axis]) + 0.5 * extent -
                  0.5 * spacing * static_cast<double>(cells[axis] - 1);
  }
  std::vector<Vector> centres;
  centres.reserve(cells[0] * cells[1] * cells[2]);
  for (std::size_t k = 0; k < cells[2]; ++k) {
    for (std::size_t j = 0; j < cells[1]; ++j) {
      for (std::size_t i = 0; i < cells[0]; ++i) {
        centres.emplace_back(static_cast<Real>(first[0] + spacing * static_cast<double>(i)),
                             static_cast<Real>(first[1] + spacing * static_cast<double>(j)),
                             static_cast<Real>(first[2] + spacing * static_cast<double>(k)));
      }
    }
  }
  return centres;
}

}  // namespace sphcast
