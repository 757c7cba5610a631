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

// Whether the edge where the planes of wall particles k and m meet is a sharp convex one: k's
// foot lies behind m's plane (and the planes are more than 30 degrees apart): the body is then
// behind both planes, and a point in front of m's plane is outside it, whatever k's says.
bool sharpConvexEdge(const Vector& footK, const Vector& normalK, const Vector& footM,
                     const Vector& normalM, Real spacing) {
  constexpr Real sharp = Real(0.866);  // cos 30 degrees
  const Real tolerance = Real(1e-3) * spacing;
  return normalK.dot(normalM) < sharp && (footK - footM).dot(normalM) < -tolerance;
}

}  // namespace

WallSurfaceDistance wallSurfaceDistance(const Vector& x, std::size_t i,
                                        const std::vector<WallSurfaceView>& walls,
                                        const PeriodicBox& periodic, Real spacing) {
  const Real patchRadius = Real(0.75) * spacing;
  const Real patchRadiusSquared = patchRadius * patchRadius;
  WallSurfaceDistance surface;
  bool anyBehind = false;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const WallSurfaceView& wall = walls[w];
    for (const std::uint32_t k : wall.neighboursOfFluid->of(i)) {
      const Vector& n = wall.normal[k];
      // x_i - s_k, with s_k = x_k + d_k n_k the wall particle's foot on the surface
      const Vector fromFoot = periodic.separation(x, wall.position[k]) - wall.depth[k] * n;
      const Real distance = fromFoot.dot(n);
      if (fromFoot.squaredNorm() - distance * distance > patchRadiusSquared)
        continue;                         // off k's patch
      if (distance < -spacing) continue;  // the far face of a thin body (see the header)
      anyBehind = anyBehind || distance < 0;
      if (!surface.found || distance < surface.distance) surface = {true, distance, n, w, k};
    }
  }
  if (!anyBehind) return surface;
  // i is behind a plane: unless it is inside the body, that plane is the other face's at a
  // sharp convex edge whose patch reaches past the edge (a patch is 1.5 dx across). Such a plane
  // is set aside when i lies in front of a plane it meets at that edge (found among the wall
  // neighbours whose foot lies within 2 dx of i along their plane), and the smallest of the
  // others is taken. Measured on a cross-shaped ditch (tutorials/crossDitchPress): without
  // this, metal beside the crossing's vertical convex edges was put 0.8 dx "behind" the other
  // arm's wall and the run stopped.
  const Real reachSquared = Real(4) * spacing * spacing;
  WallSurfaceDistance kept;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const WallSurfaceView& wall = walls[w];
    for (const std::uint32_t k : wall.neighboursOfFluid->of(i)) {
      const Vector& n = wall.normal[k];
      const Vector fromFoot = periodic.separation(x, wall.position[k]) - wall.depth[k] * n;
      const Real distance = fromFoot.dot(n);
      if (fromFoot.squaredNorm() - distance * distance > patchRadiusSquared) continue;
      if (distance < -spacing) continue;
      if (distance < 0) {
        const Vector footK = x - fromFoot;
        bool outsideEdge = false;
        for (std::size_t v = 0; v < walls.size() && !outsideEdge; ++v) {
          const WallSurfaceView& other = walls[v];
          for (const std::uint32_t m : other.neighboursOfFluid->of(i)) {
            const Vector& normalM = other.normal[m];
            const Vector fromFootM =
                periodic.separation(x, other.position[m]) - other.depth[m] * normalM;
            const Real distanceM = fromFootM.dot(normalM);
            if (distanceM < 0) continue;
            if (fromFootM.squaredNorm() - distanceM * distanceM > reachSquared) continue;
            if (sharpConvexEdge(footK, n, x - fromFootM, normalM, spacing)) {
              outsideEdge = true;
              break;
            }
          }
        }
        if (outsideEdge) continue;
      }
      if (!kept.found || distance < kept.distance) kept = {true, distance, n, w, k};
    }
  }
  return kept;
}

}  // namespace sphcast
