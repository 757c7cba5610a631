#include "bodies/BodyWallContact.h"
#include "particles/FieldNames.h"

namespace sphcast {

BodyContact deepestBodyContact(const RigidBody& body, const std::vector<WallSurfaceView>& molds,
                               const PeriodicBox& periodic, Real spacing) {
  BodyContact contact;
  if (molds.empty()) return contact;
  const ParticleCloud& cloud = body.cloud();
  const auto& x = cloud.positions();
  const auto& depth = cloud.scalarField(field::wallDistance);
  const Real touching = Real(0.5) * spacing;
  const Real surfaceLayer = Real(0.75) * spacing;
  // a serial scan of the owned particles: the deepest, lowest index
  for (std::size_t k = 0; k < cloud.ownedSize(); ++k) {
    if (depth[k] > surfaceLayer) continue;
    const WallSurfaceDistance surface = wallSurfaceDistance(x[k], k, molds, periodic, spacing);
    if (!surface.found) continue;
    const Real shortfall = touching - surface.distance;
    if (shortfall > contact.depth) contact = {shortfall, k, surface.normal};
  }
  return contact;
}

BodyContact keepBodyOutOfMolds(RigidBody& body, const std::vector<WallSurfaceView>& molds,
                               const PeriodicBox& periodic, Real spacing) {
  const BodyContact contact = deepestBodyContact(body, molds, periodic, spacing);
  if (contact.depth > 0) body.pushBack(contact.depth * contact.normal, contact.normal);
  return contact;
}

}  // namespace sphcast
