#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/Real.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The pixels of a picture in a plane: pixel (x, y)'s centre is origin + x pixel right + y pixel up.
struct PlaneGrid {
  Vector origin, right, up, normal;  // right x up = normal; the plane through origin
  Real pixel = 0;
  int width = 0, height = 0;
  Vector centre(int x, int y) const { return origin + pixel * (Real(x) * right + Real(y) * up); }
};

// The clouds' bodies and a field on a plane, by SPH interpolation onto its pixels:
//
//   c_k(x) = sum_j V_j W(|x - x_j|, h_j)            (j in cloud k; Shepard's denominator)
//   f(x)   = sum_j V_j f_j W(|x - x_j|, h_j) / c_k(x)
//
// c_k is 1 inside a full body and falls through 1/2 about half a spacing beyond its last
// particles, where its surface is (VoxelOccupancy.h): a pixel where the clouds' sum of c_k is
// at least 1/2 shows the cloud with the largest c_k, coloured by f where the cloud carries the
// field. The sum closes the seam between two bodies in contact (a lattice's staircase against a
// sloping mold leaves each body's own c_k below 1/2 there), while a free surface, or a gap wider
// than about a spacing, stays where c falls through 1/2. V_j is
// particleVolumes' (m / rho: a shrinking melt's own volume); h_j is the support radius scaled by
// the particle's localSpacing over its cloud's spacing on a graded mold. Accumulated particle
// by particle into the pixels within h_j (no neighbour search); only particles within h_j of
// the plane reach it. In 2D the plane is the case's and every particle counts.
class PlaneInterpolation {
 public:
  PlaneInterpolation(const PlaneGrid& grid, int dimension);

  // Adds cloud `index` (the caller's numbering) with `field` (interpolated where the cloud has
  // it) and support radius h (the case's, for particles at the cloud's spacing).
  void add(const ParticleCloud& cloud, int index, const std::string& field, Real supportRadius);

  // The cloud shown at pixel (x, y): its index, or -1 where the clouds' kernel sums together
  // stay below 1/2.
  int owner(int x, int y) const { return total_[at(x, y)] >= 0.5 ? owner_[at(x, y)] : -1; }
  // The field there (NaN where the owner has no such field or there is no owner).
  double value(int x, int y) const {
    return owner(x, y) >= 0 ? value_[at(x, y)] : std::numeric_limits<double>::quiet_NaN();
  }
  const PlaneGrid& grid() const { return grid_; }

 private:
  std::size_t at(int x, int y) const { return std::size_t(y) * std::size_t(grid_.width) + x; }

  PlaneGrid grid_;
  int dimension_;
  std::vector<int> owner_;
  std::vector<double> value_, fill_, total_;  // the owner's value and c_k, the sum of the c_k
};

}  // namespace sphcast
