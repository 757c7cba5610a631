#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/TriangleMesh.h"
#include "geometry/WallParticles.h"

namespace sphcast {

// How a mold volume is particleized at graded spacing (particleizeMold's `grading` of a volume
// patch): the particles within `fineDepth` of the surfaces that are kept fine stay at the
// spacing dx, and deeper in the material the spacing doubles, level by level, up to
// `maxSpacing`. Each level is `layersPerLevel` of its own spacings deep before the next begins,
// so that a particle's kernel (its support radius h l / dx, l its spacing) reaches particles of
// its own level and the two beside it only.
struct VolumeGrading {
  double maxSpacing = 0.0;  // m; the coarsest spacing (2^L dx, L levels); below 2 dx: no grading
  double fineDepth = 0.0;   // m; particles nearer a fine surface than this keep dx
  int layersPerLevel = 3;
  // The Physical Surfaces kept fine (where the metal meets the mold); empty: every surface.
  std::vector<std::string> fineSurfaces;
};

// The particles of a graded volume made from `fine`, every lattice point of the volume at dx
// (fillVolumeParticles), with `depth` each point's distance to the surfaces kept fine.
//
// Method: the lattice's blocks of 2^l x 2^l x 2^l points (2^l x 2^l in 2D) (aligned on the lattice,
// so that the blocks of one level nest in those of the next, an octree of the lattice) stand for a
// particle of spacing 2^l dx at the centre of their points when at least half of their 8^l
// points (4^l) are in the volume (a block cut by a face keeps the points inside; a complete block's centre is a
// point of the coarser lattice with the same half-cell offset, LatticeSolid.h) and every one lies
// at least start_l deep: start_1 = fineDepth, start_(l+1) = start_l + layersPerLevel 2^l dx. A
// point takes the coarsest block that qualifies. The blocks partition the fine lattice exactly:
// a particle's volume is its points' count times the fine particles' volume (the caller's share
// of the geometry's volume, `fineVolume`), so the mold's mass and heat capacity are those of the
// uniform mold to round-off. Fine points keep their place in the order of `fine`; a coarse
// particle takes the place of its block's first point. A coarse particle's normal and wall
// distance are those of its centre to `boundary`. `spacings` holds each particle's spacing.
WallParticles gradeVolumeParticles(const WallParticles& fine, const std::vector<double>& depth,
                                   const TriangleMesh& boundary, double spacing, double fineVolume,
                                   const VolumeGrading& grading);

// The same for any lattice of `dimension` 2 (the plane z = 0: blocks of 2^l x 2^l points, a
// quadtree) or 3, the boundary given by its nearest point to a place and the distance to it
// (called from several threads at once).
using NearestBoundaryPoint =
    std::function<std::pair<Eigen::Vector3d, double>(const Eigen::Vector3d&)>;
WallParticles gradeLatticeParticles(const WallParticles& fine, const std::vector<double>& depth,
                                    const NearestBoundaryPoint& nearest, double spacing,
                                    double fineVolume, const VolumeGrading& grading, int dimension);

// The number of levels above dx that `grading` asks for (0: none).
int gradingLevels(const VolumeGrading& grading, double spacing);

}  // namespace sphcast
