#include "sph/DensityReinitialisation.h"

#include <algorithm>
#include <cmath>

#include "boundaries/PeriodicBox.h"
#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"

namespace sphcast {

DensityReinitialisation::DensityReinitialisation(int dimension, Real supportRadius, Real spacing,
                                                 Real relaxation)
    : dimension_(dimension),
      supportRadius_(supportRadius),
      relaxation_(relaxation),
      latticeSum_(latticeKernelSum(dimension, supportRadius, spacing)) {}

void DensityReinitialisation::apply(ParticleCloud& fluid,
                                    const std::vector<const ParticleCloud*>& walls,
                                    const Neighbourhood& neighbourhood) const {
  if (dimension_ == 2) {
    applyIn<2>(fluid, walls, neighbourhood);
  } else {
    applyIn<3>(fluid, walls, neighbourhood);
  }
}

template <int Dim>
void DensityReinitialisation::applyIn(ParticleCloud& fluid,
                                      const std::vector<const ParticleCloud*>& walls,
                                      const Neighbourhood& neighbourhood) const {
  const WendlandC2Kernel<Dim> kernel(supportRadius_);
  const auto& x = fluid.positions();
  const auto& mass = fluid.scalarField(field::mass);
  const auto& restDensity = fluid.scalarField(field::restDensity);
  auto& rho = fluid.scalarField(field::rho);
  const NeighbourList& fluidPairs = neighbourhood.pairs(fluid, fluid);
  std::vector<const NeighbourList*> wallPairs;
  for (const ParticleCloud* wall : walls) wallPairs.push_back(&neighbourhood.pairs(fluid, *wall));
  const Real selfKernel = kernel.value(0);
  const Real inverseLatticeSum = Real(1) / latticeSum_;
  const std::size_t owned = fluid.ownedSize();
  std::vector<Real> summed(owned);
  withSeparation(neighbourhood.periodicBox(), [&](auto separation) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < owned; ++i) {
      Real sum = mass[i] / restDensity[i] * selfKernel;
      for (const std::uint32_t j : fluidPairs.of(i)) {
        sum += mass[j] / restDensity[j] * kernel.value(separation(x[i], x[j]).norm());
      }
      for (std::size_t w = 0; w < walls.size(); ++w) {
        const Vector* wallX = walls[w]->positions().data();
        const Real* volume = walls[w]->scalarField(field::volume).data();
        for (const std::uint32_t k : wallPairs[w]->of(i)) {
          sum += volume[k] * kernel.value(separation(x[i], wallX[k]).norm());
        }
      }
      summed[i] = restDensity[i] * sum * inverseLatticeSum;
    }
  });
  // every particle's sum is taken before any density changes (the sums read only positions)
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < owned; ++i) {
    const Real target = std::max(summed[i], std::min(rho[i], restDensity[i]));
    rho[i] += relaxation_ * (target - rho[i]);
  }
  neighbourhood.syncHalo(fluid, {field::rho});
}

}  // namespace sphcast
