#include "particles/WallSurfaceDistance.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Smoothstep.h"
#include "particles/FieldNames.h"

namespace sphcast {

std::vector<WallSurfaceView> wallSurfaceViews(const ParticleCloud& fluid,
                                              const std::vector<const ParticleCloud*>& walls,
                                              const Neighbourhood& neighbourhood) {
  std::vector<WallSurfaceView> views;
  for (const ParticleCloud* wall : walls) {
    views.push_back({wall->positions(), wall->vectorField(field::normal),
                     wall->scalarField(field::wallDistance), &neighbourhood.pairs(fluid, *wall),
                     wall->hasVectorField(field::U)
                         ? std::span<const Vector>(wall->vectorField(field::U))
                         : std::span<const Vector>(),
                     wall->hasScalarField(field::wallPatchRadius)
                         ? std::span<const Real>(wall->scalarField(field::wallPatchRadius))
                         : std::span<const Real>()});
    if (wall->hasScalarField(field::wallPatchAtRim)) {
      views.back().patchAtRim = wall->scalarField(field::wallPatchAtRim);
    }
    if (wall->hasScalarField(field::secondWallPatchRadius)) {
      views.back().secondNormal = wall->vectorField(field::secondNormal);
      views.back().secondDepth = wall->scalarField(field::secondWallDistance);
      views.back().secondPatchRadius = wall->scalarField(field::secondWallPatchRadius);
    }
  }
  return views;
}

namespace {

// A foot of wall particle k: the normal and depth that put it on the surface, the radius of the
// patch of surface it stands for, and whether that patch may reach past an open rim (the patch
// is a disc: where it covers the face up to a rim, it reaches as far past it): a foot whose
// patch was not worked out, or one particleizeMold marked.
struct Foot {
  Vector normal;
  Real depth;
  Real radius;
  bool nearARim;
  bool sampled;  // its radius was worked out by particleizeMold (not the 0.75 dx default)
};

// Calls visit(foot) for each foot of wall particle k: its first, and its second where
// particleizeMold gave it one (a thin part of the mold, an acute edge).
template <class Visit>
void forEachFoot(const WallSurfaceView& wall, std::uint32_t k, Real spacing, Visit&& visit) {
  const Real latticePatch = Real(0.75) * spacing;
  const bool worked = !wall.patchRadius.empty();
  visit(Foot{wall.normal[k], wall.depth[k], worked ? wall.patchRadius[k] : latticePatch,
             !worked || (!wall.patchAtRim.empty() && wall.patchAtRim[k] > 0), worked});
  if (!wall.secondPatchRadius.empty() && wall.secondPatchRadius[k] > 0) {
    visit(Foot{wall.secondNormal[k], wall.secondDepth[k], wall.secondPatchRadius[k], false, true});
  }
}

// x_i seen from a foot of wall particle k on the surface, s = x_k + d n: its distance along n,
// and the square of its distance along the foot's plane.
struct FootPlane {
  Vector fromFoot;
  Real distance;
  Real alongSquared;
};

FootPlane footPlane(const Vector& x, const WallSurfaceView& wall, std::uint32_t k, const Foot& foot,
                    const PeriodicBox& periodic) {
  const Vector fromFoot = periodic.separation(x, wall.position[k]) - foot.depth * foot.normal;
  const Real distance = fromFoot.dot(foot.normal);
  return {fromFoot, distance, fromFoot.squaredNorm() - distance * distance};
}

// A foot of one of x_i's wall neighbours, as x_i sees it.
struct SeenFoot {
  Foot foot;
  FootPlane plane;
  std::size_t wall;
  std::uint32_t particle;
};

// The feet of x_i's wall neighbours, into `feet` (cleared first).
void gatherFeet(const Vector& x, std::size_t i, const std::vector<WallSurfaceView>& walls,
                const PeriodicBox& periodic, Real spacing, std::vector<SeenFoot>& feet) {
  feet.clear();
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const WallSurfaceView& wall = walls[w];
    for (const std::uint32_t k : wall.neighboursOfFluid->of(i)) {
      forEachFoot(wall, k, spacing, [&](const Foot& foot) {
        feet.push_back({foot, footPlane(x, wall, k, foot, periodic), w, k});
      });
    }
  }
}

// Whether the edge where the planes of feet k and m meet is a sharp convex one (the planes more
// than 30 degrees apart): the body is then behind both planes, and a point in front of m's plane
// is outside it, whatever k's says. Each foot lies behind the other's plane, or on it: a foot on
// the edge itself (a particle on a face, its second foot on the other) is on both planes, and
// the other foot tells. At a concave edge each lies in front of the other's plane.
bool sharpConvexEdge(const Vector& footK, const Vector& normalK, const Vector& footM,
                     const Vector& normalM, Real spacing) {
  constexpr Real sharp = Real(0.866);  // cos 30 degrees
  const Real tolerance = Real(1e-3) * spacing;
  if (normalK.dot(normalM) >= sharp) return false;
  const Real kBehindM = (footK - footM).dot(normalM), mBehindK = (footM - footK).dot(normalK);
  return kBehindM < tolerance && mBehindK < tolerance && std::min(kBehindM, mBehindK) < -tolerance;
}

// Where each foot's share of its face is known (the patch radius r_m): whether x_i lies over
// foot m's patch but for up to 0.6 dx across the edge m's plane makes with plane K (x_i may lie
// that far off m's face beside the edge, over K's), not beyond the patch along the edge: the
// edge of a face ends where the face does, and past its end the other plane bounds nothing.
bool nearTheEdge(const FootPlane& plane, const Vector& normalM, const Vector& normalK, Real radius,
                 Real spacing) {
  const Vector along = plane.fromFoot - plane.distance * normalM;
  const Vector edge = normalK.cross(normalM).normalized();
  const Real alongEdge = along.dot(edge);
  const Real across = std::sqrt(std::max(Real(0), along.squaredNorm() - alongEdge * alongEdge));
  const Real acrossTrimmed = std::max(Real(0), across - Real(0.6) * spacing);
  return alongEdge * alongEdge + acrossTrimmed * acrossTrimmed <= radius * radius;
}

// The feet whose planes make a sharp convex edge with the plane of foot footK, which reads x_i
// behind it or near it (not the far face of a thin body; their patches under x_i by
// nearTheEdge, or, where patches were not worked out, their feet within 2 dx along): the largest
// distance in front of one of them, and that plane. The body near a convex edge is the wedge
// behind both planes (distanceToWedge).
struct ConvexPartner {
  bool found = false;
  Real distance = 0;
  Vector normal = Vector::Zero();
  std::size_t wall = 0;
  std::uint32_t particle = 0;
};

ConvexPartner convexPartner(const Vector& x, const Vector& footK, const Vector& normalK,
                            const std::vector<SeenFoot>& feet, Real spacing) {
  ConvexPartner partner;
  for (const SeenFoot& seen : feet) {
    const FootPlane& plane = seen.plane;
    const Foot& foot = seen.foot;
    if (plane.distance < -spacing) continue;
    if (!foot.sampled && plane.alongSquared > Real(4) * spacing * spacing) continue;
    if (partner.found && plane.distance <= partner.distance) continue;
    if (!sharpConvexEdge(footK, normalK, x - plane.fromFoot, foot.normal, spacing)) continue;
    if (foot.sampled && !nearTheEdge(plane, foot.normal, normalK, foot.radius, spacing)) continue;
    partner = {true, plane.distance, foot.normal, seen.wall, seen.particle};
  }
  return partner;
}

// Whether x_i, read behind foot k's plane with no sharp convex partner, lies past an open edge of
// k's face (a shell's rim, a face whose neighbour face has no particles), over which it is not in
// the body: its projection on the plane lies more than dx/2 from k's foot, and no foot of the
// same face (normal within 25 degrees, foot within dx/4 of k's plane and 1.5 dx of k's foot)
// lies at least as far in that direction. On a lattice a face ends dx/2 past its last row, and
// inside it the foot on the far side of a point that far from its nearest foot always does
// (cell corners included: 0.707 dx along the diagonal to the next row's foot). Where two faces
// meet (a tank's floor and side), particleizeMold fills the corner behind the junction with
// particles whose feet lie on the edge (normals between the faces'): a particle pressed into it
// is within dx/2 of their feet, and their planes keep it.
bool pastAnOpenEdge(const FootPlane& plane, const Vector& normalK,
                    const std::vector<SeenFoot>& feet, Real spacing) {
  const Real half = Real(0.5) * spacing;
  if (plane.alongSquared <= half * half) return false;
  const Real along = std::sqrt(plane.alongSquared);
  const Vector direction = (plane.fromFoot - plane.distance * normalK) / along;
  const Real sameFace = Real(0.9);  // cos 25 degrees
  const Real reachSquared = Real(2.25) * spacing * spacing;
  for (const SeenFoot& seen : feet) {
    if (seen.foot.normal.dot(normalK) < sameFace) continue;
    const Vector between = plane.fromFoot - seen.plane.fromFoot;  // s_m - s_k
    if (std::abs(between.dot(normalK)) > Real(0.25) * spacing) continue;
    if (between.squaredNorm() > reachSquared) continue;
    if (between.dot(direction) >= along - Real(1e-3) * spacing) return false;
  }
  return true;
}

// The distance of a point from the wedge behind two planes that make a sharp convex edge (the
// point dK in front of plane K, dM in front of plane M; unit normals nK, nM), and the direction
// out of the wedge: inside it (behind both), the nearest face (the larger distance); outside,
// a plane it is in front of where its foot on that plane lies behind the other plane (the
// nearer, if both do), else the edge itself. The foot on the edge is x - a nK - b nM with
// a + b c = dK, a c + b = dM (c = nK . nM).
struct WedgeDistance {
  Real distance;
  Vector normal;
};

WedgeDistance distanceToWedge(Real dK, const Vector& nK, Real dM, const Vector& nM) {
  if (dK <= 0 && dM <= 0) return dK >= dM ? WedgeDistance{dK, nK} : WedgeDistance{dM, nM};
  const Real c = nK.dot(nM);
  const bool onK = dK > 0 && dM - c * dK <= 0;  // x's foot on plane K lies behind plane M
  const bool onM = dM > 0 && dK - c * dM <= 0;
  if (onK && (!onM || dK <= dM)) return {dK, nK};
  if (onM) return {dM, nM};
  const Real a = (dK - c * dM) / (1 - c * c), b = (dM - c * dK) / (1 - c * c);
  const Vector fromEdge = a * nK + b * nM;
  const Real distance = fromEdge.norm();
  return {distance, fromEdge / distance};
}

// The smallest plane distance over the wall neighbours' feet whose patch lies under x_i,
// leaving out the far face of a thin body and reading each plane nearer x_i than `near` (none
// when it is negative) with its sharp convex partner (convexPartner) as the wedge behind both.
WallSurfaceDistance nearestPlane(const Vector& x, const std::vector<SeenFoot>& feet, Real spacing,
                                 Real near) {
  WallSurfaceDistance surface;
  for (const SeenFoot& seen : feet) {
    const FootPlane& plane = seen.plane;
    const Foot& foot = seen.foot;
    if (plane.alongSquared > foot.radius * foot.radius) continue;  // off the foot's patch
    if (plane.distance < -spacing) continue;  // the far face of a thin body (see the header)
    WallSurfaceDistance reading{true, plane.distance, foot.normal, seen.wall, seen.particle};
    if (plane.distance < near) {
      const ConvexPartner partner =
          convexPartner(x, x - plane.fromFoot, foot.normal, feet, spacing);
      if (partner.found) {
        // the body there is behind both planes: i's distance to that wedge
        const auto [distance, normal] =
            distanceToWedge(plane.distance, foot.normal, partner.distance, partner.normal);
        const bool throughM = distance == partner.distance && normal == partner.normal;
        reading = {true, distance, normal, throughM ? partner.wall : seen.wall,
                   throughM ? partner.particle : seen.particle};
      } else if (plane.distance < 0 && foot.nearARim &&
                 pastAnOpenEdge(plane, foot.normal, feet, spacing)) {
        continue;  // over a rim, not in the body
      }
    }
    if (!surface.found || reading.distance < surface.distance) surface = reading;
  }
  return surface;
}

}  // namespace

