#pragma once

#include <algorithm>
#include <cmath>

#include "particles/FieldNames.h"
#include "particles/ParticleCloud.h"

namespace sphcast::testing {

// A 2D block of fluid particles on a lattice of spacing dx, cell centres from lower.
inline ParticleCloud fluidBlock2D(int columns, int rows, Real dx, const Vector& lower, Real density,
                                  Real viscosity) {
  ParticleCloud fluid("fluid");
  fluid.resize(static_cast<std::size_t>(columns * rows));
  auto& U = fluid.addVectorField(field::U);
  auto& rho = fluid.addScalarField(field::rho);
  auto& mass = fluid.addScalarField(field::mass);
  auto& mu = fluid.addScalarField(field::viscosity);
  auto& rest = fluid.addScalarField(field::restDensity);
  std::size_t i = 0;
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column, ++i) {
      fluid.positions()[i] = lower + Vector((column + Real(0.5)) * dx, (row + Real(0.5)) * dx, 0);
      U[i] = Vector::Zero();
      rho[i] = rest[i] = density;
      mass[i] = density * dx * dx;
      mu[i] = viscosity;
    }
  }
  fluid.attributes()["spacing"] = dx;
  return fluid;
}

// Wall particles of volume dx^2 in the given rows and columns (cell indices relative to the
// lattice of fluidBlock2D at the same origin: negative rows lie below the fluid), with the normal
// pointing towards the fluid given by normalOf(column, row) and the depth behind the wall
// surface by depthOf(column, row).
template <class NormalOf, class DepthOf>
inline void addWallCells(ParticleCloud& wall, int columnBegin, int columnEnd, int rowBegin,
                         int rowEnd, Real dx, const Vector& lower, NormalOf normalOf,
                         DepthOf depthOf) {
  for (int row = rowBegin; row < rowEnd; ++row) {
    for (int column = columnBegin; column < columnEnd; ++column) {
      const std::size_t k = wall.size();
      wall.resize(k + 1);
      wall.positions()[k] = lower + Vector((column + Real(0.5)) * dx, (row + Real(0.5)) * dx, 0);
      wall.scalarField(field::volume)[k] = dx * dx;
      const Vector normal = normalOf(column, row).normalized();
      wall.vectorField(field::normal)[k] = normal;
      wall.scalarField(field::wallDistance)[k] = depthOf(column, row);
    }
  }
}

// Wall particles in the cells [columnBegin, columnEnd) x [rowBegin, rowEnd) where inside(column,
// row), particleized at graded spacing as particleizeMold grades a volume (geometry/
// GradedVolume.h): each 2 x 2 block of cells (aligned on columnBegin, rowBegin) whose four cells
// are inside and none fine(column, row) is one particle of 2 dx at the block's centre, of volume
// 4 dx^2; the other cells inside are particles of dx. Each particle has the field localSpacing,
// its normal normalAt(x) and its depth depthAt(x) (x in spacings from `lower`).
template <class Inside, class Fine, class NormalAt, class DepthAt>
inline void addGradedWallCells(ParticleCloud& wall, int columnBegin, int columnEnd, int rowBegin,
                               int rowEnd, Real dx, const Vector& lower, Inside inside, Fine fine,
                               NormalAt normalAt, DepthAt depthAt) {
  if (!wall.hasScalarField(field::localSpacing)) wall.addScalarField(field::localSpacing);
  const auto add = [&](Real column, Real row, Real spacing) {
    const std::size_t k = wall.size();
    wall.resize(k + 1);
    const Vector at(column, row, 0);
    wall.positions()[k] = lower + at * dx;
    wall.scalarField(field::volume)[k] = spacing * spacing;
    wall.scalarField(field::localSpacing)[k] = spacing;
    wall.vectorField(field::normal)[k] = normalAt(at).normalized();
    wall.scalarField(field::wallDistance)[k] = depthAt(at) * dx;
  };
  for (int row = rowBegin; row < rowEnd; row += 2) {
    for (int column = columnBegin; column < columnEnd; column += 2) {
      bool coarse = true;
      for (int r = row; r < row + 2; ++r) {
        for (int c = column; c < column + 2; ++c) coarse = coarse && inside(c, r) && !fine(c, r);
      }
      if (coarse) {
        add(Real(column + 1), Real(row + 1), 2 * dx);
        continue;
      }
      for (int r = row; r < std::min(row + 2, rowEnd); ++r) {
        for (int c = column; c < std::min(column + 2, columnEnd); ++c) {
          if (inside(c, r)) add(Real(c) + Real(0.5), Real(r) + Real(0.5), dx);
        }
      }
    }
  }
}

inline ParticleCloud emptyWall(const std::string& name = "wall") {
  ParticleCloud wall(name);
  wall.addScalarField(field::volume);
  wall.addVectorField(field::normal);
  wall.addScalarField(field::wallDistance);
  return wall;
}

// A 2D open tank of three wall layers round the lattice of fluidBlock2D at the origin: a floor
// under columns [0, columns) and side walls `rows` high at both ends, each wall particle's normal
// towards the fluid and its depth behind the wall surface.
inline ParticleCloud tankWalls2D(int columns, int rows, Real dx) {
  constexpr int layers = 3;
  auto outside = [=](int column, int row) {
    const Real ox =
        column < 0 ? Real(column + 0.5) : (column >= columns ? Real(column - columns + 0.5) : 0);
    const Real oy = row < 0 ? Real(row + 0.5) : 0;
    return Vector(ox, oy, 0);
  };
  auto normal = [=](int column, int row) { return Vector(-outside(column, row)); };
  auto depth = [=](int column, int row) { return outside(column, row).norm() * dx; };
  ParticleCloud wall = emptyWall();
  addWallCells(wall, -layers, columns + layers, -layers, 0, dx, Vector::Zero(), normal, depth);
  addWallCells(wall, -layers, 0, 0, rows, dx, Vector::Zero(), normal, depth);
  addWallCells(wall, columns, columns + layers, 0, rows, dx, Vector::Zero(), normal, depth);
  return wall;
}

}  // namespace sphcast::testing
