#include "particles/WallSurfaceDistance.h"

namespace sphcast {

std::vector<WallSurfaceView> wallSurfaceViews(const ParticleCloud& fluid,
                                              const std::vector<const ParticleCloud*>& walls,
                                              const Neighbourhood& neighbourhood) {
  std::vector<WallSurfaceView> views;
  for (const ParticleCloud* wall : walls) {
    views.push_back({wall->positions(), wall->vectorField("normal"),
                     wall->scalarField("wallDistance"), &neighbourhood.pairs(fluid, *wall),
                     wall->hasVectorField("U") ? std::span<const Vector>(wall->vectorField("U"))
                                               : std::span<const Vector>()});
  }
  return views;
}

namespace {

// x_i seen from wall particle k's foot on the surface, s_k = x_k + d_k n_k: its distance along
// n_k, and the square of its distance along k's plane.
struct FootPlane {
  Vector fromFoot;
  Real distance;
  Real alongSquared;
};

FootPlane footPlane(const Vector& x, const WallSurfaceView& wall, std::uint32_t k,
                    const PeriodicBox& periodic) {
  const Vector& n = wall.normal[k];
  const Vector fromFoot = periodic.separation(x, wall.position[k]) - wall.depth[k] * n;
  const Real distance = fromFoot.dot(n);
  return {fromFoot, distance, fromFoot.squaredNorm() - distance * distance};
}

// Whether the edge where the planes of wall particles k and m meet is a sharp convex one: k's
// foot lies behind m's plane (and the planes are more than 30 degrees apart): the body is then
// behind both planes, and a point in front of m's plane is outside it, whatever k's says.
bool sharpConvexEdge(const Vector& footK, const Vector& normalK, const Vector& footM,
                     const Vector& normalM, Real spacing) {
  constexpr Real sharp = Real(0.866);  // cos 30 degrees
  const Real tolerance = Real(1e-3) * spacing;
  return normalK.dot(normalM) < sharp && (footK - footM).dot(normalM) < -tolerance;
}

// Whether x_i, behind the plane of foot footK, lies in front of a plane (foot within 2 dx of it
// along the plane) with which that one makes a sharp convex edge: then it is outside the body.
bool beyondConvexEdge(const Vector& x, std::size_t i, const Vector& footK, const Vector& normalK,
                      const std::vector<WallSurfaceView>& walls, const PeriodicBox& periodic,
                      Real spacing) {
  const Real reachSquared = Real(4) * spacing * spacing;
  for (const WallSurfaceView& other : walls) {
    for (const std::uint32_t m : other.neighboursOfFluid->of(i)) {
      const FootPlane plane = footPlane(x, other, m, periodic);
      if (plane.distance < 0 || plane.alongSquared > reachSquared) continue;
      if (sharpConvexEdge(footK, normalK, x - plane.fromFoot, other.normal[m], spacing)) {
        return true;
      }
    }
  }
  return false;
}

// The smallest plane distance over the wall neighbours whose patch lies under x_i, leaving out
// the far face of a thin body and, with setAsideBeyondEdges, the planes x_i is read behind at a
// sharp convex edge; anyBehind: whether a plane counted read x_i behind it.
WallSurfaceDistance nearestPlane(const Vector& x, std::size_t i,
                                 const std::vector<WallSurfaceView>& walls,
                                 const PeriodicBox& periodic, Real spacing,
                                 bool setAsideBeyondEdges, bool& anyBehind) {
  const Real patchRadius = Real(0.75) * spacing;
  const Real patchRadiusSquared = patchRadius * patchRadius;
  WallSurfaceDistance surface;
  anyBehind = false;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const WallSurfaceView& wall = walls[w];
    for (const std::uint32_t k : wall.neighboursOfFluid->of(i)) {
      const FootPlane plane = footPlane(x, wall, k, periodic);
      if (plane.alongSquared > patchRadiusSquared) continue;  // off k's patch
      if (plane.distance < -spacing) continue;  // the far face of a thin body (see the header)
      const Vector& n = wall.normal[k];
      if (setAsideBeyondEdges && plane.distance < 0 &&
          beyondConvexEdge(x, i, x - plane.fromFoot, n, walls, periodic, spacing)) {
        continue;
      }
      anyBehind = anyBehind || plane.distance < 0;
      if (!surface.found || plane.distance < surface.distance) {
        surface = {true, plane.distance, n, w, k};
      }
    }
  }
  return surface;
}

}  // namespace

WallSurfaceDistance wallSurfaceDistance(const Vector& x, std::size_t i,
                                        const std::vector<WallSurfaceView>& walls,
                                        const PeriodicBox& periodic, Real spacing) {
  bool anyBehind = false;
  const WallSurfaceDistance surface =
      nearestPlane(x, i, walls, periodic, spacing, false, anyBehind);
  if (!anyBehind) return surface;
  // i is read behind a plane: unless it is inside the body, that plane is the other face's at a
  // sharp convex edge whose patch reaches past the edge (a patch is 1.5 dx across). Such planes
  // are set aside (beyondConvexEdge) and the smallest of the others is taken: checked only here,
  // so it costs nothing elsewhere. Measured on a cross-shaped ditch (tutorials/crossDitchPress):
  // without this, metal beside the crossing's vertical convex edges was put 0.8 dx "behind" the
  // other arm's wall and the run stopped.
  return nearestPlane(x, i, walls, periodic, spacing, true, anyBehind);
}

}  // namespace sphcast