WallSurfaceDistance wallSurfaceDistance(const Vector& x, std::size_t i,
                                        const std::vector<WallSurfaceView>& walls,
                                        const PeriodicBox& periodic, Real spacing, Real near) {
  const Real within = std::max(near, Real(0)) * spacing;
  constexpr Real nowhere = -std::numeric_limits<Real>::infinity();
  thread_local std::vector<SeenFoot> feet;  // the clearance pass asks for every particle
  gatherFeet(x, i, walls, periodic, spacing, feet);
  const WallSurfaceDistance surface = nearestPlane(x, feet, spacing, nowhere);
  if (!surface.found || surface.distance >= within) return surface;
  // i is read behind a plane or near it: either that plane is the other face's at a sharp convex
  // edge whose patch reaches past the edge, or i is inside the body there, or beside the edge
  // in front of both faces, nearer the edge than either plane says. Each such plane is read
  // with its partner as the distance to the wedge behind both (distanceToWedge); checked only
  // where the nearest plane reads i nearer than `near` (the clearance pass's clearance), so it
  // costs nothing elsewhere. Measured on a
  // cross-shaped ditch (tutorials/crossDitchPress): without the first, metal beside the crossing's
  // vertical convex edges was put 0.8 dx "behind" the other arm's wall and the run stopped; without
  // the second, metal 0.0001 dx past the side of a ditch's arm, at the corner where it meets the
  // pocket floor, was read 0.6 dx behind the floor's plane and the run stopped (dx = 3 mm).
  // A plane read at `within` or more is left as it is: the wedge never lowers a reading, so the
  // result is below `within` exactly when the refined one is.
  return nearestPlane(x, feet, spacing, within);
}

