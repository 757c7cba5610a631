#include "sph/KernelCorrection.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace sphcast {

namespace {

template <int Size>
Matrix blendedInverse(const Eigen::Matrix<Real, Size, Size>& moment,
                      const CorrectionFallback& fallback) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<Real, Size, Size>> eigen;
  eigen.computeDirect(moment, Eigen::EigenvaluesOnly);
  const Real smallest = eigen.eigenvalues()[0];  // ascending
  Matrix corrected = Matrix::Identity();
  // also catches NaN: a moment that is not finite gets the identity
  if (!(smallest > fallback.none)) return corrected;
  const Real weight =
      std::min(Real(1), (smallest - fallback.none) / (fallback.full - fallback.none));
  const Eigen::Matrix<Real, Size, Size> inverse = moment.inverse();
  corrected.template topLeftCorner<Size, Size>() =
      weight * inverse + (Real(1) - weight) * Eigen::Matrix<Real, Size, Size>::Identity();
  return corrected;
}

}  // namespace

Matrix correctionMatrix(const Matrix& moment, int dimension, const CorrectionFallback& fallback) {
  if (dimension == 2) {
    return blendedInverse<2>(moment.topLeftCorner<2, 2>(), fallback);
  }
  return blendedInverse<3>(moment, fallback);
}

}  // namespace sphcast
