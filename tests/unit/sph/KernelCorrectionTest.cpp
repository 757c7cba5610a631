// Kernel-gradient normalisation: exact gradients of linear fields on disordered particles, and
// the fallback to the plain kernel gradient where the support is not full (a free surface).
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <limits>
#include <random>

#include "particles/WendlandKernel.h"
#include "sph/KernelCorrection.h"

namespace sphcast {
namespace {

struct Particles {
  std::vector<Vector> position;
  Real volume;
};

// A lattice of spacing dx filling [-n dx, n dx]^dimension (z = 0 in 2D), each particle moved by
// up to `jitter` dx along every axis, and only those below `surface` (in y) kept.
Particles lattice(int dimension, int n, Real dx, Real jitter, Real surface) {
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> offset(-jitter * dx, jitter * dx);
  Particles particles{{}, dimension == 2 ? dx * dx : dx * dx * dx};
  const int zLayers = dimension == 2 ? 0 : n;
  for (int i = -n; i <= n; ++i) {
    for (int j = -n; j <= n; ++j) {
      for (int k = -zLayers; k <= zLayers; ++k) {
        Vector x(i * dx + offset(random), j * dx + offset(random),
                 dimension == 2 ? Real(0) : k * dx + offset(random));
        if (x.y() <= surface) particles.position.push_back(x);
      }
    }
  }
  return particles;
}

// The moment of the particle nearest the origin, and the SPH gradient sum_j V_j (f_j - f_i)
// grad_i W_ij of f(x) = a . x there, with and without the correction.
struct GradientAtOrigin {
  Matrix moment;
  Vector plain;
  Vector corrected;
};

template <int Dim>
GradientAtOrigin gradientAtOrigin(const Particles& particles, Real radius, const Vector& a) {
  const WendlandC2Kernel<Dim> kernel(radius);
  std::size_t i = 0;
  for (std::size_t k = 0; k < particles.position.size(); ++k) {
    if (particles.position[k].norm() < particles.position[i].norm()) i = k;
  }
  CorrectionMoment moment;
  Vector plain = Vector::Zero();
  for (const Vector& xj : particles.position) {
    const Vector xij = particles.position[i] - xj;
    const Real r = xij.norm();
    if (r >= radius || r == 0) continue;
    moment.add(particles.volume, kernel.derivativeOverDistance(r), xij);
    plain += particles.volume * a.dot(xj - particles.position[i]) * kernel.gradient(xij, r);
  }
  return {moment.sum, plain, correctionMatrix(moment.sum, Dim) * plain};
}

TEST(KernelCorrection, MakesTheGradientOfALinearFieldExactOnDisorderedParticles3D) {
  const Real dx = 0.01;
  const Vector a(1.5, -2.0, 0.7);
  const auto result = gradientAtOrigin<3>(lattice(3, 5, dx, Real(0.15), Real(1)), 3 * dx, a);
  // disorder of +-0.15 dx moves the plain gradient by several per cent ...
  EXPECT_GT((result.plain - a).norm() / a.norm(), 0.01);
  // ... the corrected one is exact to round-off
  EXPECT_LT((result.corrected - a).norm() / a.norm(), 1e-12);
}

TEST(KernelCorrection, MakesTheGradientOfALinearFieldExactOnDisorderedParticles2D) {
  const Real dx = 0.01;
  const Vector a(-0.3, 4.0, 0);
  const auto result = gradientAtOrigin<2>(lattice(2, 6, dx, Real(0.15), Real(1)), 3 * dx, a);
  EXPECT_GT((result.plain - a).norm() / a.norm(), 0.01);
  EXPECT_LT((result.corrected - a).norm() / a.norm(), 1e-12);
  EXPECT_EQ(result.moment(2, 2), 0);  // no z in 2D; the correction keeps z untouched
}

TEST(KernelCorrection, IsTheIdentityOnAFullRegularLattice) {
  // the moment of a full lattice at h = 3 dx is the identity to lattice-quadrature error
  const Real dx = 0.01;
  const auto result = gradientAtOrigin<3>(lattice(3, 5, dx, 0, Real(1)), 3 * dx, Vector(1, 0, 0));
  EXPECT_LT((result.moment - Matrix::Identity()).norm(), 0.01);
  EXPECT_LT((correctionMatrix(result.moment, 3) - Matrix::Identity()).norm(), 0.01);
}

TEST(KernelCorrection, FallsBackToThePlainGradientAtAFreeSurface) {
  // a particle on the surface (nothing above y = 0) has half a support: the moment's
  // eigenvalue along y is about 1/2, below the fallback's `none`, so L is the identity
  const Real dx = 0.01;
  const auto surface = gradientAtOrigin<3>(lattice(3, 5, dx, 0, Real(0)), 3 * dx, Vector(1, 0, 0));
  EXPECT_NEAR(surface.moment(1, 1), 0.5, 0.1);
  EXPECT_EQ(correctionMatrix(surface.moment, 3), Matrix::Identity());

  // one spacing below the surface it is corrected only in part
  const auto below = gradientAtOrigin<3>(lattice(3, 5, dx, 0, dx), 3 * dx, Vector(1, 0, 0));
  const Matrix partial = correctionMatrix(below.moment, 3);
  const Matrix full = below.moment.inverse();
  EXPECT_GT(partial(1, 1), 1.0);
  EXPECT_LT(partial(1, 1), full(1, 1));
}

TEST(KernelCorrection, BlendsLinearlyBetweenTheFallbackEigenvalues) {
  const CorrectionFallback fallback;
  Matrix moment = Matrix::Identity();
  const Real middle = Real(0.5) * (fallback.none + fallback.full);
  moment(1, 1) = middle;
  const Matrix corrected = correctionMatrix(moment, 3, fallback);
  EXPECT_NEAR(corrected(1, 1), 0.5 / middle + 0.5, 1e-14);
  EXPECT_NEAR(corrected(0, 0), 1.0, 1e-14);
  moment(1, 1) = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_EQ(correctionMatrix(moment, 3, fallback), Matrix::Identity());
}

}  // namespace
}  // namespace sphcast
