#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/TriangleMesh.h"

namespace sphcast {

// A flat face of a mold wall (a CAD face whose triangles all lie in one plane) and the lattice
// its wall particles sit on: layers at (k + 1/2) dx behind the plane, and in each layer the
// points origin + (i + 1/2) dx axis1 + (j + 1/2) dx axis2, a square lattice in the face's own
// frame.
//
// The frame: where the face is parallel to the global lattice's planes and its straight edges
// (if any) run along global axes, it is the global lattice itself (origin 0), so that
// axis-aligned molds keep the particles every other generator puts there. Otherwise axis1 runs
// along the face's dominant straight edge (the direction that most of its border length
// follows: a rectangle's long side), or along the projection of the global axis most
// parallel to the plane when no direction dominates (a disc), and the origin is the corner of
// the face's bounding rectangle in that frame, so that particles sit dx/2 from the straight
// edges of a face whose sides are whole multiples of dx.
struct PlanarFace {
  int face = -1;           // TriangleMesh::faces value
  Eigen::Vector3d normal;  // unit, out of the mold material (into the cavity)
  Eigen::Vector3d origin;  // on the plane
  Eigen::Vector3d axis1, axis2;
  Eigen::Vector2d lower, upper;  // the face's extent in (axis1, axis2) from origin, m
  bool globalLattice = false;
};

// The flat faces of `wall` (triangles grouped by TriangleMesh::faces; a face is flat when all
// its vertices lie within 1e-6 dx of one plane), oriented by `cavity`, the closed surface
// around the cavity the wall bounds.
std::vector<PlanarFace> findPlanarFaces(const TriangleMesh& wall, const TriangleMesh& cavity,
                                        double spacing);

}  // namespace sphcast
