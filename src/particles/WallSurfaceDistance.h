#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
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

// How far around a point the wall particles must be looked at to read the surface there: a foot
// beside an edge off the lattice stands for up to about 2 dx of its face, from a particle up to a
// spacing behind it (geometry/WallSurfacePatches.h). The flow looks within its support radius,
// which is at least this in every case here.
constexpr double wallSurfaceReachInSpacings = 2.5;

// What a wall cloud offers the clearance pass: its particles' positions, unit normals (out of
// the wall into the fluid), depths behind the wall surface, velocities (empty for a wall at
// rest; a moving mold's, bodies/RigidBody.h), each fluid particle's wall neighbours, and the
// radius of surface each particle's foot stands for (particleizeMold's wallPatchRadius,
// geometry/WallSurfacePatches.h; empty: 0.75 dx each).
struct WallSurfaceView {
  std::span<const Vector> position;
  std::span<const Vector> normal;
  std::span<const Real> depth;
  const NeighbourList* neighboursOfFluid;  // fluid particle i -> wall particles within h
  std::span<const Vector> velocity = {};
  std::span<const Real> patchRadius = {};
  // Second feet (particleizeMold's secondNormal, secondWallDistance, secondWallPatchRadius; a
  // radius of 0 for a particle without): empty when the cloud has none.
  std::span<const Vector> secondNormal = {};
  std::span<const Real> secondDepth = {};
  std::span<const Real> secondPatchRadius = {};
  // 1 where a particle's first foot stands for a piece of an open rim (wallPatchAtRim); empty
  // when the cloud has none.
  std::span<const Real> patchAtRim = {};
};

// The wall surface seen from fluid particle i, estimated from its wall neighbours: each wall
// particle k marks the surface point s_k = x_k + d_k n_k (its foot: depth d_k along the normal
// n_k) and the tangent plane there, on a patch of the surface about the foot. The feet whose
// patch i lies over (i's projection on the plane within the patch's radius of the foot) give
//   d_ik = (x_i - s_k) . n_k,
// and the smallest is i's distance in front of the surface: at a concave corner, the nearer
// wall. The patch's radius is the one particleizeMold worked out (geometry/WallSurfacePatches.h:
// the farthest point of the foot's share of the surface, so that the patches cover every face to
// its edges, off the lattice too; a particle with a second foot, on a face no first foot stands
// for near it, offers both); for a cloud without it, 0.75 dx (the farthest a point lies from its
// nearest foot on the lattice of a flat wall is dx/sqrt(2)). The far face of a thin body is left
// out: it puts i more than a spacing behind it (no particle gets so deep: a step moves it by at
// most maxCo dx, and the health checks stop a run at 0.5 dx); without that, a particle flowing
// past the one-layer obstacle of SPHERIC Test 2 was read 2.9 spacings "behind" a wall. On a
// curved wall of radius R the estimate errs by at most r^2 / (2 R) for a patch of radius r;
// inside a concave wall it never underestimates.
//
// At a sharp convex edge (faces more than 30 degrees apart) a patch can reach past the edge, and
// a plane read there bounds the body on one side only. So a plane that reads i nearer than
// `near` (below; half a spacing unless the caller asks less), or behind it, is read with its
// partner: the plane in front of which i lies farthest among those it makes a sharp convex edge
// with (each foot behind the other's plane or on it, one strictly behind; and i over the
// partner's patch but for 0.6 dx across the edge, not beyond it along the edge: past a face's
// end its plane bounds nothing). The body there is the wedge behind both
// planes, and i's distance from it is exact for a straight edge: behind both, the depth behind
// the nearer face; in front of one, the distance to that face where i's foot on it lies behind
// the other plane, else to the edge itself, out along the edge's normal. Without it, metal
// beside the crossing's vertical convex edges of tutorials/crossDitchPress was read 0.8 dx
// behind the other arm's wall, metal inside the corner where an arm meets the pocket floor 0.6
// dx too deep, and metal half a spacing off one face of an edge read at the other face's plane
// (and moved by a quarter spacing). Where three faces meet, the wedge of two is an approximation
// (tests/unit/geometry/MoldWallSurfaceTest.cpp measures it). A plane that reads i behind it
// with no partner is set aside when i lies past an open edge of its face (a shell's rim: i's
// projection more than dx/2 from the foot and no foot of the face as far in that direction),
// since i is then over the wall, not in it: for the feet whose patch reaches a rim (particleize-
// Mold marks them: a disc that covers the face up to the rim reaches as far past it), and for
// every foot of a cloud without patch radii (2D walls, molds of an older particleizeMold).
// `found` is false when no wall neighbour's patch lies under i (no wall near, or i beyond a
// convex edge): the clearance leaves i alone.
struct WallSurfaceDistance {
  bool found = false;
  Real distance = 0;  // in front of the surface (negative: behind it)
  Vector normal = Vector::Zero();
  std::size_t wall = 0;        // the view whose particle gave it
  std::uint32_t particle = 0;  // that particle
};

// The views of `walls` (clouds with `normal` and `wallDistance`, as particleizeMold writes them,
// and `U` when they move) seen from `fluid`, with the fluid's wall neighbours of the
// neighbourhood's last update.
std::vector<WallSurfaceView> wallSurfaceViews(const ParticleCloud& fluid,
                                              const std::vector<const ParticleCloud*>& walls,
                                              const Neighbourhood& neighbourhood);

// `near` (in spacings): how near the surface a reading is refined at sharp convex edges (the
// wedge, above). The wedge never lowers a reading, so a caller that acts only on readings below
// some distance (the clearance) may pass that distance and skip the refinement beyond it.
WallSurfaceDistance wallSurfaceDistance(const Vector& x, std::size_t i,
                                        const std::vector<WallSurfaceView>& walls,
                                        const PeriodicBox& periodic, Real spacing,
                                        Real near = Real(0.5));

// The gap between facing walls at fluid particle i (at x), among its wall neighbours: its width,
// i's distance in front of its nearest wall surface (wallSurfaceDistance, normal n) plus its
// distance in front of the nearest foot facing that wall (its normal within 45 degrees of -n);
// infinity where no such foot is in front of i, or the nearest wall is a support radius `reach`
// or more away. `cover`: how fully the facing wall stands over i, 1 over its feet's patches
// (within a patch's radius of a foot, along its plane), fading to 0 at one and a half radii:
// past the facing wall's end (a punch's edge) the gap ends smoothly. For the surface tension's
// meniscus in a gap narrower than the kernel (surface/ContinuumSurfaceForce.h).
struct WallGap {
  Real width = std::numeric_limits<Real>::infinity();
  Real cover = 0;
};
WallGap wallGapAcross(const Vector& x, std::size_t i, const std::vector<WallSurfaceView>& walls,
                      const PeriodicBox& periodic, Real spacing, Real reach);

}  // namespace sphcast
