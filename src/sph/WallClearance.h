#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/Real.h"
#include "particles/CellGrid.h"
#include "particles/WallSurfaceDistance.h"

namespace sphcast {

// What the pass found: the particles it moved back, and the deepest one behind the surface.
struct WallClearanceReport {
  std::size_t corrected = 0;      // particles closer than the clearance, moved back to it
  std::size_t beyondSurface = 0;  // of those, the ones that had passed the wall surface
  Real deepest = 0;               // largest distance behind the surface found (m), 0 if none
  std::size_t deepestParticle = 0;
  Vector deepestPosition = Vector::Zero();  // where it was, before it was moved back
};

// No fluid particle may pass a wall surface, whatever the step: the wall's pressure pushes the
// fluid back only as much as the kernel sum over the wall particles allows, and on curved walls
// (Poisson-disk layers with gaps of up to one spacing), in thin films at zero pressure, or after
// an impact too fast for the step, a particle can drift through between two wall particles.
// This pass is the geometric guarantee behind the pressure: every fluid particle closer than
// `clearance` to the surface (WallSurfaceDistance) is moved back along the wall normal to the
// clearance, and its velocity towards the wall, relative to the wall's (a moving mold's), is
// removed (a perfectly inelastic contact; the tangential velocity is kept). Gather over the
// fluid particles: each writes only its own position and velocity, the result does not depend
// on the thread count.
// Particles with held[i] != 0 (frozen metal, when `held` is not empty) are left where they are:
// their surface distance, estimated from pair lists that change from step to step, would
// otherwise nudge them by round-off-sized amounts.
// With `velocityChange` (one per particle) each particle's change of velocity is kept there,
// and the view it came from in `changeAtWall` (-1: none): the flow turns them into the
// impulse on a moving mold, so that metal and mold conserve momentum.
WallClearanceReport enforceWallClearance(std::span<Vector> positions, std::span<Vector> velocities,
                                         const std::vector<WallSurfaceView>& walls,
                                         const PeriodicBox& periodic, Real spacing, Real clearance,
                                         std::span<const Real> held = {},
                                         std::span<Vector> velocityChange = {},
                                         std::span<int> changeAtWall = {});

}  // namespace sphcast
