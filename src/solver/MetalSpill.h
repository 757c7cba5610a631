#pragma once

#include <cstdint>
#include <string>

#include "parallel/Communicator.h"
#include "parallel/DomainDecomposition.h"
#include "particles/Domain.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// Metal that leaves the domain is spilled, as in a foundry: a splash over a mold's rim, a run-out,
// a fall below the floor a case names. Each flow step, after the drift, the metal's particles
// outside the domain are removed from the run, and their mass, heat and count are booked on the
// metal's cloud as the attributes spilledMass (kg, kg/m in 2D), spilledParticles and
// heatLost.spilled (J: sum m u, the heat that left with them, a loss path beside the air's and
// the radiation's). Written and restarted with the cloud, they keep the books closed
// (post/EnergyBalance.h's lost_spilled). The solver stops the run only when the spilled mass
// passes healthChecks' maxSpilledFraction of the metal's.
struct Spill {
  std::int64_t particles = 0;
  double mass = 0;
  double energy = 0;
  // sum m du/dt of the spilled particles (W): the heat rates their neighbours' next kick still
  // applies (the kick-drift-kick heat step kicks twice with one set of rates), to be booked with
  // the spill then (CastingSolver::firstHeatKick)
  double heatRate = 0;
  std::string first;  // the first spilled particle on this rank (id and place), or empty
};

// Removes `fluid`'s owned particles outside `domain` and books them; returns what spilled in
// this call on all ranks (`first` this rank's). In a decomposed run every rank calls it: one sum
// over the ranks per call, and when any rank spills every rank drops the fluid's halo (the next
// search rebuilds it).
Spill spillOutside(ParticleCloud& fluid, const Domain& domain, DomainDecomposition* decomposition,
                   const Communicator& comm);

// The metal spilled so far as a fraction of the metal's mass, spilled included (collective).
double spilledFraction(const ParticleCloud& fluid, const Communicator& comm);

}  // namespace sphcast
