#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/Real.h"
#include "particles/CellGrid.h"
#include "particles/NeighbourList.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The least distance, in particle spacings, a fluid particle keeps from a wall surface: the
// flow moves back any that come closer (sph/WallClearance.h), and setCastFields fills no
// particle closer. A fluid at rest sits half a spacing in front of the surface; an impact
// presses it closer. A quarter spacing leaves the wall pressure to do the work wherever it can.
constexpr double wallClearanceInSpacings = 0.25;

// What a wall cloud offers the clearance pass: its particles' positions, unit normals (out of
// the wall into the fluid), depths behind the wall surface, velocities (empty for a wall at
// rest; a moving mold's, bodies/RigidBody.h), and each fluid particle's wall neighbours.
struct WallSurfaceView {
  std::span<const Vector> position;
  std::span<const Vector> normal;
  std::span<const Real> depth;
  const NeighbourList* neighboursOfFluid;  // fluid particle i -> wall particles within h
  std::span<const Vector> velocity = {};
};

// The wall surface seen from fluid particle i, estimated from its wall neighbours: each wall
// particle k marks the surface point s_k = x_k + d_k n_k (its foot: depth d_k along the normal
// n_k) and the tangent plane there, on a patch of the surface about one spacing across. The
// feet whose patch i lies over (i's projection on the plane within 0.75 dx of the foot: the
// farthest a point lies from its nearest foot on the lattice of a flat wall is dx/sqrt(2)) give
//   d_ik = (x_i - s_k) . n_k,
// and the smallest is i's distance in front of the surface: at a concave corner, the nearer
// wall. Two kinds of plane are left out, each of which i can lie behind without being in the
// body: the other face's at a convex edge (its patches do not lie under i), and the far face's
// of a thin body, which puts i more than a spacing behind it (no particle gets so deep: a step
// moves it by at most maxCo dx, and the health checks stop a run at 0.5 dx). Without them, the
// smallest plane distance of the wall particles within dx put a particle flowing past the
// one-layer obstacle of SPHERIC Test 2 2.9 spacings "behind" a wall, and one above a convex
// ledge a spacing behind it. On a curved wall of radius R the estimate errs by at most
// (0.75 dx)^2 / (2 R); inside a concave wall it never underestimates. A patch reaches 0.75 dx past
// a sharp convex edge (faces more than 30 degrees apart), where i can lie over the patch of one
// face and in front of the other: when i is behind a plane, that plane is set aside if i lies in
// front of a plane (foot within 2 dx along it) with which it makes a sharp convex edge (its foot
// behind the other's plane), since the body is behind both; if i is behind all such planes, it
// is inside the body's convex edge or corner (the intersection of the faces' half-spaces) and
// the plane reads the largest of their distances: the depth behind the nearest face, exact
// there. A plane with no such partner is set aside when i lies past an open edge of its face (a
// shell's rim: i's projection more than dx/2 from the foot and no foot of the face as far in
// that direction), since i is then over the wall, not in it. `found` is false when no
// wall neighbour's patch lies under i (no wall near, or i beyond a convex edge whose particles
// all face the other way): the clearance then leaves i alone.
struct WallSurfaceDistance {
  bool found = false;
  Real distance = 0;  // in front of the surface (negative: behind it)
  Vector normal = Vector::Zero();
  std::size_t wall = 0;      // the view whose particle gave it
  std::uint32_t particle = 0;  // that particle
};

// The views of `walls` (clouds with `normal` and `wallDistance`, as particleizeMold writes them,
// and `U` when they move) seen from `fluid`, with the fluid's wall neighbours of the
// neighbourhood's last update.
std::vector<WallSurfaceView> wallSurfaceViews(const ParticleCloud& fluid,
                                              const std::vector<const ParticleCloud*>& walls,
                                              const Neighbourhood& neighbourhood);

WallSurfaceDistance wallSurfaceDistance(const Vector& x, std::size_t i,
                                        const std::vector<WallSurfaceView>& walls,
                                        const PeriodicBox& periodic, Real spacing);

}  // namespace sphcast
