#include "bodies/BodyWallContact.h"

namespace sphcast {

BodyContact keepBodyOutOfMolds(RigidBody& body, const std::vector<WallSurfaceView>& molds,
                               const PeriodicBox& periodic, Real spacing) {
  BodyContact contact;
  if (molds.empty()) return contact;
  const ParticleCloud& cloud = body.cloud();
  const auto& x = cloud.positions();
  const auto& depth = cloud.scalarField("wallDistance");
  const Real touching = Real(0.5) * spacing;
  const Real surfaceLayer = Real(0.75) * spacing;
  Vector normal = Vector::Zero();
  for (std::size_t k = 0; k < x.size(); ++k) {  // a serial scan: the deepest, lowest index
    if (depth[k] > surfaceLayer) continue;
    const WallSurfaceDistance surface = wallSurfaceDistance(x[k], k, molds, periodic, spacing);
    if (!surface.found) continue;
    const Real shortfall = touching - surface.distance;
    if (shortfall > contact.depth) {
      contact = {shortfall, k};
      normal = surface.normal;
    }
  }
  if (contact.depth > 0) body.pushBack(contact.depth * normal, normal);
  return contact;
}

}  // namespace sphcast
