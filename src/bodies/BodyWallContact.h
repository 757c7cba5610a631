#pragma once

#include <cstddef>
#include <vector>

#include "bodies/RigidBody.h"
#include "particles/WallSurfaceDistance.h"

namespace sphcast {

// What the contact pass did: how deep the body had gone into another mold (m, 0 if not), at
// which of its particles, and that mold's outward normal there.
struct BodyContact {
  Real depth = 0;
  std::size_t particle = 0;
  Vector normal = Vector::Zero();
};

// A body may not pass into another mold: only the metal and the end stop push it, and a heavy
// body in a shallow pool, or a punch pressed past its stroke, would go through the floor. After
// the drift, each of the body's surface particles (wallDistance <= 0.75 dx: the first layer)
// must lie at least half a spacing in front of the other molds' surfaces (WallSurfaceDistance,
// the estimate the fluid's wall clearance uses), where the two surfaces touch. If one lies
// nearer, the body is moved back along that mold's normal by the deepest shortfall (projected on
// its translation constraint) and its velocity into the mold is removed: a perfectly inelastic
// contact without friction, as the end stop. `molds` are the other walls seen from the body's
// particles (their lists: the body's particles against each mold).
BodyContact keepBodyOutOfMolds(RigidBody& body, const std::vector<WallSurfaceView>& molds,
                               const PeriodicBox& periodic, Real spacing);
// The scan alone, over the cloud's owned particles (a decomposed run takes the deepest of the
// ranks' and moves the body back itself).
BodyContact deepestBodyContact(const RigidBody& body, const std::vector<WallSurfaceView>& molds,
                               const PeriodicBox& periodic, Real spacing);

}  // namespace sphcast
