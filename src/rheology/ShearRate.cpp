#include "rheology/ShearRate.h"

#include <cmath>

#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"
#include "sph/KernelCorrection.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

// Full normalisation down to a half-empty support (a flat wall or free surface leaves the
// moment's smallest eigenvalue near 1/2); blended out towards an isolated particle.
constexpr CorrectionFallback truncatedSupport{Real(0.1), Real(0.3)};

template <int Dim, class PerParticle>
void velocityGradients(const ParticleCloud& fluid, const Neighbourhood& neighbourhood,
                       const std::vector<ShearWall>& walls, Real supportRadius,
                       PerParticle&& take) {
  const WendlandC2Kernel<Dim> kernel(supportRadius);
  const PeriodicBox periodic = neighbourhood.periodicBox();
  const NeighbourList& pairs = neighbourhood.pairs(fluid, fluid);
  const auto& x = fluid.positions();
  const auto& v = fluid.vectorField(field::U);
  const auto& rho = fluid.scalarField(field::rho);
  const auto& mass = fluid.scalarField(field::mass);
  const std::size_t owned = fluid.ownedSize();
  struct WallArrays {
    const std::vector<Vector>& position;
    const std::vector<Vector>* velocity;  // null: at rest
    const std::vector<Real>& volume;
    const std::vector<Vector>& normal;
    const std::vector<Real>& depth;
    const NeighbourList& pairs;
    bool slip;
  };
  std::vector<WallArrays> wallArrays;
  for (const ShearWall& wall : walls) {
    const ParticleCloud& cloud = *wall.cloud;
    wallArrays.push_back({cloud.positions(),
                          cloud.hasVectorField(field::U) ? &cloud.vectorField(field::U) : nullptr,
                          cloud.scalarField(field::volume), cloud.vectorField(field::normal),
                          cloud.scalarField(field::wallDistance), neighbourhood.pairs(fluid, cloud),
                          wall.condition.slip()});
  }
  const Real halfSpacing =
      walls.empty() ? Real(0) : Real(0.5) * static_cast<Real>(fluid.attributes().at("spacing"));
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
    for (const WallArrays& wall : wallArrays) {
      for (const std::uint32_t k : wall.pairs.of(i)) {
        const Vector xik = periodic.separation(x[i], wall.position[k]);
        const Real r = xik.norm();
        const Vector& normal = wall.normal[k];
        const Real fluidDistance = std::max(xik.dot(normal) - wall.depth[k], halfSpacing);
        const Real beta = Real(1) + wall.depth[k] / fluidDistance;
        Vector relative = v[i] - (wall.velocity ? (*wall.velocity)[k] : Vector::Zero());
        if (wall.slip) relative = relative.dot(normal) * normal;
        gradient.noalias() +=
            wall.volume[k] * (-beta * relative) * kernel.gradient(xik, r).transpose();
        moment.add(wall.volume[k], kernel.derivativeOverDistance(r), xik);
      }
    }
    take(i, Matrix(gradient * correctionMatrix(moment.sum, Dim, truncatedSupport)));
  }
}

}  // namespace

Real shearRateOf(const Matrix& gradient) {
  const Matrix strain = Real(0.5) * (gradient + gradient.transpose());
  return std::sqrt(Real(2) * strain.cwiseAbs2().sum());
}

std::vector<ShearWall> shearWalls(const WeaklyCompressibleFlow& flow) {
  std::vector<ShearWall> walls;
  for (const ParticleCloud* wall : flow.walls()) {
    walls.push_back({wall, flow.settings().walls.of(wall->name())});
  }
  return walls;
}

void computeShearRates(const ParticleCloud& fluid, const Neighbourhood& neighbourhood,
                       const std::vector<ShearWall>& walls, int dimension, Real supportRadius,
                       std::vector<Real>& shearRate) {
  auto take = [&](std::size_t i, const Matrix& gradient) { shearRate[i] = shearRateOf(gradient); };
  if (dimension == 2) {
    velocityGradients<2>(fluid, neighbourhood, walls, supportRadius, take);
  } else {
    velocityGradients<3>(fluid, neighbourhood, walls, supportRadius, take);
  }
}

void computeVelocityGradients(const ParticleCloud& fluid, const Neighbourhood& neighbourhood,
                              const std::vector<ShearWall>& walls, int dimension,
                              Real supportRadius, std::vector<Matrix>& gradient) {
  gradient.resize(fluid.size());
  auto take = [&](std::size_t i, const Matrix& value) { gradient[i] = value; };
  if (dimension == 2) {
    velocityGradients<2>(fluid, neighbourhood, walls, supportRadius, take);
  } else {
    velocityGradients<3>(fluid, neighbourhood, walls, supportRadius, take);
  }
}

}  // namespace sphcast
