#include "sph/ParticleVolumes.h"

#include <algorithm>

#include "core/Error.h"
#include "particles/FieldNames.h"

namespace sphcast {

std::vector<Real> particleVolumes(const ParticleCloud& cloud, int dimension) {
  std::vector<Real> volume(cloud.size());
  if (cloud.hasScalarField(field::mass) && cloud.hasScalarField(field::rho)) {
    const auto& mass = cloud.scalarField(field::mass);
    const auto& rho = cloud.scalarField(field::rho);
    for (std::size_t j = 0; j < volume.size(); ++j) volume[j] = mass[j] / rho[j];
    return volume;
  }
  if (cloud.hasScalarField(field::volume)) return cloud.scalarField(field::volume);
  const auto spacing = cloud.attributes().find("spacing");
  if (spacing == cloud.attributes().end()) {
    throw Error("cloud '" + cloud.name() +
                "' has no volume, mass and rho, or spacing: its particles' volumes are unknown");
  }
  const Real dx = Real(spacing->second);
  std::fill(volume.begin(), volume.end(), dimension == 2 ? dx * dx : dx * dx * dx);
  return volume;
}

}  // namespace sphcast
