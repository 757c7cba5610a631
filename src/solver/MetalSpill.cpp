#include "solver/MetalSpill.h"

#include <vector>

#include "particles/FieldNames.h"
#include "solver/RunHealth.h"

namespace sphcast {

Spill spillOutside(ParticleCloud& fluid, const Domain& domain, DomainDecomposition* decomposition,
                   const Communicator& comm) {
  const std::vector<std::size_t> outside = particlesOutside(fluid, domain);
  const auto& mass = fluid.scalarField(field::mass);
  // the heat fields, where the metal carries heat
  const auto* u = fluid.hasScalarField(field::u) ? &fluid.scalarField(field::u) : nullptr;
  const auto* rate =
      fluid.hasScalarField(field::energyRate) ? &fluid.scalarField(field::energyRate) : nullptr;
  Spill spill;
  std::vector<double> books = {static_cast<double>(outside.size()), 0.0, 0.0, 0.0};
  for (const std::size_t i : outside) {
    const double m = static_cast<double>(mass[i]);
    books[1] += m;
    if (u) books[2] += m * static_cast<double>((*u)[i]);
    if (rate) books[3] += m * static_cast<double>((*rate)[i]);
  }
  if (!outside.empty())
    spill.first = describeParticle(fluid, outside.front(), fluid.positions()[outside.front()]);
  if (decomposition) comm.sum(books);  // every rank books the whole's, as the heat's attributes
  spill.particles = static_cast<std::int64_t>(books[0] + 0.5);
  spill.mass = books[1];
  spill.energy = books[2];
  spill.heatRate = books[3];
  if (spill.particles == 0) return spill;
  if (decomposition) decomposition->dropHalo(fluid);  // collective: every rank knows the count
  fluid.remove(outside);
  fluid.attributes()["spilledParticles"] += books[0];
  fluid.attributes()["spilledMass"] += spill.mass;
  fluid.attributes()["heatLost.spilled"] += spill.energy;
  return spill;
}

double spilledFraction(const ParticleCloud& fluid, const Communicator& comm) {
  const auto found = fluid.attributes().find("spilledMass");
  const double spilled = found == fluid.attributes().end() ? 0.0 : found->second;
  const auto& mass = fluid.scalarField(field::mass);
  double held = 0;
  for (std::size_t i = 0; i < fluid.ownedSize(); ++i) held += static_cast<double>(mass[i]);
  held = comm.sum(held);
  return spilled > 0 ? spilled / (held + spilled) : 0.0;
}

}  // namespace sphcast
