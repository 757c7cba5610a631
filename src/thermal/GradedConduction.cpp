#include "thermal/GradedConduction.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"

namespace sphcast {

namespace {

// The particles of one spacing, binned in cells of their own support radius.
struct LevelGrid {
  double spacing = 0;
  double radius = 0;  // h of the level's own pairs
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells;

  static std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k) {
    constexpr std::int64_t offset = std::int64_t{1} << 20;
    return (static_cast<std::uint64_t>(i + offset) << 42) |
           (static_cast<std::uint64_t>(j + offset) << 21) | static_cast<std::uint64_t>(k + offset);
  }
  std::int64_t cellOf(double x) const { return static_cast<std::int64_t>(std::floor(x / radius)); }
};

}  // namespace

GradedConduction::GradedConduction(const ParticleCloud& cloud, int dimension, Real supportRadius,
                                   Real spacing, const PeriodicBox& periodic,
                                   bool correctFirstMoments) {
  if (dimension == 2) {
    build<2>(cloud, supportRadius, spacing, periodic, correctFirstMoments);
  } else {
    build<3>(cloud, supportRadius, spacing, periodic, correctFirstMoments);
  }
}

template <int Dim>
void GradedConduction::build(const ParticleCloud& cloud, Real supportRadius, Real spacing,
                             const PeriodicBox& periodic, bool correctFirstMoments) {
  using Vec = Eigen::Matrix<double, Dim, 1>;
  using Mat = Eigen::Matrix<double, Dim, Dim>;
  const std::size_t n = cloud.size();
  const auto& placed = cloud.hasVectorField(field::restPosition)
                           ? cloud.vectorField(field::restPosition)
                           : cloud.positions();
  std::vector<Vec> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = placed[i].template head<Dim>().template cast<double>();
  const auto& localSpacing = cloud.scalarField(field::localSpacing);
  const auto& mass = cloud.scalarField(field::mass);
  const auto& rho = cloud.scalarField(field::rho);
  const double dx = spacing;
  const double hOverDx = static_cast<double>(supportRadius) / dx;

  // The levels and their grids.
  std::vector<double> spacings;
  for (std::size_t i = 0; i < n; ++i) spacings.push_back(localSpacing[i]);
  std::sort(spacings.begin(), spacings.end());
  spacings.erase(std::unique(spacings.begin(), spacings.end()), spacings.end());
  std::vector<LevelGrid> grids(spacings.size());
  std::vector<std::uint8_t> level(n);
  for (std::size_t l = 0; l < spacings.size(); ++l) {
    grids[l].spacing = spacings[l];
    grids[l].radius = hOverDx * spacings[l];
  }
  // A particle within the widest reach of a periodic axis's ends is binned at its image too;
  // a pair's separation is the minimum image, the same bits from either end.
  const double widest = hOverDx * spacings.back();
  for (int axis = 0; axis < Dim; ++axis) {
    if (periodic.isPeriodic(axis) && !(periodic.period(axis) > 2 * widest)) {
      throw Error("graded conduction in cloud '" + cloud.name() +
                  "': a periodic axis shorter than twice the coarsest support radius (" +
                  std::to_string(2 * widest) + " m)");
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto l = static_cast<std::size_t>(
        std::lower_bound(spacings.begin(), spacings.end(), double(localSpacing[i])) -
        spacings.begin());
    level[i] = static_cast<std::uint8_t>(l);
    LevelGrid& grid = grids[l];
    std::vector<Vec> images{x[i]};
    for (int axis = 0; axis < Dim; ++axis) {
      if (!periodic.isPeriodic(axis)) continue;
      const double lower = periodic.lower(axis), period = periodic.period(axis);
      const std::size_t count = images.size();
      for (std::size_t m = 0; m < count; ++m) {
        Vec image = images[m];
        if (image[axis] < lower + widest) {
          image[axis] += period;
          images.push_back(image);
        } else if (image[axis] >= lower + period - widest) {
          image[axis] -= period;
          images.push_back(image);
        }
      }
    }
    for (const Vec& image : images) {
      const std::int64_t k = Dim == 3 ? grid.cellOf(image[Dim - 1]) : 0;
      grid.cells[LevelGrid::key(grid.cellOf(image[0]), grid.cellOf(image[1]), k)].push_back(
          static_cast<std::uint32_t>(i));
    }
  }
  const auto separation = [&](std::size_t j, std::size_t i) {  // x_j - x_i, minimum image
    Vec r;
    for (int axis = 0; axis < Dim; ++axis) {
      r[axis] = double(periodic.minimumImage(static_cast<Real>(x[j][axis] - x[i][axis]), axis));
    }
    return r;
  };
  std::vector<double> volume(n);
  for (std::size_t i = 0; i < n; ++i) volume[i] = double(mass[i]) / double(rho[i]);

  // Every neighbour j of i within h_ij, and G_ij: counted, then filled (the same walk twice).
  const auto forEachPair = [&](std::size_t i, auto&& visit) {
    const double hi = hOverDx * localSpacing[i];
    for (const LevelGrid& grid : grids) {
      const double reach = 0.5 * (hi + grid.radius);
      const auto span = static_cast<std::int64_t>(std::ceil(reach / grid.radius));
      const std::int64_t ci = grid.cellOf(x[i][0]), cj = grid.cellOf(x[i][1]);
      const std::int64_t ck = Dim == 3 ? grid.cellOf(x[i][Dim - 1]) : 0;
      const std::int64_t kSpan = Dim == 3 ? span : 0;
      for (std::int64_t a = ci - span; a <= ci + span; ++a) {
        for (std::int64_t b = cj - span; b <= cj + span; ++b) {
          for (std::int64_t c = ck - kSpan; c <= ck + kSpan; ++c) {
            const auto cell = grid.cells.find(LevelGrid::key(a, b, c));
            if (cell == grid.cells.end()) continue;
            for (const std::uint32_t j : cell->second) {
              if (j == i) continue;
              const double r = separation(j, i).norm();
              if (r < reach) visit(j, r, reach);
            }
          }
        }
      }
    }
  };
  const auto weight = [&](std::size_t i, std::size_t j, double r, double hij) {
    const WendlandC2Kernel<Dim> kernel(static_cast<Real>(hij));
    const double meanSpacing = 0.5 * (double(localSpacing[i]) + double(localSpacing[j]));
    const double etaSquared = 0.01 * meanSpacing * meanSpacing;
    const double rSquared = r * r;
    return -2.0 * volume[i] * volume[j] *
           static_cast<double>(kernel.derivativeOverDistance(static_cast<Real>(r))) * rSquared /
           (rSquared + etaSquared);
  };
  // Row i: its neighbours in index order, each once (the sums do not depend on the grids'
  // hashing, and a periodic image binned beside its particle is not counted twice).
  struct Neighbour {
    std::uint32_t j;
    double r, hij;
    bool operator<(const Neighbour& other) const { return j < other.j; }
  };
  const auto rowOf = [&](std::size_t i, std::vector<Neighbour>& row) {
    row.clear();
    forEachPair(i, [&](std::uint32_t j, double r, double hij) { row.push_back({j, r, hij}); });
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end(),
                          [](const Neighbour& a, const Neighbour& b) { return a.j == b.j; }),
              row.end());
  };
  rowStart_.assign(n + 1, 0);
