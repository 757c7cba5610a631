#pragma once

#include <cmath>
#include <numbers>

#include "core/HostDevice.h"
#include "core/Real.h"

namespace sphcast {

// The Wendland C2 kernel (Wendland 1995, Adv. Comput. Math. 4:389; eq. (5) of the paper) with
// support radius h, i.e. W = 0 for r >= h, and q = r / h:
//   W(r, h) = alpha_d (1 - q)^4 (4 q + 1),   alpha_2D = 7 / (pi h^2),  alpha_3D = 21 / (2 pi h^3)
//   dW/dr   = -20 alpha_d q (1 - q)^3 / h
// The gradient with respect to x_i of W(|x_i - x_j|) is dW/dr x_ij / r; since dW/dr / r =
// -20 alpha_d (1 - q)^3 / h^2 is finite at r = 0, it is computed without dividing by r and is
// exactly zero for coincident particles.
//
// Dim is the space dimension (2 or 3); 2D cases keep z = 0 in their vectors. The kernel stores
// h, 1/h and alpha_d so that a pair costs no division: build it once per pass, e.g.
//   const WendlandC2Kernel<3> kernel(h);  ...  kernel.value(r), kernel.gradient(xij, r)
template <int Dim>
class WendlandC2Kernel {
  static_assert(Dim == 2 || Dim == 3, "the Wendland C2 kernel is defined here for 2D and 3D");

 public:
  static constexpr int dimension = Dim;

  // alpha_d of eq. (5) for support radius h.
  SPHCAST_HOST_DEVICE static constexpr Real normalisationFor(Real h) {
    constexpr Real pi = std::numbers::pi_v<Real>;
    if constexpr (Dim == 2) {
      return Real(7) / (pi * h * h);
    } else {
      return Real(21) / (Real(2) * pi * h * h * h);
    }
  }

  SPHCAST_HOST_DEVICE constexpr explicit WendlandC2Kernel(Real supportRadius)
      : h_(supportRadius),
        inverseH_(Real(1) / supportRadius),
        alpha_(normalisationFor(supportRadius)) {}

  SPHCAST_HOST_DEVICE constexpr Real supportRadius() const { return h_; }
  SPHCAST_HOST_DEVICE constexpr Real normalisation() const { return alpha_; }

  // W(r, h); zero for r >= h.
  SPHCAST_HOST_DEVICE constexpr Real value(Real r) const {
    const Real q = r * inverseH_;
    if (q >= Real(1)) return Real(0);
    const Real oneMinusQ = Real(1) - q;
    const Real square = oneMinusQ * oneMinusQ;
    return alpha_ * square * square * (Real(4) * q + Real(1));
  }

  // dW/dr; zero for r >= h and at r = 0.
  SPHCAST_HOST_DEVICE constexpr Real derivative(Real r) const {
    const Real q = r * inverseH_;
    if (q >= Real(1)) return Real(0);
    const Real oneMinusQ = Real(1) - q;
    return Real(-20) * alpha_ * q * oneMinusQ * oneMinusQ * oneMinusQ * inverseH_;
  }

  // (dW/dr) / r, finite everywhere (-20 alpha_d / h^2 at r = 0); the gradient is this times x_ij.
  SPHCAST_HOST_DEVICE constexpr Real derivativeOverDistance(Real r) const {
    const Real q = r * inverseH_;
    if (q >= Real(1)) return Real(0);
    const Real oneMinusQ = Real(1) - q;
    return Real(-20) * alpha_ * oneMinusQ * oneMinusQ * oneMinusQ * inverseH_ * inverseH_;
  }

  // grad_i W(x_i - x_j) for xij = x_i - x_j with r = |xij| already known (the pair loop has it);
  // zero at r = 0 and for r >= h.
  SPHCAST_HOST_DEVICE Vector gradient(const Vector& xij, Real r) const {
    return derivativeOverDistance(r) * xij;
  }

  // The same, computing r = |xij| itself.
  SPHCAST_HOST_DEVICE Vector gradient(const Vector& xij) const { return gradient(xij, xij.norm()); }

 private:
  Real h_;
  Real inverseH_;
  Real alpha_;
};

using WendlandC2Kernel2D = WendlandC2Kernel<2>;
using WendlandC2Kernel3D = WendlandC2Kernel<3>;

// sum_j dx^d W(|x_j|) over the cubic lattice of spacing dx with a particle at the origin: a full
// support's kernel sum (about 1), the norm of a kernel sum (a colour, a summed density).
template <int Dim>
Real latticeKernelSum(Real supportRadius, Real spacing) {
  const WendlandC2Kernel<Dim> kernel(supportRadius);
  const int reach = static_cast<int>(std::ceil(supportRadius / spacing));
  const int zReach = Dim == 3 ? reach : 0;
  const Real cell = std::pow(spacing, Dim);
  Real sum = 0;
  for (int k = -zReach; k <= zReach; ++k) {
    for (int j = -reach; j <= reach; ++j) {
      for (int i = -reach; i <= reach; ++i) {
        sum += cell * kernel.value(spacing * std::sqrt(Real(i * i + j * j + k * k)));
      }
    }
  }
  return sum;
}

inline Real latticeKernelSum(int dimension, Real supportRadius, Real spacing) {
  return dimension == 2 ? latticeKernelSum<2>(supportRadius, spacing)
                        : latticeKernelSum<3>(supportRadius, spacing);
}

}  // namespace sphcast
