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

WallSurfaceDistance wallSurfaceDistance(const Vector& x, std::size_t i,
                                        const std::vector<WallSurfaceView>& walls,
                                        const PeriodicBox& periodic, Real spacing) {
  const Real patchRadius = Real(0.75) * spacing;
  const Real patchRadiusSquared = patchRadius * patchRadius;
  WallSurfaceDistance surface;
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
      if (!surface.found || distance < surface.distance) surface = {true, distance, n, w, k};
    }
  }
  return surface;
}

}  // namespace sphcast
