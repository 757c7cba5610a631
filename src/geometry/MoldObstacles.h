#pragma once

#include <vector>

#include "core/Real.h"
#include "geometry/PackingRelaxation.h"
#include "particles/CellGrid.h"
#include "particles/NeighbourList.h"
#include "particles/ParticleCloud.h"
#include "particles/WallSurfaceDistance.h"

namespace sphcast {

// The particles of constant/particles as the metal fill sees them: obstacles the metal keeps
// clear of, fixed neighbours of the packing relaxation, and, where particleizeMold wrote their
// `normal` (into the cavity) and `wallDistance` (behind the wall surface), the side of the wall
// they mark. A mold particle without `volume` counts as spacing^3.
class MoldObstacles {
 public:
  MoldObstacles(const std::vector<ParticleCloud>& moldClouds, double spacing, double clearance);

  bool empty() const { return particles_.positions.empty(); }
  double clearance() const { return clearance_; }
  const FixedNeighbours& particles() const { return particles_; }

  // For each point, whether no mold particle is closer than the clearance (cell-grid search).
  std::vector<bool> clear(const std::vector<Vector>& points) const;

  // For each point, whether it lies behind the wall, in the mold material: a mold particle w
  // puts the wall surface at w + d_w n_w, so the point's depth behind that surface is
  // d_w - (x - w) . n_w. Behind when that is positive for some mold particle within `radius`
  // (1.5 dx takes in the particles of both faces near a rim, where the nearest one may belong
  // to the other face). All false when some mold cloud lacks normal or wallDistance.
  std::vector<bool> behindWall(const std::vector<Vector>& points, double radius) const;

  // For each point, its distance in front of the wall surface and the wall normal there, as the
  // flow estimates them (particles/WallSurfaceDistance.h) from the mold particles within
  // `radius`; not found where none is that near, or some mold cloud lacks normal or
  // wallDistance.
  std::vector<WallSurfaceDistance> wallSurfaceDistances(const std::vector<Vector>& points,
                                                        double radius) const;

  // The mold particles inside the box [lower, upper].
  FixedNeighbours within(const Vector& lower, const Vector& upper) const;

 private:
  FixedNeighbours particles_;
  std::vector<Vector> normals_;        // empty when some cloud has none
  std::vector<Real> wallDistances_;    // likewise
  std::vector<Real> patchRadii_;       // likewise (0.75 dx where a cloud has no wallPatchRadius)
  std::vector<Vector> secondNormals_;  // likewise (radius 0 where a particle has no second foot)
  std::vector<Real> secondDepths_;
  std::vector<Real> secondPatchRadii_;
  std::vector<Real> patchesAtRim_;
  double spacing_;
  double clearance_;
  CellGrid clearanceGrid_;
};

}  // namespace sphcast
