#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/Real.h"
#include "particles/CellGrid.h"
#include "particles/NeighbourList.h"

namespace sphcast {

// The least distance, in particle spacings, a fluid particle keeps from a wall surface: the
// flow moves back any that come closer (sph/WallClearance.h), and setCastFields fills no
// particle closer. A fluid at rest sits half a spacing in front of the surface; an impact
// presses it closer. A quarter spacing leaves the wall pressure to do the work wherever it can.
constexpr double wallClearanceInSpacings = 0.25;

// What a wall cloud offers the clearance pass: its particles' positions, unit normals (out of
// the wall into the fluid), depths behind the wall surface, and each fluid particle's wall
// neighbours.
struct WallSurfaceView {
  std::span<const Vector> position;
  std::span<const Vector> normal;
  std::span<const Real> depth;
  const NeighbourList* neighboursOfFluid;  // fluid particle i -> wall particles within h
};

// The wall surface seen from fluid particle i, estimated from its wall neighbours: each wall
// particle k carries the tangent plane of the surface at its foot, so
//   d_ik = (x_i - x_k) . n_k - depth_k
// is i's distance in front of that plane. The planes of the wall particles laterally within one
// spacing of i are taken, and the smallest d_ik wins: at a concave corner this is the nearer of
// the two walls; on a curved wall of radius R the lateral offset s <= dx errs by at most
// s^2 / (2 R) (0.05 dx at R = 10 dx). Without such a neighbour the nearest wall particle's plane
// is used. `found` is false when i has no wall neighbour at all.
struct WallSurfaceDistance {
  bool found = false;
  Real distance = 0;             // in front of the surface (negative: behind it)
  Vector normal = Vector::Zero();
};

WallSurfaceDistance wallSurfaceDistance(const Vector& x, std::size_t i,
                                        const std::vector<WallSurfaceView>& walls,
                                        const PeriodicBox& periodic, Real spacing);

}  // namespace sphcast
