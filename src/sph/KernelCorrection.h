#pragma once

#include <Eigen/Core>

#include "core/Real.h"

namespace sphcast {

using Matrix = Eigen::Matrix<Real, 3, 3>;

// Kernel-gradient normalisation (Randles & Libersky 1996; Bonet & Lok 1999), the "normalisation
// of the kernel gradient" the paper applies (its ref. [3]). The moment of particle i,
//   M_i = sum_j V_j (x_j - x_i) (x) grad_i W_ij = -sum_j V_j F(r_ij) x_ij x_ij^T
// (grad_i W_ij = F(r) x_ij, F = W'(r)/r < 0: M_i is symmetric and positive), is the identity
// where the kernel support is full of particles on a regular lattice. With L_i = M_i^-1 the
// corrected gradient L_i grad_i W_ij makes sum_j V_j (f_j - f_i) L_i grad_i W_ij exact for every
// linear f, on any particle arrangement.
struct CorrectionMoment {
  Matrix sum = Matrix::Zero();

  void add(Real volumeJ, Real gradientFactor, const Vector& xij) {
    sum.noalias() -= (volumeJ * gradientFactor) * (xij * xij.transpose());
  }
};

// The smallest eigenvalue of the moment below which the correction is blended out: at a free
// surface half of the support is empty and M has an eigenvalue near 1/2 along the normal; there
// M^-1 doubles the pressure gradient towards the surface, which Bonet & Lok's correction is
// known to turn unstable. Full correction from `full` up (the interior, where disorder moves the
// eigenvalues by about 10 %), none at `none` and below, linear between.
struct CorrectionFallback {
  Real none = Real(0.6);
  Real full = Real(0.9);
};

// L_i from the moment: M^-1 blended with the identity by the smallest eigenvalue of M (over the
// first `dimension` axes; in 2D the z row and column are left as the identity's).
Matrix correctionMatrix(const Matrix& moment, int dimension,
                        const CorrectionFallback& fallback = {});

}  // namespace sphcast
