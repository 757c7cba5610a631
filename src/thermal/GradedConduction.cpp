#include "thermal/GradedConduction.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "particles/GradedPairs.h"
#include "particles/WendlandKernel.h"

namespace sphcast {

GradedConduction::GradedConduction(const ParticleCloud& cloud, int dimension, Real supportRadius,
                                   Real spacing, const PeriodicBox& periodic,
                                   bool correctFirstMoments, const Neighbourhood* decomposition) {
  if (dimension == 2) {
    build<2>(cloud, supportRadius, spacing, periodic, correctFirstMoments, decomposition);
  } else {
    build<3>(cloud, supportRadius, spacing, periodic, correctFirstMoments, decomposition);
  }
}

template <int Dim>
void GradedConduction::build(const ParticleCloud& cloud, Real supportRadius, Real spacing,
                             const PeriodicBox& periodic, bool correctFirstMoments,
                             const Neighbourhood* decomposition) {
  using Vec = Eigen::Matrix<double, Dim, 1>;
  using Mat = Eigen::Matrix<double, Dim, Dim>;
  const std::size_t n = cloud.size();
  // the rows: this rank's own particles (decomposed: the halo's are its owners' rows)
  const std::size_t owned = cloud.ownedSize();
  std::vector<std::uint8_t> ownRows(n, 0);
  std::fill(ownRows.begin(), ownRows.begin() + static_cast<long>(owned), 1);
  const auto sumOverRanks = [&](double value) {
    if (decomposition == nullptr) return value;
    std::vector<double> values{value};
    decomposition->sumOverRanks(values);
    return values[0];
  };
  const auto maxOverRanks = [&](double value) {
    return decomposition ? decomposition->maxOverRanks(value) : value;
  };
  const auto syncHalo = [&](std::vector<Vec>& values) {
    if (decomposition) decomposition->syncHalo(cloud, values);
  };
  const auto& placed = cloud.hasVectorField(field::restPosition)
                           ? cloud.vectorField(field::restPosition)
                           : cloud.positions();
  const auto& localSpacing = cloud.scalarField(field::localSpacing);
  const auto& mass = cloud.scalarField(field::mass);
  const auto& rho = cloud.scalarField(field::rho);
  const GradedPairs pairs = findGradedPairs(placed, localSpacing, supportRadius / spacing, periodic,
                                            owned < n ? &ownRows : nullptr);
  rowStart_ = pairs.rowStart;
  neighbours_ = pairs.neighbours;
  const auto separation = [&](std::size_t j, std::size_t i) {  // x_j - x_i, minimum image
    return Vec(
        periodic.separation(placed[j], placed[i]).template head<Dim>().template cast<double>());
  };
  std::vector<double> volume(n);
  for (std::size_t i = 0; i < n; ++i) volume[i] = double(mass[i]) / double(rho[i]);
  weights_.resize(neighbours_.size());
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t s = rowStart_[i]; s < rowStart_[i + 1]; ++s) {
      const std::size_t j = neighbours_[s];
      const Real hij = pairs.supportRadii[s];
      const WendlandC2Kernel<Dim> kernel(hij);
      const double meanSpacing = 0.5 * (double(localSpacing[i]) + double(localSpacing[j]));
      const double etaSquared = 0.01 * meanSpacing * meanSpacing;
      const double rSquared = separation(j, i).squaredNorm();
      weights_[s] = -2.0 * volume[i] * volume[j] *
                    double(kernel.derivativeOverDistance(static_cast<Real>(std::sqrt(rSquared)))) *
                    rSquared / (rSquared + etaSquared);
    }
  }
  std::vector<Real> spacings(localSpacing.begin(), localSpacing.begin() + static_cast<long>(owned));
  std::sort(spacings.begin(), spacings.end());
  spacings.erase(std::unique(spacings.begin(), spacings.end()), spacings.end());

  // The first-moment correction, at the particles whose own support lies in the material.
  std::vector<std::uint8_t> interior(n, 0);
  std::size_t interiorCount = 0;
  const double hOverDxForInterior = double(supportRadius) / double(spacing);
  if (correctFirstMoments && cloud.hasScalarField(field::wallDistance)) {
    const auto& depth = cloud.scalarField(field::wallDistance);
    for (std::size_t i = 0; i < n; ++i) {
      interior[i] = depth[i] >= hOverDxForInterior * localSpacing[i] ? 1 : 0;
      if (i < owned) interiorCount += interior[i];
    }
  }
  const auto pairLength = [&](std::size_t i, std::size_t j) {
    return 0.5 * (double(localSpacing[i]) + double(localSpacing[j]));
  };
  std::vector<Vec> moment(n, Vec::Zero());
  std::vector<Mat> diagonal(n, Mat::Zero());
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t s = rowStart_[i]; s < rowStart_[i + 1]; ++s) {
      const std::size_t j = neighbours_[s];
      const Vec r = separation(j, i);
      moment[i] += weights_[s] * r;
      diagonal[i] += weights_[s] / pairLength(i, j) * r * r.transpose();
    }
  }
  // (A lambda)_i = sum_j G_ij / l_ij r_ij r_ij^T (lambda_i - lambda_j), lambda = 0 off the
  // interior; A lambda = b, b_i = sum_j G_ij r_ij: symmetric positive definite.
  const auto apply = [&](const std::vector<Vec>& lambda, std::vector<Vec>& out) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      Vec sum = Vec::Zero();
      if (interior[i]) {
        for (std::size_t s = rowStart_[i]; s < rowStart_[i + 1]; ++s) {
          const std::size_t j = neighbours_[s];
          const Vec r = separation(j, i);
          const Vec difference = interior[j] ? Vec(lambda[i] - lambda[j]) : lambda[i];
          sum += weights_[s] / pairLength(i, j) * r * r.dot(difference);
        }
      }
      out[i] = sum;
    }
  };
  // in index order on one thread: the weights are then the same bits on any number of threads
  // (decomposed: each rank's own, summed over the ranks)
  const auto dot = [&](const std::vector<Vec>& a, const std::vector<Vec>& b) {
    double sum = 0;
    for (std::size_t i = 0; i < owned; ++i) sum += interior[i] ? a[i].dot(b[i]) : 0.0;
    return sumOverRanks(sum);
  };
  std::vector<Mat> inverse(n, Mat::Zero());
  for (std::size_t i = 0; i < owned; ++i) {
    if (interior[i]) inverse[i] = diagonal[i].inverse();
  }
  std::vector<Vec> lambda(n, Vec::Zero()), residual(n, Vec::Zero()), z(n, Vec::Zero()),
      direction(n, Vec::Zero()), product(n, Vec::Zero());
  for (std::size_t i = 0; i < owned; ++i) residual[i] = interior[i] ? moment[i] : Vec::Zero();
  const double target = 1e-26 * std::max(dot(residual, residual), 1e-300);  // |r| 1e-13 of |b|
  int iterations = 0;
  double residualSquared = dot(residual, residual);
  const auto interiorEverywhere = sumOverRanks(static_cast<double>(interiorCount));
  if (interiorEverywhere > 0 && residualSquared > 0) {
    for (std::size_t i = 0; i < owned; ++i) z[i] = inverse[i] * residual[i];
    direction = z;
    double rz = dot(residual, z);
    constexpr int maxIterations = 5000;
    while (residualSquared > target && iterations < maxIterations) {
      syncHalo(direction);  // the halo's lambda_j are their owners' unknowns
      apply(direction, product);
      const double alpha = rz / dot(direction, product);
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < owned; ++i) {
        lambda[i] += alpha * direction[i];
        residual[i] -= alpha * product[i];
        z[i] = inverse[i] * residual[i];
      }
      const double rzNext = dot(residual, z);
      const double beta = rzNext / rz;
      rz = rzNext;
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < owned; ++i) direction[i] = z[i] + beta * direction[i];
      residualSquared = dot(residual, residual);
      ++iterations;
    }
  }
  // both rows of a pair on two ranks scale it by the same bits: the books close across ranks
  syncHalo(lambda);
  double leastRatio = 1;
