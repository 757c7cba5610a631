#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/Real.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The box a run's particles must stay in: a particle outside it has left the mold (through a
// wall, or splashed away), and one that is not finite has blown up. Either stops the run.
struct Domain {
  Vector lower;
  Vector upper;
};

// The bounding box of the clouds (the walls; the fluid in a run without walls) grown by half its
// size on every side: generous for splashes over an open top, and a particle through a wall is
// caught before it falls far.
Domain defaultDomain(const std::vector<const ParticleCloud*>& clouds);

struct ParticleCheck {
  std::size_t nonFinite = 0;  // position, velocity or density not finite
  std::size_t outside = 0;    // finite but outside the domain
  std::size_t first = 0;      // index of the first bad particle
  Vector firstPosition = Vector::Zero();

  bool good() const { return nonFinite == 0 && outside == 0; }
  // "3 particles of cloud 'water' left the domain (-0.05 -0.05 -0.05) (0.15 0.15 0.15), 1 went
  // non-finite; the first, particle 12 (id 345), at (0.2 0.05 0.01)"
  std::string describe(const ParticleCloud& cloud, const Domain& domain) const;
};

ParticleCheck checkParticles(const ParticleCloud& cloud, const Domain& domain);

}  // namespace sphcast
