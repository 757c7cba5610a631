#include "geometry/GradedVolume.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

#include "geometry/LatticeSolid.h"

namespace sphcast {

int gradingLevels(const VolumeGrading& grading, double spacing) {
  // 1e-9: a maxSpacing written as 4 dx in decimals must give 2 levels, not 1.
  const double ratio = grading.maxSpacing / spacing;
  if (!(ratio >= 2.0 - 1e-9)) return 0;
  return static_cast<int>(std::floor(std::log2(ratio) + 1e-9));
}

WallParticles gradeVolumeParticles(const WallParticles& fine, const std::vector<double>& depth,
                                   const TriangleMesh& boundary, double spacing, double fineVolume,
                                   const VolumeGrading& grading) {
  const TriangleDistanceTree tree(boundary);
  return gradeLatticeParticles(
      fine, depth,
      [&tree](const Eigen::Vector3d& x) {
        const ClosestPoint hit = tree.closest(x, std::numeric_limits<double>::max());
        return std::make_pair(hit.point, hit.distance);
      },
      spacing, fineVolume, grading, 3);
}

WallParticles gradeLatticeParticles(const WallParticles& fine, const std::vector<double>& depth,
                                    const NearestBoundaryPoint& nearest, double spacing,
                                    double fineVolume, const VolumeGrading& grading,
                                    int dimension) {
  const int levels = gradingLevels(grading, spacing);
  const std::size_t count = fine.size();
  using Index = std::array<std::int64_t, 3>;
  std::vector<Index> index(count);
  for (std::size_t p = 0; p < count; ++p) {
    for (int a = 0; a < 3; ++a) index[p][a] = latticeIndex(fine.positions[p][a], spacing);
  }
  // The block of level l holding point p: its indices shifted right by l (a floor division).
  const auto blockOf = [&](std::size_t p, int l) {
    return Index{index[p][0] >> l, index[p][1] >> l, index[p][2] >> l};
  };
  std::vector<int> level(count, 0);
  std::vector<std::size_t> order(count);
  double start = grading.fineDepth;
  for (int l = 1; l <= levels; ++l) {
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return blockOf(a, l) < blockOf(b, l); });
    const std::size_t complete = std::size_t{1} << (dimension * l);
    for (std::size_t first = 0; first < count;) {
      std::size_t last = first;
      double shallowest = std::numeric_limits<double>::max();
      const Index block = blockOf(order[first], l);
      while (last < count && blockOf(order[last], l) == block) {
        shallowest = std::min(shallowest, depth[order[last]]);
        ++last;
      }
      if (2 * (last - first) >= complete && shallowest >= start) {
        for (std::size_t q = first; q < last; ++q) level[order[q]] = l;
      }
      first = last;
    }
    start += grading.layersPerLevel * std::ldexp(spacing, l);
  }

  // One particle per (level, block), at the place of the block's first point.
  std::vector<std::size_t> members(count, 0);  // per point: its particle
  std::vector<std::size_t> firstPoint;
  {
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto key = [&](std::size_t p) {
      const Index b = blockOf(p, level[p]);
      return std::array<std::int64_t, 4>{level[p], b[0], b[1], b[2]};
    };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return key(a) < key(b) || (key(a) == key(b) && a < b);
    });
    for (std::size_t first = 0; first < count;) {
      std::size_t last = first;
      while (last < count && key(order[last]) == key(order[first])) ++last;
      for (std::size_t q = first; q < last; ++q) members[order[q]] = firstPoint.size();
      firstPoint.push_back(order[first]);  // the group's smallest index
      first = last;
    }
  }
  // Particles in the order of their first points.
  std::vector<std::size_t> groups(firstPoint.size());
  std::iota(groups.begin(), groups.end(), std::size_t{0});
  std::sort(groups.begin(), groups.end(),
            [&](std::size_t a, std::size_t b) { return firstPoint[a] < firstPoint[b]; });
  std::vector<std::size_t> rank(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) rank[groups[g]] = g;

  WallParticles graded;
  const std::size_t n = groups.size();
  graded.positions.assign(n, Eigen::Vector3d::Zero());
  graded.normals.resize(n);
  graded.wallDistances.resize(n);
  graded.volumes.assign(n, 0.0);
  graded.owners.resize(n);
  graded.spacings.resize(n);
  std::vector<std::size_t> points(n, 0);
  for (std::size_t p = 0; p < count; ++p) {
    const std::size_t g = rank[members[p]];
    graded.positions[g] += fine.positions[p];
    graded.volumes[g] += fineVolume;
    ++points[g];
    graded.owners[g] = fine.owners[p];
    graded.spacings[g] = std::ldexp(spacing, level[p]);
    if (level[p] == 0) {
      graded.normals[g] = fine.normals[p];
      graded.wallDistances[g] = fine.wallDistances[p];
    }
  }
#pragma omp parallel for schedule(dynamic, 256)
  for (std::ptrdiff_t s = 0; s < static_cast<std::ptrdiff_t>(n); ++s) {
    const auto g = static_cast<std::size_t>(s);
    graded.positions[g] /= static_cast<double>(points[g]);
    if (points[g] == 1) continue;
    const auto [point, distance] = nearest(graded.positions[g]);
    graded.normals[g] = (point - graded.positions[g]).normalized();
    graded.wallDistances[g] = distance;
  }
  return graded;
}

}  // namespace sphcast
