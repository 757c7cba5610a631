// Shepard interpolation, surface heights and the fluid front (post/FluidSampling.h) on lattices
// where the exact answer is known.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/FieldNames.h"
#include "post/FluidSampling.h"
#include "sph/FlowTestCases.h"

namespace sphcast {
namespace {

constexpr Real dx = 0.01;
constexpr Real h = 3 * dx;

// 30 x 30 particles on [0, 0.3]^2 with the linear field f = a + b.x.
ParticleCloud linearBlock() {
  auto fluid = testing::fluidBlock2D(30, 30, dx, Vector::Zero(), 1000, 1e-3);
  auto& f = fluid.addScalarField("f");
  auto& velocity = fluid.vectorField(field::U);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Vector& x = fluid.positions()[i];
    f[i] = 2 + 3 * x.x() - 5 * x.y();
    velocity[i] = Vector(x.y(), -x.x(), 1);
  }
  return fluid;
}

double linear(const Vector& x) { return 2 + 3 * x.x() - 5 * x.y(); }

TEST(ShepardInterpolation, ReproducesAConstantFieldEverywhereTheFluidReaches) {
  auto fluid = linearBlock();
  std::vector<Real> constant(fluid.size(), 7.25);
  const ShepardInterpolation interpolation(fluid, h);
  // Inside, off the lattice, and near the free surface and the corner where the support is cut.
  for (const Vector& point : {Vector(0.1234, 0.0871, 0), Vector(0.2999, 0.15, 0),
                              Vector(0.31, 0.31, 0), Vector(-0.02, 0.01, 0)}) {
    EXPECT_NEAR(interpolation.scalar(constant, point), 7.25, 1e-12) << point.transpose();
  }
}

TEST(ShepardInterpolation, IsExactForALinearFieldWhereTheNeighbourhoodIsSymmetric) {
  auto fluid = linearBlock();
  const ShepardInterpolation interpolation(fluid, h);
  const auto& f = fluid.scalarField("f");
  // A particle, the middle of a cell of four particles, the middle between two: the first
  // moment sum_j V_j W (x_j - x) vanishes by symmetry, so the linear part is reproduced.
  for (const Vector& point :
       {Vector(0.155, 0.145, 0), Vector(0.15, 0.15, 0), Vector(0.15, 0.105, 0)}) {
    EXPECT_NEAR(interpolation.scalar(f, point), linear(point), 1e-12) << point.transpose();
  }
  const Vector point(0.15, 0.15, 0);
  const Vector velocity = interpolation.vector(fluid.vectorField(field::U), point);
  EXPECT_NEAR((velocity - Vector(0.15, -0.15, 1)).norm(), 0, 1e-12);
}

TEST(ShepardInterpolation, LinearFieldErrorIsSmallInsideAndFirstOrderAtTheSurface) {
  auto fluid = linearBlock();
  const ShepardInterpolation interpolation(fluid, h);
  const auto& f = fluid.scalarField("f");
  const double gradient = std::hypot(3.0, 5.0);
  // Inside, at a point of no symmetry, the first moment is a quadrature error of a vanishing
  // integral: measured 1.2e-3 |grad f| dx with h = 3 dx.
  const Vector inside(0.1234, 0.0871, 0);
  EXPECT_LT(std::abs(interpolation.scalar(f, inside) - linear(inside)), 2e-3 * gradient * dx);
  // At the free surface (x = 0.3) half the support is empty: the value is pulled inwards by a
  // fraction of h (measured 0.23 h), the known first-order error of Shepard's sum there.
  const Vector surface(0.3, 0.155, 0);
  const double error = std::abs(interpolation.scalar(f, surface) - linear(surface));
  EXPECT_GT(error, 0.15 * 3 * h);
  EXPECT_LT(error, 0.3 * 3 * h);
}

TEST(ShepardInterpolation, GivesNanWhereNoFluidIsWithinTheSupport) {
  auto fluid = linearBlock();
  const ShepardInterpolation interpolation(fluid, h);
  // The nearest particle is at (0.295, 0.295): 0.0354 m from (0.32, 0.32) > h.
  EXPECT_TRUE(std::isnan(interpolation.scalar(fluid.scalarField("f"), Vector(0.32, 0.32, 0))));
  EXPECT_FALSE(std::isnan(interpolation.scalar(fluid.scalarField("f"), Vector(0.31, 0.31, 0))));
}

TEST(FluidSampling, SurfaceHeightAndFrontOfABlockAreItsFaces) {
  // 12 columns x 7 rows from (0.1, 0): surface at y = 0.07, front at x = 0.22.
  auto fluid = testing::fluidBlock2D(12, 7, dx, Vector(0.1, 0, 0), 1000, 1e-3);
  const Vector up(0, 1, 0);
  EXPECT_NEAR(surfaceHeight(fluid, up, Vector(0.15, 0.5, 0), h), 0.07, 1e-12);
  // The column reaches particles within the radius of the vertical line only: the first
  // particles are at x = 0.105.
  EXPECT_NEAR(surfaceHeight(fluid, up, Vector(0.101, 0, 0), 0.5 * dx), 0.07, 1e-12);
  EXPECT_TRUE(std::isnan(surfaceHeight(fluid, up, Vector(0.099, 0, 0), 0.5 * dx)));
  EXPECT_TRUE(std::isnan(surfaceHeight(fluid, up, Vector(0.05, 0, 0), h)));
  EXPECT_NEAR(fluidFront(fluid, Vector(1, 0, 0)), 0.22, 1e-12);
  EXPECT_NEAR(fluidFront(fluid, Vector(-1, 0, 0)), -0.1, 1e-12);
}

}  // namespace
}  // namespace sphcast
