#include "castAnalysis/TemperatureGradient.h"

#include "particles/CellGrid.h"
#include "particles/FieldNames.h"
#include "particles/NeighbourList.h"
#include "sph/CorrectedGradient.h"

namespace sphcast {

std::vector<Vector> temperatureGradient(const ParticleCloud& cloud, Real supportRadius,
                                        int dimension) {
  const auto& x = cloud.positions();
  const std::vector<Real> volume = particleVolumes(cloud, dimension);
  CellGrid grid(supportRadius);
  grid.build(x);
  NeighbourList pairs;
  pairs.buildWithin(x, grid);
  const auto& T = cloud.scalarField(field::T);
  std::vector<Vector> result(cloud.size(), Vector::Zero());
  const auto count = static_cast<std::ptrdiff_t>(cloud.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const auto i = static_cast<std::size_t>(k);
    result[i] =
        correctedGradient(cloud, T, volume, pairs, PeriodicBox(), supportRadius, dimension, i);
  }
  return result;
}

}  // namespace sphcast
