// The Wendland C2 kernel of eq. (5): normalisation, zero mean gradient, hand values, and the
// partition of unity on a lattice.
#include "particles/WendlandKernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace sphcast {
namespace {

constexpr double pi = std::numbers::pi;
// Round-off of Real (double, or float in the single-precision build) for the tolerances.
constexpr double epsilon = std::numeric_limits<Real>::epsilon();

// The kernel evaluated in Real at a double argument, returned as double for the quadratures.
Real real(double value) { return static_cast<Real>(value); }

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
    const WendlandC2Kernel<2> kernel(real(h));
    const double integral =
        integrateRadius([&](double r) { return 2 * pi * r * double(kernel.value(real(r))); }, h);
    EXPECT_NEAR(integral, 1.0, 1e-6) << "h = " << h;
  }
}

TEST(WendlandKernel, IntegratesToOneIn3D) {
  for (const double h : {0.01, 1.0, 3.7}) {
    const WendlandC2Kernel<3> kernel(real(h));
    const double integral = integrateRadius(
        [&](double r) { return 4 * pi * r * r * double(kernel.value(real(r))); }, h);
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
  const WendlandC2Kernel<2> kernel2(real(h));
  Eigen::Vector3d sum2 = Eigen::Vector3d::Zero();
  double moment2 = 0;
  for (int a = 0; a < cells; ++a) {
    for (int b = 0; b < cells; ++b) {
      const Vector x(real(-h + (a + 0.5) * step), real(-h + (b + 0.5) * step), 0);
      const Eigen::Vector3d grad = kernel2.gradient(x).cast<double>();
      sum2 += grad * step * step;
      moment2 += double(x[0]) * grad[0] * step * step;
    }
  }
  EXPECT_LT(sum2.norm(), 1e4 * epsilon);
  EXPECT_NEAR(moment2, -1.0, 1e-4);

  const WendlandC2Kernel<3> kernel3(real(h));
  const int cells3 = 80;
  const double step3 = 2 * h / cells3;
  Eigen::Vector3d sum3 = Eigen::Vector3d::Zero();
  double moment3 = 0;
  for (int a = 0; a < cells3; ++a) {
    for (int b = 0; b < cells3; ++b) {
      for (int c = 0; c < cells3; ++c) {
        const Vector x(real(-h + (a + 0.5) * step3), real(-h + (b + 0.5) * step3),
                       real(-h + (c + 0.5) * step3));
        const Eigen::Vector3d grad = kernel3.gradient(x).cast<double>();
        sum3 += grad * step3 * step3 * step3;
        moment3 += double(x[2]) * grad[2] * step3 * step3 * step3;
      }
    }
  }
  EXPECT_LT(sum3.norm(), 1e4 * epsilon);
  EXPECT_NEAR(moment3, -1.0, 1e-3);
}

TEST(WendlandKernel, MatchesHandValues) {
  // h = 2, r = 1: q = 1/2, (1 - q)^4 (4 q + 1) = 3/16, dW/dq = -20 q (1 - q)^3 alpha = -5/4 alpha
  const double tolerance = 8 * epsilon;  // relative
  const WendlandC2Kernel<2> kernel2(2);
  const double alpha2 = 7 / (pi * 4);
  EXPECT_NEAR(double(kernel2.normalisation()), alpha2, tolerance * alpha2);
  EXPECT_NEAR(double(kernel2.value(0)), alpha2, tolerance * alpha2);
  EXPECT_NEAR(double(kernel2.value(1)), alpha2 * 3 / 16, tolerance * alpha2);
  EXPECT_NEAR(double(kernel2.derivative(1)), -alpha2 * 5.0 / 4.0 / 2.0, tolerance * alpha2);

  const WendlandC2Kernel<3> kernel3(2);
  const double alpha3 = 21 / (2 * pi * 8);
  EXPECT_NEAR(double(kernel3.normalisation()), alpha3, tolerance * alpha3);
  EXPECT_NEAR(double(kernel3.value(0)), alpha3, tolerance * alpha3);
  EXPECT_NEAR(double(kernel3.value(1)), alpha3 * 3 / 16, tolerance * alpha3);
  EXPECT_NEAR(double(kernel3.derivative(1)), -alpha3 * 5.0 / 8.0, tolerance * alpha3);
  // h = 1, r = 0.25: (0.75)^4 * 2 = 0.6328125; dW/dr = -20 * 0.25 * 0.421875 = -2.109375
  const WendlandC2Kernel<3> unit(1);
  const double alpha = 21 / (2 * pi);
  EXPECT_NEAR(double(unit.value(0.25)), alpha * 0.6328125, tolerance * alpha);
  EXPECT_NEAR(double(unit.derivative(0.25)), alpha * -2.109375, 3 * tolerance * alpha);
}

TEST(WendlandKernel, VanishesAtAndBeyondTheSupportRadius) {
  const WendlandC2Kernel<3> kernel(0.5);
  for (const double r : {0.5, 0.50001, 1.0, 100.0}) {
    EXPECT_EQ(kernel.value(real(r)), 0);
    EXPECT_EQ(kernel.derivative(real(r)), 0);
    EXPECT_EQ(kernel.gradient(Vector(real(r), 0, 0)), Vector::Zero());
  }
  EXPECT_EQ(kernel.derivative(0), 0);
}

TEST(WendlandKernel, GradientIsDerivativeAlongSeparationAndZeroAtOrigin) {
  const WendlandC2Kernel<3> kernel(1.5);
  EXPECT_EQ(kernel.gradient(Vector::Zero()), Vector::Zero());
  const Vector xij(real(0.3), real(-0.4), real(0.5));
  const Real r = xij.norm();
  const Vector expected = kernel.derivative(r) * xij / r;
  const double tolerance = 16 * epsilon * double(expected.norm());
  EXPECT_LT(double((kernel.gradient(xij) - expected).norm()), tolerance);
  EXPECT_LT(double((kernel.gradient(xij, r) - expected).norm()), tolerance);
  // and dW/dr is the derivative of W (central difference)
  const double eps = 1e-3;
  const double difference =
      double(kernel.value(real(double(r) + eps)) - kernel.value(real(double(r) - eps))) / (2 * eps);
  EXPECT_NEAR(double(kernel.derivative(r)), difference, 1e-5 + 1e3 * epsilon);
}

TEST(WendlandKernel, IsUsableInConstantExpressions) {
  constexpr WendlandC2Kernel<2> kernel(2);
  static_assert(kernel.value(2) == 0);
  static_assert(kernel.value(0) > kernel.value(1));
  static_assert(kernel.derivative(1) < 0);
  SUCCEED();
}

// Sum_j V_j W_ij over a lattice of spacing dx (V_j = dx^d) at a lattice point and at a point
// between lattice points; the partition of unity holds only approximately (zeroth-order
// consistency error of the discrete sum).
template <int Dim>
double latticeKernelSum(int hOverDx, const Vector& offset) {
  const WendlandC2Kernel<Dim> kernel(static_cast<Real>(hOverDx));  // dx = 1, V_j = 1
  const int reach = hOverDx + 1;
  double sum = 0;
  for (int a = -reach; a <= reach; ++a) {
    for (int b = -reach; b <= reach; ++b) {
      for (int c = (Dim == 3 ? -reach : 0); c <= (Dim == 3 ? reach : 0); ++c) {
        const Vector xj(static_cast<Real>(a), static_cast<Real>(b), static_cast<Real>(c));
        sum += double(kernel.value((offset - xj).norm()));
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
  const Vector between2(real(0.5), real(0.5), 0);
  const Vector between3(real(0.5), real(0.5), real(0.5));
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
