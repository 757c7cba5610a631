#include "sph/WallClearance.h"

#include <algorithm>

namespace sphcast {

WallClearanceReport enforceWallClearance(std::span<Vector> positions, std::span<Vector> velocities,
                                         const std::vector<WallSurfaceView>& walls,
                                         const PeriodicBox& periodic, Real spacing,
                                         Real clearance, std::span<const Real> held,
                                         std::span<Vector> velocityChange,
                                         std::span<int> changeAtWall) {
  WallClearanceReport report;
  const bool recording = !velocityChange.empty();
  if (recording) {
    std::fill(velocityChange.begin(), velocityChange.end(), Vector::Zero());
    std::fill(changeAtWall.begin(), changeAtWall.end(), -1);
  }
  if (walls.empty()) return report;
  const std::size_t count = positions.size();
  std::size_t corrected = 0;
  std::size_t beyondSurface = 0;
#pragma omp parallel for schedule(static) reduction(+ : corrected, beyondSurface)
  for (std::size_t i = 0; i < count; ++i) {
    if (!held.empty() && held[i] != 0) continue;
    const WallSurfaceDistance surface =
        wallSurfaceDistance(positions[i], i, walls, periodic, spacing, clearance / spacing);
    if (!surface.found || surface.distance >= clearance) continue;
    ++corrected;
    if (surface.distance < 0) {
      ++beyondSurface;
      // rare (a particle behind the surface): the deepest, ties to the lowest index, so the
      // report is the same on any number of threads
#pragma omp critical(deepestBehindWall)
      if (-surface.distance > report.deepest ||
          (-surface.distance == report.deepest && i < report.deepestParticle)) {
        report.deepest = -surface.distance;
        report.deepestParticle = i;
        report.deepestPosition = positions[i];
      }
    }
    positions[i] = periodic.wrap(positions[i] + (clearance - surface.distance) * surface.normal);
    const WallSurfaceView& wall = walls[surface.wall];
    const Vector wallVelocity =
        wall.velocity.empty() ? Vector::Zero() : Vector(wall.velocity[surface.particle]);
    const Real towardsWall = (velocities[i] - wallVelocity).dot(surface.normal);
    if (towardsWall < 0) {
      velocities[i] -= towardsWall * surface.normal;
      if (recording) {
        velocityChange[i] = -towardsWall * surface.normal;
        changeAtWall[i] = static_cast<int>(surface.wall);
      }
    }
  }
  report.corrected = corrected;
  report.beyondSurface = beyondSurface;
  return report;
}

}  // namespace sphcast