#pragma omp parallel for schedule(static) reduction(min : leastRatio)
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t s = rowStart_[i]; s < rowStart_[i + 1]; ++s) {
      const std::size_t j = neighbours_[s];
      const Vec lj = interior[j] ? lambda[j] : Vec::Zero();
      const Vec li = interior[i] ? lambda[i] : Vec::Zero();
      const double ratio = 1.0 + (lj - li).dot(separation(j, i)) / pairLength(i, j);
      weights_[s] *= ratio;
      leastRatio = std::min(leastRatio, ratio);
    }
  }
  leastRatio = -maxOverRanks(-leastRatio);
  leastWeightRatio_ = leastRatio;
  double largest = 0;
  for (std::size_t i = 0; i < owned; ++i) {
    if (!interior[i]) continue;
    Vec sum = Vec::Zero();
    double scale = 0;
    for (std::size_t s = rowStart_[i]; s < rowStart_[i + 1]; ++s) {
      const std::size_t j = neighbours_[s];
      sum += weights_[s] * separation(j, i);
      scale += std::abs(weights_[s]) * pairLength(i, j);
    }
    largest = std::max(largest, sum.norm() / scale);
  }
  largest = maxOverRanks(largest);
  largestFirstMoment_ = largest;
  if (!(leastRatio > 0)) {
    throw Error("graded conduction in cloud '" + cloud.name() +
                "': the first-moment correction turned a pair's conductance negative (least "
                "ratio " +
                std::to_string(leastRatio) +
                "); particleize the mold with more fineLayers or a smaller maxSpacing");
  }
  // the counts and spacings of every rank's particles
  const double finest =
      -maxOverRanks(spacings.empty() ? -std::numeric_limits<double>::max() : -spacings.front());
  const double coarsest =
      maxOverRanks(spacings.empty() ? -std::numeric_limits<double>::max() : spacings.back());
  std::ostringstream line;
  line << "graded conduction in cloud '" << cloud.name()
       << "': " << std::llround(sumOverRanks(static_cast<double>(owned)))
       << " particles at spacings from " << finest << " to " << coarsest << " m, "
       << std::llround(sumOverRanks(static_cast<double>(neighbours_.size()))) / 2
       << " pairs, each with its own kernel; first moments held to zero at "
       << std::llround(interiorEverywhere) << " particles inside (" << iterations
       << " conjugate-gradient iterations, largest left " << largest
       << " of the pair sum), weights scaled by " << leastRatio << " at least";
  description_ = line.str();
}

void GradedConduction::addEnergyRates(const Real* phi, const Real* mass, Real* energyRate) const {
  const std::size_t n = rowStart_.size() - 1;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0;
    const double phiI = phi[i];
    for (std::size_t s = rowStart_[i]; s < rowStart_[i + 1]; ++s) {
      sum += weights_[s] * (double(phi[neighbours_[s]]) - phiI);
    }
    energyRate[i] += static_cast<Real>(sum / double(mass[i]));
  }
}

}  // namespace sphcast
