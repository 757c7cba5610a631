#include "solver/BallisticMotion.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Error.h"
#include "particles/FieldNames.h"

namespace sphcast {

double BallisticMotion::stableDeltaT(const ParticleCloud& cloud, double maxCo) const {
  const auto spacing = cloud.attributes().find("spacing");
  if (spacing == cloud.attributes().end() || !(spacing->second > 0.0)) {
    throw Error("cloud '" + cloud.name() +
                "' has no positive 'spacing' attribute: adjustTimeStep needs the particle "
                "spacing (setCastFields writes it)");
  }
  const auto& velocity = cloud.vectorField(field::U);
  double fastest = 0.0;
#pragma omp parallel for reduction(max : fastest)
  for (std::size_t i = 0; i < velocity.size(); ++i) {
    fastest = std::max(fastest, static_cast<double>(velocity[i].norm()));
  }
  const double allowedTravel = maxCo * spacing->second;
  // Within one step the speed grows by |g| dt: solve |v| dt + |g| dt^2 / 2 = allowed travel.
  const double g = static_cast<double>(gravity_.norm());
  if (g > 0.0) {
    return (-fastest + std::sqrt(fastest * fastest + 2.0 * g * allowedTravel)) / g;
  }
  return fastest > 0.0 ? allowedTravel / fastest : std::numeric_limits<double>::max();
}

void BallisticMotion::step(ParticleCloud& cloud, double deltaT) const {
  auto& position = cloud.positions();
  auto& velocity = cloud.vectorField(field::U);
  const Real dt = static_cast<Real>(deltaT);
  const Vector halfGravityDt2 = Real(0.5) * gravity_ * dt * dt;
  const Vector gravityDt = gravity_ * dt;
#pragma omp parallel for
  for (std::size_t i = 0; i < position.size(); ++i) {
    position[i] += velocity[i] * dt + halfGravityDt2;
    velocity[i] += gravityDt;
  }
}

}  // namespace sphcast