WallGap wallGapAcross(const Vector& x, std::size_t i, const std::vector<WallSurfaceView>& walls,
                      const PeriodicBox& periodic, Real spacing, Real reach) {
  WallGap gap;
  const WallSurfaceDistance nearest = wallSurfaceDistance(x, i, walls, periodic, spacing);
  if (!nearest.found || !(nearest.distance < reach)) return gap;
  constexpr Real facing = Real(-0.7071);  // cos 135 degrees
  Real across = std::numeric_limits<Real>::infinity();
  for (const WallSurfaceView& wall : walls) {
    for (const std::uint32_t k : wall.neighboursOfFluid->of(i)) {
      forEachFoot(wall, k, spacing, [&](const Foot& foot) {
        if (!(foot.normal.dot(nearest.normal) < facing)) return;
        const FootPlane plane = footPlane(x, wall, k, foot, periodic);
        if (!(plane.distance > 0)) return;
        // 1 within the patch's radius along the plane, a smoothstep down to 0 at 1.5 radii
        const Real along = std::sqrt(std::max(plane.alongSquared, Real(0)));
        const Real cover = Real(1) - smoothstep(Real(2) * (along / foot.radius - Real(1)));
        if (!(cover > 0)) return;
        gap.cover = std::max(gap.cover, cover);
        across = std::min(across, plane.distance);
      });
    }
  }
  gap.width = std::max(nearest.distance, Real(0)) + across;
  return gap;
}

}  // namespace sphcast
