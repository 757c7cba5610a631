#include "sph/WallClearance.h"

namespace sphcast {

WallClearanceReport enforceWallClearance(std::span<Vector> positions, std::span<Vector> velocities,
                                         const std::vector<WallSurfaceView>& walls,
                                         const PeriodicBox& periodic, Real spacing,
                                         Real clearance, std::span<const Real> held) {
  WallClearanceReport report;
  if (walls.empty()) return report;
  const std::size_t count = positions.size();
  std::size_t corrected = 0;
  std::size_t beyondSurface = 0;
#pragma omp parallel for schedule(static) reduction(+ : corrected, beyondSurface)
  for (std::size_t i = 0; i < count; ++i) {
    if (!held.empty() && held[i] != 0) continue;
    const WallSurfaceDistance surface =
        wallSurfaceDistance(positions[i], i, walls, periodic, spacing);
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
    const Real towardsWall = velocities[i].dot(surface.normal);
    if (towardsWall < 0) velocities[i] -= towardsWall * surface.normal;
  }
  report.corrected = corrected;
  report.beyondSurface = beyondSurface;
  return report;
}

}  // namespace sphcast