#pragma omp parallel
  {
    std::vector<Neighbour> row;
#pragma omp for schedule(dynamic, 512)
    for (std::size_t i = 0; i < n; ++i) {
      rowOf(i, row);
      rowStart_[i + 1] = row.size();
    }
  }
  for (std::size_t i = 0; i < n; ++i) rowStart_[i + 1] += rowStart_[i];
  neighbours_.resize(rowStart_[n]);
  weights_.resize(rowStart_[n]);
  std::vector<double> reachOf(n, 0.0);
#pragma omp parallel
  {
    std::vector<Neighbour> row;
#pragma omp for schedule(dynamic, 512)
    for (std::size_t i = 0; i < n; ++i) {
      rowOf(i, row);
      std::size_t slot = rowStart_[i];
      for (const Neighbour& pair : row) {
        neighbours_[slot] = pair.j;
        weights_[slot] = weight(i, pair.j, pair.r, pair.hij);
        reachOf[i] = std::max(reachOf[i], pair.hij);
        ++slot;
      }
    }
  }

  // The first-moment correction, at the particles whose support lies in the material.
  std::vector<std::uint8_t> interior(n, 0);
  std::size_t interiorCount = 0;
  if (correctFirstMoments && cloud.hasScalarField(field::wallDistance)) {
    const auto& depth = cloud.scalarField(field::wallDistance);
    for (std::size_t i = 0; i < n; ++i) {
      interior[i] = depth[i] >= reachOf[i] ? 1 : 0;
      interiorCount += interior[i];
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
  const auto dot = [&](const std::vector<Vec>& a, const std::vector<Vec>& b) {
    double sum = 0;
#pragma omp parallel for schedule(static) reduction(+ : sum)
    for (std::size_t i = 0; i < n; ++i) sum += interior[i] ? a[i].dot(b[i]) : 0.0;
    return sum;
  };
  std::vector<Mat> inverse(n, Mat::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    if (interior[i]) inverse[i] = diagonal[i].inverse();
  }
  std::vector<Vec> lambda(n, Vec::Zero()), residual(n, Vec::Zero()), z(n), direction(n), product(n);
  for (std::size_t i = 0; i < n; ++i) residual[i] = interior[i] ? moment[i] : Vec::Zero();
  const double target = 1e-26 * std::max(dot(residual, residual), 1e-300);  // |r| 1e-13 of |b|
  int iterations = 0;
  double residualSquared = dot(residual, residual);
  if (interiorCount > 0 && residualSquared > 0) {
    for (std::size_t i = 0; i < n; ++i) z[i] = inverse[i] * residual[i];
    direction = z;
    double rz = dot(residual, z);
    constexpr int maxIterations = 5000;
    while (residualSquared > target && iterations < maxIterations) {
      apply(direction, product);
      const double alpha = rz / dot(direction, product);
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        lambda[i] += alpha * direction[i];
        residual[i] -= alpha * product[i];
        z[i] = inverse[i] * residual[i];
      }
      const double rzNext = dot(residual, z);
      const double beta = rzNext / rz;
      rz = rzNext;
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) direction[i] = z[i] + beta * direction[i];
      residualSquared = dot(residual, residual);
      ++iterations;
    }
  }
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
  leastWeightRatio_ = leastRatio;
  double largest = 0;
  for (std::size_t i = 0; i < n; ++i) {
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
  largestFirstMoment_ = largest;
  if (!(leastRatio > 0)) {
    throw Error("graded conduction in cloud '" + cloud.name() +
                "': the first-moment correction turned a pair's conductance negative (least "
                "ratio " +
                std::to_string(leastRatio) +
                "); particleize the mold with more fineLayers or a smaller maxSpacing");
  }
  std::ostringstream line;
  line << "graded conduction in cloud '" << cloud.name() << "': " << n << " particles at "
       << spacings.size() << " spacings (" << spacings.front() << " to " << spacings.back()
       << " m), " << pairCount() << " pairs, each with its own kernel; first moments held to zero at "
       << interiorCount << " particles inside (" << iterations
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
