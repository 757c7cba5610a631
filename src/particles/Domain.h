#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "core/Real.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The box a run's particles must stay in: a particle outside it has left the mold (through a
// wall, or splashed away), and one that is not finite has blown up. Metal that leaves it is
// spilled (solver/MetalSpill.h); any other cloud leaving it, or a particle not finite, stops the
// run.
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

// Whether x lies in the box, its faces included (a position not finite does not).
bool inside(const Domain& domain, const Vector& x);
// The owned particles of `cloud` whose position is finite and outside `domain`, in index order.
std::vector<std::size_t> particlesOutside(const ParticleCloud& cloud, const Domain& domain);

// The domain kept with a cloud as its attributes domain.lower.x ... domain.upper.z (written with
// it), so that a restart keeps the domain its run started with; nothing when they are absent.
void storeDomain(ParticleCloud& cloud, const Domain& domain);
std::optional<Domain> storedDomain(const ParticleCloud& cloud);

}  // namespace sphcast
