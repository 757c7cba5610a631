#include "rheology/ShearRate.h"

#include <cmath>

#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"
#include "sph/KernelCorrection.h"

namespace sphcast {
namespace {

// Full normalisation down to a half-empty support (a flat wall or free surface leaves the
// moment's smallest eigenvalue near 1/2); blended out towards an isolated particle.
constexpr CorrectionFallback truncatedSupport{Real(0.1), Real(0.3)};

template <int Dim>
void shearRates(const ParticleCloud& fluid, const Neighbourhood& neighbourhood, Real supportRadius,
                std::vector<Real>& shearRate) {
  const WendlandC2Kernel<Dim> kernel(supportRadius);
  const PeriodicBox periodic = neighbourhood.periodicBox();
  const NeighbourList& pairs = neighbourhood.pairs(fluid, fluid);
  const auto& x = fluid.positions();
  const auto& v = fluid.vectorField(field::U);
  const auto& rho = fluid.scalarField(field::rho);
  const auto& mass = fluid.scalarField(field::mass);
  const std::size_t owned = fluid.ownedSize();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < owned; ++i) {
    Matrix gradient = Matrix::Zero();  // sum_j V_j (v_j - v_i) (x) grad_i W_ij
    CorrectionMoment moment;
    for (const std::uint32_t j : pairs.of(i)) {
      const Vector xij = periodic.separation(x[i], x[j]);
      const Real r = xij.norm();
      const Real volume = mass[j] / rho[j];
      gradient.noalias() += volume * (v[j] - v[i]) * kernel.gradient(xij, r).transpose();
      moment.add(volume, kernel.derivativeOverDistance(r), xij);
    }
    gradient = gradient * correctionMatrix(moment.sum, Dim, truncatedSupport);
    const Matrix strain = Real(0.5) * (gradient + gradient.transpose());
    shearRate[i] = std::sqrt(Real(2) * strain.cwiseAbs2().sum());
  }
}

}  // namespace

void computeShearRates(const ParticleCloud& fluid, const Neighbourhood& neighbourhood,
                       int dimension, Real supportRadius, std::vector<Real>& shearRate) {
  if (dimension == 2) {
    shearRates<2>(fluid, neighbourhood, supportRadius, shearRate);
  } else {
    shearRates<3>(fluid, neighbourhood, supportRadius, shearRate);
  }
}

}  // namespace sphcast
