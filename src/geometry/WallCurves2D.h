#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "geometry/WallParticles.h"

namespace sphcast {

// Mold particles of a 2D case: walls are curves in the plane z = 0, the cavity and the solid
// molds are plane regions, and every particle lies on z = 0 (the flow solver's 2D plane).

// One wall curve (a gmsh curve entity of a shell patch) as a polyline: two points for a straight
// segment, the curve sampled finely (a small fraction of dx) for a curved one.
struct WallCurve {
  std::vector<Eigen::Vector2d> points;
  int owner = 0;  // patch index

  bool straight() const { return points.size() == 2; }
  double length() const;
};

// A plane region bounded by closed polylines (the edges of its boundary curves, any order and
// orientation): inside by the parity of crossings, as LatticeSolid does in 3D.
class PlaneRegion {
 public:
  // Adds the edges of an open or closed polyline.
  void add(const std::vector<Eigen::Vector2d>& polyline);

  bool contains(const Eigen::Vector2d& p) const;
  // The nearest point of the boundary's edges to p and its distance (max without edges).
  std::pair<Eigen::Vector2d, double> closest(const Eigen::Vector2d& p) const;
  // Area of the inside (the shoelace sum with each edge oriented inside-left); only meaningful
  // for a closed boundary.
  double area() const;
  const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& edges() const { return edges_; }

 private:
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> edges_;
};

// `layers` layers of particles behind the wall curves, on the side away from `cavity`, layer k
// at (k + 1/2) dx behind its curve; normal (unit, from the wall into the cavity), wallDistance
// (distance to the nearest point of the particle's curve) and volume (area, m^2) as the 3D
// shell's (WallParticles.h).
//
// Method: each curve's layer k is the curve offset by (k + 1/2) dx, sampled at equal arc length
// ~dx (round(length / dx) particles per layer, at the middle of equal pieces): on a straight
// segment whose length is a multiple of dx exactly dx apart, on the lattice of setCastFields
// when its ends lie on multiples of dx. Where two wall curves meet and the cavity's corner is
// convex (the inside corner of a tank), the wedge between their layers is filled: at a right
// angle with the corner square of both lattices continued, at any other angle with arcs around
// the corner point at the layers' distances. Then the candidates are thinned: one closer to
// another wall curve than to its own, or inside the cavity, is dropped (the overlap at a
// re-entrant corner), and greedily, straight walls' first, none is kept within 0.7 dx of one
// kept before (0.7: below the 0.75 dx a layer of two particles on a tiny circle can have,
// above nothing a lattice or a layer holds).
// A particle's volume is its layer band's area shared among the layer's particles: dx^2 on a
// straight wall, (length of the offset curve) dx / count on a curved one.
WallParticles generateShellParticles2D(const std::vector<WallCurve>& walls,
                                       const PlaneRegion& cavity, double spacing, int layers);

// Every lattice point ((i + 1/2) dx, (j + 1/2) dx, 0) inside `region`, with volume dx^2; normal
// (out of the solid) and wallDistance refer to the nearest point of the region's boundary.
WallParticles fillAreaParticles(const PlaneRegion& region, double spacing, int patch);

// The number of particles generateShellParticles2D makes, about: length / dx per layer.
double estimateShellParticleCount2D(const std::vector<WallCurve>& walls, double spacing,
                                    int layers);

}  // namespace sphcast
