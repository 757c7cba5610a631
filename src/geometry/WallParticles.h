#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "geometry/LatticeSolid.h"
#include "geometry/PlanarFaces.h"
#include "geometry/TriangleMesh.h"

namespace sphcast {

// Mold particles before they are split into clouds: position, unit normal of the nearest wall
// pointing out of the mold material (into the cavity), distance to that wall (positive inside
// the material), volume, and the owner (patch index) of the nearest wall triangle.
struct WallParticles {
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector3d> normals;
  std::vector<double> wallDistances;
  std::vector<double> volumes;
  std::vector<int> owners;
  // The radius of wall surface each particle's foot stands for (WallSurfacePatches.h); empty
  // where it was not worked out (the flow then takes 0.75 dx), 0 for a foot that stands for none.
  std::vector<double> patchRadii;
  // A second foot, on a face no first foot stands for near it (WallSurfacePatches.h): its unit
  // normal, depth and radius; all empty when no particle has one, radius 0 for one without.
  std::vector<Eigen::Vector3d> secondNormals;
  std::vector<double> secondWallDistances;
  std::vector<double> secondPatchRadii;
  // 1 for a particle whose foot stands for a piece of an open rim (a shell's free edge), else 0;
  // empty when there is none.
  std::vector<double> patchesAtRim;
  // Each particle's own spacing in a graded volume (GradedVolume.h), 0 for the mold's spacing dx;
  // empty when every particle has dx.
  std::vector<double> spacings;

  std::size_t size() const { return positions.size(); }
  // Adds the particles of `more` after these.
  void append(const WallParticles& more);
};

// `layers` layers of particles behind `wall` (the surfaces of the shell patches, owners = patch
// indices), on the side away from `cavity`, at distances (k + 1/2) dx, k = 0 .. layers-1.
//
// Method: every lattice point (LatticeSolid.h) outside the cavity and within (layers + 1/2) dx
// of the wall is moved along its wall normal onto the one or two nearest layer surfaces; the
// candidates are then thinned greedily, nearest-to-their-layer first, so that no two particles
// are closer than 0.75 dx (a maximal Poisson-disk sample of the layer surfaces, as in
// Dunbar & Humphreys, "A spatial data structure for fast Poisson-disk sample generation",
// SIGGRAPH 2006, with lattice points as the dart candidates). On a flat wall parallel to the
// lattice the candidates already lie on the layers and form the lattice itself; on a curved one
// they follow the wall at the exact layer distances. 0.75 dx lies between the 0.707 dx of a
// lattice point's diagonal neighbours in the plane (so that a flat wall keeps exactly the
// lattice) and dx (so that the thinning leaves no hole wider than a particle).
// Wall points whose nearest wall point is on the free border of the wall (an edge used by one
// triangle: the rim of an open mold) are left out, so the shell ends flush with the rim instead
// of curling around it; so are points on the cavity's side of the face they are nearest to
// (over the opening of an open mold, outside the closed cavity: they made a lip into the
// opening), the side being the one the cavity's own lattice points near that face lie on.
// A particle of a flat face's lattice (below) has the volume dx^3 of its lattice cell. Any
// other particle's volume is the volume of its layer band [k dx, (k+1) dx) behind the curved
// walls of its patch (counted on the lattice) shared among that layer's projected particles:
// the right total on a curved wall.
//
// Flat faces (`planarFaces`, PlanarFaces.h) come first and exactly: every point of a face's own
// lattice (its layers, and in-plane rows continued past its edges) for which that face (or its
// border) is among the nearest walls is a candidate, before any projected one; a tie between
// two faces is decided by distance, so that round-off cannot drop a point on a ridge's diagonal.
// Behind the face they are the face's square lattice at the exact layer distances, tilted or not;
// past a convex edge of the cavity they fill the corner (where two faces at a right angle meet, the
// two lattices continue into the same points, as on an axis-aligned box). The projected lattice
// points then only fill what remains: curved walls and what lies between unlike lattices.
WallParticles generateShellParticles(const TriangleMesh& wall, const LatticeSolid& cavity,
                                     double spacing, int layers, int patchCount,
                                     const std::vector<PlanarFace>& planarFaces = {});

// Every lattice point inside the closed surface `boundary`, with volume dx^3; normal and wall
// distance refer to the nearest point of `boundary`; owner is `patch`.
WallParticles fillVolumeParticles(const TriangleMesh& boundary, double spacing, int patch);

// The number of particles generateShellParticles makes, estimated from the wall area without
// generating them (to refuse a spacing that would make too many).
double estimateShellParticleCount(const TriangleMesh& wall, double spacing, int layers);

// For each point, whether one of `obstacles` is closer than `radius`.
std::vector<bool> closerThan(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<Eigen::Vector3d>& obstacles, double radius);

// Nearest-neighbour distances of the particles of each owner, to particles of any owner.
struct SpacingStatistics {
  std::size_t count = 0;
  double min = 0.0, mean = 0.0, max = 0.0;  // m
};
std::vector<SpacingStatistics> nearestNeighbourStatistics(const WallParticles& particles,
                                                          int ownerCount, double spacing);

}  // namespace sphcast
