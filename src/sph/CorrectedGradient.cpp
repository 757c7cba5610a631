#include "sph/CorrectedGradient.h"

#include <Eigen/Dense>

#include "particles/WendlandKernel.h"

namespace sphcast {

namespace {

template <int Dim>
Vector gradientAt(const ParticleCloud& cloud, const std::vector<Real>& field,
                  const std::vector<Real>& volume, const NeighbourList& pairs,
                  const PeriodicBox& periodic, Real h, std::size_t i) {
  const WendlandC2Kernel<Dim> kernel(h);
  const auto& x = cloud.positions();
  Eigen::Matrix<double, Dim, Dim> moment = Eigen::Matrix<double, Dim, Dim>::Zero();
  Eigen::Matrix<double, Dim, 1> sum = Eigen::Matrix<double, Dim, 1>::Zero();
  for (const std::uint32_t j : pairs.of(i)) {
    const Vector xij = periodic.separation(x[i], x[j]);
    const Eigen::Matrix<double, Dim, 1> g =
        kernel.gradient(xij, xij.norm()).template head<Dim>().template cast<double>();
    const Eigen::Matrix<double, Dim, 1> xji = (-xij).template head<Dim>().template cast<double>();
    moment += double(volume[j]) * g * xji.transpose();
    sum += double(volume[j]) * double(field[j] - field[i]) * g;
  }
  Eigen::Matrix<double, Dim, 1> gradient = sum;
  const Eigen::FullPivLU<Eigen::Matrix<double, Dim, Dim>> lu(moment);
  if (pairs.of(i).size() >= Dim + 1 && lu.isInvertible()) gradient = lu.solve(sum);
  Vector result = Vector::Zero();
  result.template head<Dim>() = gradient.template cast<Real>();
  return result;
}

}  // namespace

Vector correctedGradient(const ParticleCloud& cloud, const std::vector<Real>& field,
                         const std::vector<Real>& volume, const NeighbourList& pairs,
                         const PeriodicBox& periodic, Real supportRadius, int dimension,
                         std::size_t i) {
  return dimension == 2 ? gradientAt<2>(cloud, field, volume, pairs, periodic, supportRadius, i)
                        : gradientAt<3>(cloud, field, volume, pairs, periodic, supportRadius, i);
}

}  // namespace sphcast
