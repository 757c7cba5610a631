#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "geometry/TriangleMesh.h"

namespace sphcast {

// The lattice all particle generators share: points at ((i + 1/2) dx, (j + 1/2) dx,
// (k + 1/2) dx) for integers i, j, k, so that walls on multiples of dx fall half-way between
// particle planes.
inline double latticeCoordinate(std::int64_t index, double spacing) {
  return (static_cast<double>(index) + 0.5) * spacing;
}
// The index of the lattice plane nearest to x.
std::int64_t latticeIndex(double x, double spacing);

// Which lattice points lie inside a closed triangulated surface, by the parity of crossings along
// lines of the lattice in x (scan-line voxelisation, as in Nooruddin & Turk, "Simplification and
// repair of polygonal models using volumetric techniques", IEEE TVCG 2003). The lines are offset
// by a tiny irrational fraction of dx so that they never pass exactly through a mesh edge or
// vertex, where a crossing would be counted twice or not at all.
class LatticeSolid {
 public:
  LatticeSolid(const TriangleMesh& closedSurface, double spacing);

  // p is a lattice point (or near one: it is classified on its nearest lattice line).
  bool contains(const Eigen::Vector3d& p) const;
  // Every lattice point inside, ordered by k, j, i.
  std::vector<Eigen::Vector3d> interiorPoints() const;
  // Their number, without storing them.
  std::size_t interiorCount() const;

 private:
  const std::vector<double>* crossings(std::int64_t j, std::int64_t k) const;

  double spacing_;
  std::int64_t jFirst_ = 0, kFirst_ = 0, jCount_ = 0, kCount_ = 0;
  std::vector<std::vector<double>> crossings_;  // per line (j, k), sorted x of the crossings
};

}  // namespace sphcast
