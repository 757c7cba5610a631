#include "castAnalysis/VoxelOccupancy.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "particles/WendlandKernel.h"
#include "sph/ParticleVolumes.h"

namespace sphcast {

VoxelOccupancy::VoxelOccupancy(const Vector& lower, const Vector& upper, Real voxel,
                               Real supportRadius, int dimension)
    : voxel_(voxel), h_(supportRadius), dimension_(dimension) {
  const int axes = dimension == 2 ? 2 : 3;
  origin_ = Vector::Zero();
  double total = 1;
  for (int a = 0; a < axes; ++a) {
    const Real from = lower[a] - h_, to = upper[a] + h_;
    counts_[a] = static_cast<int>(std::ceil((to - from) / voxel_)) + 1;
    origin_[a] = from;
    total *= counts_[a];
  }
  if (total > 4e8) {
    throw Error("the voxel grid of the casting would have " + std::to_string(long(total)) +
                " voxels (more than 4e8): give a larger voxelSize");
  }
  for (auto& c : channel_) c.assign(static_cast<std::size_t>(total), 0.0f);
}

Vector VoxelOccupancy::centre(std::size_t index) const {
  const auto nx = std::size_t(counts_[0]), ny = std::size_t(counts_[1]);
  const auto i = index % nx, j = (index / nx) % ny, k = index / (nx * ny);
  Vector x = origin_ + voxel_ * Vector(Real(i), Real(j), Real(k));
  if (dimension_ == 2) x.z() = 0;
  return x;
}

double VoxelOccupancy::voxelVolume() const {
  return dimension_ == 2 ? double(voxel_) * voxel_ : double(voxel_) * voxel_ * voxel_;
}

template <class Accumulate>
void VoxelOccupancy::forEachVoxelNear(const ParticleCloud& cloud, Accumulate&& accumulate) const {
  const std::vector<Real> volume = particleVolumes(cloud, dimension_);
  const WendlandC2Kernel<3> kernel3(h_);
  const WendlandC2Kernel<2> kernel2(h_);
  const int reach = static_cast<int>(std::ceil(h_ / voxel_));
  for (std::size_t j = 0; j < cloud.size(); ++j) {
    const Vector& x = cloud.positions()[j];
    std::array<int, 3> from{0, 0, 0}, to{0, 0, 0};
    for (int a = 0; a < (dimension_ == 2 ? 2 : 3); ++a) {
      const int centre = static_cast<int>(std::lround((x[a] - origin_[a]) / voxel_));
      from[a] = std::max(0, centre - reach);
      to[a] = std::min(counts_[a] - 1, centre + reach);
    }
    for (int k = from[2]; k <= to[2]; ++k) {
      for (int jj = from[1]; jj <= to[1]; ++jj) {
        for (int i = from[0]; i <= to[0]; ++i) {
          const Vector at = origin_ + voxel_ * Vector(Real(i), Real(jj), Real(k));
          const Real r = dimension_ == 2 ? (at - x).head<2>().norm() : (at - x).norm();
          if (r >= h_) continue;
          const Real w = dimension_ == 2 ? kernel2.value(r) : kernel3.value(r);
          accumulate(j, index(i, jj, k), volume[j] * w);
        }
      }
    }
  }
}

void VoxelOccupancy::add(const ParticleCloud& cloud, int channel) {
  auto& c = channel_[channel];
  forEachVoxelNear(cloud, [&](std::size_t, std::size_t n, Real vw) { c[n] += float(vw); });
}

void VoxelOccupancy::addField(const ParticleCloud& cloud, const std::string& field) {
  const auto& f = cloud.scalarField(field);
  fieldSum_.resize(size(), 0.0f);
  forEachVoxelNear(
      cloud, [&](std::size_t j, std::size_t n, Real vw) { fieldSum_[n] += float(vw * f[j]); });
}

std::vector<EnclosedVoid> enclosedVoids(const VoxelOccupancy& occupancy, double threshold) {
  const auto [nx, ny, nz] = occupancy.counts();
  const std::size_t n = occupancy.size();
  const auto& a = occupancy.channel(0);
  const auto& b = occupancy.channel(1);
  // 0: filled; 1: void, not yet reached; 2: void joined to the outside; >= 3: enclosed group
  std::vector<std::uint32_t> state(n);
  for (std::size_t v = 0; v < n; ++v) state[v] = double(a[v] + b[v]) < threshold ? 1 : 0;
  std::vector<std::size_t> stack;
  const auto visitNeighbours = [&](std::size_t v, auto&& visit) {
    const int i = int(v % std::size_t(nx)), j = int((v / std::size_t(nx)) % std::size_t(ny)),
              k = int(v / (std::size_t(nx) * std::size_t(ny)));
    if (i > 0) visit(occupancy.index(i - 1, j, k));
    if (i + 1 < nx) visit(occupancy.index(i + 1, j, k));
    if (j > 0) visit(occupancy.index(i, j - 1, k));
    if (j + 1 < ny) visit(occupancy.index(i, j + 1, k));
    if (k > 0) visit(occupancy.index(i, j, k - 1));
    if (k + 1 < nz) visit(occupancy.index(i, j, k + 1));
  };
  const auto fill = [&](std::size_t seed, std::uint32_t mark) {
    state[seed] = mark;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::size_t v = stack.back();
      stack.pop_back();
      visitNeighbours(v, [&](std::size_t w) {
        if (state[w] == 1) {
          state[w] = mark;
          stack.push_back(w);
        }
      });
    }
  };
  // the outside: every void voxel on the box's faces, and all it reaches
  for (std::size_t v = 0; v < n; ++v) {
    const int i = int(v % std::size_t(nx)), j = int((v / std::size_t(nx)) % std::size_t(ny)),
              k = int(v / (std::size_t(nx) * std::size_t(ny)));
    const bool face =
        i == 0 || i == nx - 1 || j == 0 || j == ny - 1 || (nz > 1 && (k == 0 || k == nz - 1));
    if (face && state[v] == 1) fill(v, 2);
  }
  std::vector<EnclosedVoid> voids;
  for (std::size_t v = 0; v < n; ++v) {
    if (state[v] != 1) continue;
    const auto mark = static_cast<std::uint32_t>(3 + voids.size());
    fill(v, mark);
    voids.emplace_back();
  }
  std::vector<Eigen::Vector3d> sums(voids.size(), Eigen::Vector3d::Zero());
  std::vector<double> deficit(voids.size(), 0.0);
  // the filled voxels within h of each void (face steps: sqrt(3) h / voxel of them reach h in
  // every direction), each given to the void it was reached from first
  const int reach = static_cast<int>(
      std::ceil(std::sqrt(3.0) * double(occupancy.supportRadius()) / double(occupancy.voxel())));
  std::vector<std::uint32_t> owner(n, 0);
  std::vector<std::size_t> front, next;
  for (std::size_t v = 0; v < n; ++v) {
    if (state[v] < 3) continue;
    EnclosedVoid& group = voids[state[v] - 3];
    const Vector x = occupancy.centre(v);
    if (group.voxels == 0) group.lower = group.upper = x;
    group.lower = group.lower.cwiseMin(x);
    group.upper = group.upper.cwiseMax(x);
    ++group.voxels;
    sums[state[v] - 3] += x.cast<double>();
    owner[v] = state[v];
    front.push_back(v);
  }
  for (int step = 1; step <= reach && !front.empty(); ++step) {
    next.clear();
    for (const std::size_t v : front) {
      visitNeighbours(v, [&](std::size_t w) {
        if (state[w] == 0 && owner[w] == 0) {
          owner[w] = owner[v];
          next.push_back(w);
        }
      });
    }
    front.swap(next);
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (owner[v] >= 3) deficit[owner[v] - 3] += 1.0 - double(a[v] + b[v]);
  }
  for (std::size_t g = 0; g < voids.size(); ++g) {
    voids[g].volume = deficit[g] * occupancy.voxelVolume();
    voids[g].centroid = (sums[g] / double(voids[g].voxels)).cast<Real>();
  }
  std::sort(voids.begin(), voids.end(),
            [](const EnclosedVoid& x, const EnclosedVoid& y) { return x.voxels > y.voxels; });
  return voids;
}

}  // namespace sphcast
