// The Wendland C2 kernel of eq. (5): normalisation, zero mean gradient, hand values, and the
// partition of unity on a lattice.
#include "particles/WendlandKernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace sphcast {
namespace {

constexpr double pi = std::numbers::pi;

// Gauss-Legendre nodes and weights on [-1, 1], 8 points (Abramowitz & Stegun, Table 25.4).
constexpr double gaussNodes[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                  0.9602898564975363};
constexpr double gaussWeights[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                    0.1012285362903763};

// Composite 8-point Gauss-Legendre over [0, h] in `panels` panels; the kernel is a polynomial
// in r on [0, h], so this is exact up to round-off.
template <class F>
double integrateRadius(F f, double h, int panels = 4) {
  double sum = 0;
  const double width = h / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = (p + 0.5) * width;
    for (int k = 0; k < 4; ++k) {
      const double offset = 0.5 * width * gaussNodes[k];
      sum += 0.5 * width * gaussWeights[k] * (f(mid - offset) + f(mid + offset));
    }
  }
  return sum;
}

TEST(WendlandKernel, IntegratesToOneIn2D) {
  for (const double h : {0.01, 1.0, 3.7}) {
    const WendlandC2Kernel<2> kernel(h);
    const double integral =
        integrateRadius([&](double r) { return 2 * pi * r * kernel.value(r); }, h);
    EXPECT_NEAR(integral, 1.0, 1e-6) << "h = " << h;
  }
}

TEST(WendlandKernel, IntegratesToOneIn3D) {
  for (const double h : {0.01, 1.0, 3.7}) {
    const WendlandC2Kernel<3> kernel(h);
    const double integral =
        integrateRadius([&](double r) { return 4 * pi * r * r * kernel.value(r); }, h);
    EXPECT_NEAR(integral, 1.0, 1e-6) << "h = " << h;
  }
}

// Cartesian midpoint quadrature of the gradient over the support square/cube: every component
// of the integral vanishes (antisymmetry), and its first moment int x_a dW/dx_a dV = -1 (by
// parts, since W integrates to 1) checks the gradient's size, not only its symmetry.
TEST(WendlandKernel, GradientIntegratesToZeroAndItsMomentToMinusOne) {
  const double h = 1.3;
  const int cells = 200;
  const double step = 2 * h / cells;
  const WendlandC2Kernel<2> kernel2(h);
  Vector sum2 = Vector::Zero();
  double moment2 = 0;
  for (int a = 0; a < cells; ++a) {
    for (int b = 0; b < cells; ++b) {
      const Vector x(-h + (a + 0.5) * step, -h + (b + 0.5) * step, 0);
      const Vector grad = kernel2.gradient(x);
      sum2 += grad * step * step;
      moment2 += x[0] * grad[0] * step * step;
    }
  }
  EXPECT_LT(sum2.norm(), 1e-12);
  EXPECT_NEAR(moment2, -1.0, 1e-4);

  const WendlandC2Kernel<3> kernel3(h);
  const int cells3 = 80;
  const double step3 = 2 * h / cells3;
  Vector sum3 = Vector::Zero();
  double moment3 = 0;
  for (int a = 0; a < cells3; ++a) {
    for (int b = 0; b < cells3; ++b) {
      for (int c = 0; c < cells3; ++c) {
        const Vector x(-h + (a + 0.5) * step3, -h + (b + 0.5) * step3, -h + (c + 0.5) * step3);
        const Vector grad = kernel3.gradient(x);
        sum3 += grad * step3 * step3 * step3;
        moment3 += x[2] * grad[2] * step3 * step3 * step3;
      }
    }
  }
  EXPECT_LT(sum3.norm(), 1e-12);
  EXPECT_NEAR(moment3, -1.0, 1e-3);
}

TEST(WendlandKernel, MatchesHandValues) {
  // h = 2, r = 1: q = 1/2, (1 - q)^4 (4 q + 1) = 3/16, dW/dq = -20 q (1 - q)^3 alpha = -5/4 alpha
  const WendlandC2Kernel<2> kernel2(2.0);
  const double alpha2 = 7 / (pi * 4);
  EXPECT_DOUBLE_EQ(kernel2.normalisation(), alpha2);
  EXPECT_DOUBLE_EQ(kernel2.value(0), alpha2);
  EXPECT_DOUBLE_EQ(kernel2.value(1), alpha2 * 3 / 16);
  EXPECT_DOUBLE_EQ(kernel2.derivative(1), -alpha2 * 5.0 / 4.0 / 2.0);

  const WendlandC2Kernel<3> kernel3(2.0);
  const double alpha3 = 21 / (2 * pi * 8);
  EXPECT_DOUBLE_EQ(kernel3.normalisation(), alpha3);
  EXPECT_DOUBLE_EQ(kernel3.value(0), alpha3);
  EXPECT_DOUBLE_EQ(kernel3.value(1), alpha3 * 3 / 16);
  EXPECT_DOUBLE_EQ(kernel3.derivative(1), -alpha3 * 5.0 / 8.0);
  // h = 1, r = 0.25: (0.75)^4 * 2 = 0.6328125; dW/dr = -20 * 0.25 * 0.421875 = -2.109375
  const WendlandC2Kernel<3> unit(1.0);
  EXPECT_DOUBLE_EQ(unit.value(0.25), 21 / (2 * pi) * 0.6328125);
  EXPECT_DOUBLE_EQ(unit.derivative(0.25), 21 / (2 * pi) * -2.109375);
}

