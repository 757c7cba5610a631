#pragma once

#include <vector>

#include "core/Real.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// V_j of every particle of a cloud: mass / rho where it has both (the volume now: a fluid's
// `volume` field is the one setCastFields gave it), else its `volume` field (mold particles),
// else spacing^dimension from the cloud's `spacing` attribute. An error where none is there.
std::vector<Real> particleVolumes(const ParticleCloud& cloud, int dimension);

}  // namespace sphcast
