#pragma once

#include "core/Real.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// Particles that feel gravity and nothing else: x += v dt + g dt^2/2, v += g dt, exact for a
// constant g (to rounding). It is the motion the solver runs until the SPH forces exist, and a
// checkable one: every particle follows its parabola.
class BallisticMotion {
 public:
  explicit BallisticMotion(const Vector& gravity) : gravity_(gravity) {}

  // The step that moves no particle more than maxCo of the cloud's particle spacing
  // (the cloud attribute "spacing"); infinite for a cloud at rest under no gravity.
  double stableDeltaT(const ParticleCloud& cloud, double maxCo) const;

  // Moves the cloud over deltaT; needs the vector field "U".
  void step(ParticleCloud& cloud, double deltaT) const;

 private:
  Vector gravity_;
};

}  // namespace sphcast