TEST(WendlandKernel, VanishesAtAndBeyondTheSupportRadius) {
  const WendlandC2Kernel<3> kernel(0.5);
  for (const double r : {0.5, 0.50001, 1.0, 100.0}) {
    EXPECT_EQ(kernel.value(r), 0.0);
    EXPECT_EQ(kernel.derivative(r), 0.0);
    EXPECT_EQ(kernel.gradient(Vector(r, 0, 0)), Vector::Zero());
  }
  EXPECT_EQ(kernel.derivative(0), 0.0);
}

TEST(WendlandKernel, GradientIsDerivativeAlongSeparationAndZeroAtOrigin) {
  const WendlandC2Kernel<3> kernel(1.5);
  EXPECT_EQ(kernel.gradient(Vector::Zero()), Vector::Zero());
  const Vector xij(0.3, -0.4, 0.5);
  const double r = xij.norm();
  const Vector expected = kernel.derivative(r) * xij / r;
  EXPECT_LT((kernel.gradient(xij) - expected).norm(), 1e-14 * expected.norm());
  EXPECT_LT((kernel.gradient(xij, r) - expected).norm(), 1e-14 * expected.norm());
  // and dW/dr is the derivative of W (central difference)
  const double eps = 1e-6;
  EXPECT_NEAR(kernel.derivative(r), (kernel.value(r + eps) - kernel.value(r - eps)) / (2 * eps),
              1e-7);
}

TEST(WendlandKernel, IsUsableInConstantExpressions) {
  constexpr WendlandC2Kernel<2> kernel(2.0);
  static_assert(kernel.value(2.0) == 0.0);
  static_assert(kernel.value(0.0) > kernel.value(1.0));
  static_assert(kernel.derivative(1.0) < 0.0);
  SUCCEED();
}

// Sum_j V_j W_ij over a lattice of spacing dx (V_j = dx^d) at a lattice point and at a point
// between lattice points; the partition of unity holds only approximately (zeroth-order
// consistency error of the discrete sum).
template <int Dim>
double latticeKernelSum(double hOverDx, const Vector& offset) {
  const double dx = 1.0;
  const WendlandC2Kernel<Dim> kernel(hOverDx * dx);
  const int reach = int(std::ceil(hOverDx)) + 1;
  double sum = 0;
  for (int a = -reach; a <= reach; ++a) {
    for (int b = -reach; b <= reach; ++b) {
      for (int c = (Dim == 3 ? -reach : 0); c <= (Dim == 3 ? reach : 0); ++c) {
        const Vector xj = Vector(a, b, c) * dx;
        sum += std::pow(dx, Dim) * kernel.value((offset - xj).norm());
      }
    }
  }
  return sum;
}

TEST(WendlandKernel, LatticeKernelSumIsNearOne) {
  // Measured sum - 1 (at a lattice point / at the centre of a lattice cell):
  //   h/dx = 2:  2D +3.76e-2 / -2.49e-2    3D +3.38e-2 / -1.95e-2
  //   h/dx = 3:  2D +5.14e-3 / -3.13e-3    3D +3.14e-3 / -1.42e-3
  // so the bounds below are 1.1 to 1.6 times the measured errors.
  const Vector node = Vector::Zero();
  const Vector between2(0.5, 0.5, 0);
  const Vector between3(0.5, 0.5, 0.5);
  EXPECT_NEAR(latticeKernelSum<2>(2, node), 1.0, 0.042);
  EXPECT_NEAR(latticeKernelSum<2>(2, between2), 1.0, 0.03);
  EXPECT_NEAR(latticeKernelSum<3>(2, node), 1.0, 0.04);
  EXPECT_NEAR(latticeKernelSum<3>(2, between3), 1.0, 0.025);
  EXPECT_NEAR(latticeKernelSum<2>(3, node), 1.0, 0.006);
  EXPECT_NEAR(latticeKernelSum<2>(3, between2), 1.0, 0.004);
  EXPECT_NEAR(latticeKernelSum<3>(3, node), 1.0, 0.004);
  EXPECT_NEAR(latticeKernelSum<3>(3, between3), 1.0, 0.002);
}

}  // namespace
}  // namespace sphcast
