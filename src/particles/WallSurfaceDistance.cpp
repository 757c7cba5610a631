#include "particles/WallSurfaceDistance.h"

#include <limits>

namespace sphcast {

WallSurfaceDistance wallSurfaceDistance(const Vector& x, std::size_t i,
                                        const std::vector<WallSurfaceView>& walls,
                                        const PeriodicBox& periodic, Real spacing) {
  const Real lateralLimitSquared = spacing * spacing;
  WallSurfaceDistance nearPlane;   // smallest d_ik of the laterally close wall particles
  WallSurfaceDistance nearest;     // d_ik of the nearest wall particle
  Real nearestSquared = std::numeric_limits<Real>::max();
  for (const WallSurfaceView& wall : walls) {
    for (const std::uint32_t k : wall.neighboursOfFluid->of(i)) {
      const Vector xik = periodic.separation(x, wall.position[k]);
      const Vector& n = wall.normal[k];
      const Real alongNormal = xik.dot(n);
      const Real distance = alongNormal - wall.depth[k];
      const Real squared = xik.squaredNorm();
      const Real lateralSquared = squared - alongNormal * alongNormal;
      if (lateralSquared <= lateralLimitSquared &&
          (!nearPlane.found || distance < nearPlane.distance)) {
        nearPlane = {true, distance, n};
      }
      if (squared < nearestSquared) {
        nearestSquared = squared;
        nearest = {true, distance, n};
      }
    }
  }
  return nearPlane.found ? nearPlane : nearest;
}

}  // namespace sphcast
