#pragma once

#include <cmath>

#include "particles/ParticleCloud.h"

namespace sphcast::testing {

// A 2D block of fluid particles on a lattice of spacing dx, cell centres from lower.
inline ParticleCloud fluidBlock2D(int columns, int rows, Real dx, const Vector& lower, Real density,
                                  Real viscosity) {
  ParticleCloud fluid("fluid");
  fluid.resize(static_cast<std::size_t>(columns * rows));
  auto& U = fluid.addVectorField("U");
  auto& rho = fluid.addScalarField("rho");
  auto& mass = fluid.addScalarField("mass");
  auto& mu = fluid.addScalarField("viscosity");
  auto& rest = fluid.addScalarField("restDensity");
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
      wall.scalarField("volume")[k] = dx * dx;
      const Vector normal = normalOf(column, row).normalized();
      wall.vectorField("normal")[k] = normal;
      wall.scalarField("wallDistance")[k] = depthOf(column, row);
    }
  }
}

inline ParticleCloud emptyWall() {
  ParticleCloud wall("wall");
  wall.addScalarField("volume");
  wall.addVectorField("normal");
  wall.addScalarField("wallDistance");
  return wall;
}

}  // namespace sphcast::testing
