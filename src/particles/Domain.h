#pragma once

#include <limits>
#include <vector>

#include "core/Real.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The box a run's particles must stay in: a particle outside it has left the mold (through a
// wall, or splashed away), and one that is not finite has blown up. Either stops the run.
struct Domain {
  // everywhere, until a flow sets it (a ballistic cloud may fly anywhere)
  Vector lower = Vector::Constant(std::numeric_limits<Real>::lowest());
  Vector upper = Vector::Constant(std::numeric_limits<Real>::max());
};

// The bounding box of the clouds (the walls; the fluid in a run without walls) grown by half its
// size on every side: generous for splashes over an open top, and a particle through a wall is
// caught before it falls far.
Domain defaultDomain(const std::vector<const ParticleCloud*>& clouds);
// Its two parts: the box of the clouds' owned particles (empty: lower above upper), which a
// decomposed run reduces over its ranks, and the box grown by half its size.
Domain boundingBox(const std::vector<const ParticleCloud*>& clouds);
Domain withMargin(Domain box);

}  // namespace sphcast
