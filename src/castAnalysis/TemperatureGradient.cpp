#include "castAnalysis/TemperatureGradient.h"

#include <Eigen/Dense>
#include <cmath>

#include "particles/CellGrid.h"
#include "particles/NeighbourList.h"
#include "particles/WendlandKernel.h"

namespace sphcast {

namespace {

template <int Dim>
std::vector<Vector> gradient(const ParticleCloud& cloud, Real h) {
  const auto& x = cloud.positions();
  const auto& T = cloud.scalarField("T");
  const std::size_t n = cloud.size();
  std::vector<Real> volume(n);
  if (cloud.hasScalarField("mass") && cloud.hasScalarField("rho")) {
    for (std::size_t i = 0; i < n; ++i) {
      volume[i] = cloud.scalarField("mass")[i] / cloud.scalarField("rho")[i];
    }
  } else {
    const auto spacing = cloud.attributes().find("spacing");
    const Real dx = spacing != cloud.attributes().end() ? Real(spacing->second) : h / 3;
    std::fill(volume.begin(), volume.end(), Dim == 3 ? dx * dx * dx : dx * dx);
  }
  CellGrid grid(h);
  grid.build(x);
  NeighbourList list;
  list.buildWithin(x, grid);
  const WendlandC2Kernel<Dim> kernel(h);
  std::vector<Vector> result(n, Vector::Zero());
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const auto i = static_cast<std::size_t>(k);
    Eigen::Matrix<double, Dim, Dim> moment = Eigen::Matrix<double, Dim, Dim>::Zero();
    Eigen::Matrix<double, Dim, 1> sum = Eigen::Matrix<double, Dim, 1>::Zero();
    for (const std::uint32_t j : list.of(i)) {
      const Vector xij = x[i] - x[j];
      const Vector grad = kernel.gradient(xij, xij.norm());
      const Eigen::Matrix<double, Dim, 1> g = grad.template head<Dim>().template cast<double>();
      const Eigen::Matrix<double, Dim, 1> xji = (-xij).template head<Dim>().template cast<double>();
      moment += double(volume[j]) * g * xji.transpose();
      sum += double(volume[j]) * double(T[j] - T[i]) * g;
    }
    Eigen::Matrix<double, Dim, 1> g = sum;
    const Eigen::FullPivLU<Eigen::Matrix<double, Dim, Dim>> lu(moment);
    if (list.of(i).size() >= Dim + 1 && lu.isInvertible()) g = lu.solve(sum);
    result[i].template head<Dim>() = g.template cast<Real>();
  }
  return result;
}

}  // namespace

std::vector<Vector> temperatureGradient(const ParticleCloud& cloud, Real supportRadius,
                                        int dimension) {
  return dimension == 2 ? gradient<2>(cloud, supportRadius) : gradient<3>(cloud, supportRadius);
}

}  // namespace sphcast
