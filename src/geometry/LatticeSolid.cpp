#include "geometry/LatticeSolid.h"

#include <algorithm>
#include <cmath>

namespace sphcast {

namespace {

// Offsets of the scan lines, in units of dx: small and irrational, so no mesh vertex or edge
// placed by a human or by gmsh lies exactly on a line.
constexpr double lineOffsetY = 1.4142135623730951e-7;
constexpr double lineOffsetZ = 1.7320508075688772e-7;

}  // namespace

std::int64_t latticeIndex(double x, double spacing) {
  return static_cast<std::int64_t>(std::floor(x / spacing));
}

LatticeSolid::LatticeSolid(const TriangleMesh& closedSurface, double spacing) : spacing_(spacing) {
  if (closedSurface.size() == 0) return;
  const Eigen::Vector3d lower = closedSurface.lower(), upper = closedSurface.upper();
  jFirst_ = latticeIndex(lower.y(), spacing) - 1;
  kFirst_ = latticeIndex(lower.z(), spacing) - 1;
  jCount_ = latticeIndex(upper.y(), spacing) + 2 - jFirst_;
  kCount_ = latticeIndex(upper.z(), spacing) + 2 - kFirst_;
  crossings_.resize(static_cast<std::size_t>(jCount_ * kCount_));

  for (const auto& t : closedSurface.triangles) {
    const Eigen::Vector3d& a = closedSurface.vertices[static_cast<std::size_t>(t[0])];
    const Eigen::Vector3d& b = closedSurface.vertices[static_cast<std::size_t>(t[1])];
    const Eigen::Vector3d& c = closedSurface.vertices[static_cast<std::size_t>(t[2])];
    // Twice the signed area of the triangle projected on the (y, z) plane.
    const double area = (b.y() - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (b.z() - a.z());
    if (area == 0.0) continue;  // parallel to the lines: never crossed
    const double yMin = std::min({a.y(), b.y(), c.y()}), yMax = std::max({a.y(), b.y(), c.y()});
    const double zMin = std::min({a.z(), b.z(), c.z()}), zMax = std::max({a.z(), b.z(), c.z()});
    for (std::int64_t k = latticeIndex(zMin, spacing) - 1; k <= latticeIndex(zMax, spacing) + 1;
         ++k) {
      const double z = (static_cast<double>(k) + 0.5 + lineOffsetZ) * spacing;
      if (z < zMin || z > zMax) continue;
      for (std::int64_t j = latticeIndex(yMin, spacing) - 1;
           j <= latticeIndex(yMax, spacing) + 1; ++j) {
        const double y = (static_cast<double>(j) + 0.5 + lineOffsetY) * spacing;
        if (y < yMin || y > yMax) continue;
        // Barycentric coordinates of (y, z) in the projected triangle.
        const double wb = ((y - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (z - a.z())) / area;
        const double wc = ((b.y() - a.y()) * (z - a.z()) - (y - a.y()) * (b.z() - a.z())) / area;
        const double wa = 1.0 - wb - wc;
        if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
        crossings_[static_cast<std::size_t>((k - kFirst_) * jCount_ + (j - jFirst_))].push_back(
            wa * a.x() + wb * b.x() + wc * c.x());
      }
    }
  }
  for (auto& line : crossings_) std::sort(line.begin(), line.end());
}

const std::vector<double>* LatticeSolid::crossings(std::int64_t j, std::int64_t k) const {
  if (j < jFirst_ || k < kFirst_ || j >= jFirst_ + jCount_ || k >= kFirst_ + kCount_) {
    return nullptr;
  }
  return &crossings_[static_cast<std::size_t>((k - kFirst_) * jCount_ + (j - jFirst_))];
}

bool LatticeSolid::contains(const Eigen::Vector3d& p) const {
  const auto* line = crossings(latticeIndex(p.y(), spacing_), latticeIndex(p.z(), spacing_));
  if (line == nullptr) return false;
  const auto before = std::lower_bound(line->begin(), line->end(), p.x()) - line->begin();
  return before % 2 == 1;
}

std::vector<Eigen::Vector3d> LatticeSolid::interiorPoints() const {
  std::vector<Eigen::Vector3d> points;
  points.reserve(interiorCount());
  for (std::int64_t k = kFirst_; k < kFirst_ + kCount_; ++k) {
    for (std::int64_t j = jFirst_; j < jFirst_ + jCount_; ++j) {
      const auto& line = *crossings(j, k);
      for (std::size_t pair = 0; pair + 1 < line.size(); pair += 2) {
        // Lattice points strictly between an entry and the following exit.
        for (std::int64_t i = latticeIndex(line[pair] - 0.5 * spacing_, spacing_);
             latticeCoordinate(i, spacing_) < line[pair + 1]; ++i) {
          const double x = latticeCoordinate(i, spacing_);
          if (x > line[pair]) {
            points.emplace_back(x, latticeCoordinate(j, spacing_), latticeCoordinate(k, spacing_));
          }
        }
      }
    }
  }
  return points;
}

std::size_t LatticeSolid::interiorCount() const {
  std::size_t count = 0;
  for (const auto& line : crossings_) {
    for (std::size_t pair = 0; pair + 1 < line.size(); pair += 2) {
      // Points (i + 1/2) dx in (entry, exit).
      const double first = std::floor(line[pair] / spacing_ - 0.5) + 1.0;
      const double last = std::ceil(line[pair + 1] / spacing_ - 0.5) - 1.0;
      if (last >= first) count += static_cast<std::size_t>(last - first + 1.0);
    }
  }
  return count;
}

}  // namespace sphcast
