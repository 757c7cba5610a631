#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "geometry/GmshModel.h"
#include "geometry/TriangleMesh.h"

namespace sphcast {

// Meshes the surfaces of gmsh's current model for particle generation: triangles no larger
// than maxTriangleSize on curved surfaces and on the curves and points that bound them; planes
// and straight edges between planes, exact with triangles of any size, as coarse as gmsh likes
// (the model's size). A .msh written after this call meshes as particleizeMold meshes a .geo.
void meshSurfacesForParticles(double maxTriangleSize);

// One gmsh file opened for particle generation: a .geo is meshed on the fly
// (meshSurfacesForParticles; not at all when maxTriangleSize is 0, for a look at the physical
// groups alone); a .msh (2.2 or 4.1) is used as it is.
// gmsh keeps a single global model, so only one GmshGeometry may exist at a time; it
// finalises gmsh when destroyed. gmsh's errors become an Error naming the file.
class GmshGeometry {
 public:
  GmshGeometry(const std::filesystem::path& file, double maxTriangleSize);
  ~GmshGeometry();
  GmshGeometry(const GmshGeometry&) = delete;
  GmshGeometry& operator=(const GmshGeometry&) = delete;

  const std::filesystem::path& file() const { return file_; }
  const std::vector<PhysicalGroup>& groups() const { return groups_; }
  // nullptr when the model has no group of that name.
  const PhysicalGroup* findGroup(const std::string& name) const;

  // The triangles of surface groups in one mesh (vertices shared where groups meet, so that
  // their common edges are inner edges); each triangle's owner is its group's.
  struct OwnedGroup {
    const PhysicalGroup* group;
    int owner;
  };
  TriangleMesh surfacesOf(const std::vector<OwnedGroup>& surfaceGroups) const;
  // The volume entities a surface group's surfaces bound: the cavity its walls enclose. Throws
  // an Error when one of its surfaces bounds no volume, or two (then the side is ambiguous).
  std::vector<int> volumesBoundedBy(const PhysicalGroup& surfaceGroup) const;
  // Length of a curve group (from the curves' parametrisation), area of a surface group or
  // volume of a volume group: exact from the CAD for OpenCASCADE entities, from the mesh when
  // there is one, from the boundary curves for a surface in the plane z = 0, else from the
  // entities' bounding boxes (an overestimate). For refusing too fine a spacing before meshing.
  double groupMeasure(const PhysicalGroup& group) const;
  // The volume entities of a volume group.
  std::vector<int> volumesOf(const PhysicalGroup& volumeGroup) const;
  // The combined boundary of volume entities (faces shared between two of them drop out).
  TriangleMesh boundaryOfVolumes(const std::vector<int>& volumeTags) const;

  // 2D geometry, in the plane z = 0 (read from the CAD entities; no mesh needed).
  // The entities of a group (curves of a curve group, surfaces of a surface group).
  std::vector<int> entitiesOf(const PhysicalGroup& group) const;
  // A curve entity as a polyline in the plane: its two ends for a straight line, points of its
  // parametrisation at most maxSegment apart for another curve of a .geo, its mesh nodes for a
  // discrete curve of a .msh (there a curved wall is followed as finely as it was meshed).
  // Throws an Error for a curve off z = 0.
  std::vector<Eigen::Vector2d> planarCurve(int curve, double maxSegment) const;
  // The surface entities a curve group's curves bound: the cavity its walls enclose. Throws an
  // Error when one of its curves bounds no surface, or two (then the side is ambiguous).
  std::vector<int> surfacesBoundedBy(const PhysicalGroup& curveGroup) const;
  // The combined boundary curves of surface entities (curves shared by two of them drop out).
  std::vector<int> boundaryCurvesOf(const std::vector<int>& surfaceTags) const;

 private:
  // Triangles of the surfaces (tag, owner).
  TriangleMesh surfaceTriangles(const std::vector<std::pair<int, int>>& surfaces) const;
  // Fallback for meshes without surface elements: the faces of the tetrahedra used once.
  TriangleMesh tetrahedraBoundary(const std::vector<int>& volumeTags) const;
  int vertexIndex(std::size_t nodeTag) const;
  // For a mesh without topology (MSH 2.2): the volumes with a tetrahedron on the surface.
  std::vector<int> volumesMeshedAgainst(int surface) const;
  // Points of a curve entity at most maxSegment apart (its ends for a straight line).
  std::vector<Eigen::Vector3d> sampledCurve(int curve, double maxSegment) const;
  // x, y, z of the nodes of a meshed (discrete) curve in their order along it.
  std::vector<double> meshedCurve(int curve) const;

  std::filesystem::path file_;
  std::vector<PhysicalGroup> groups_;
  std::vector<Eigen::Vector3d> nodes_;  // all mesh nodes
  std::vector<int> nodeIndex_;          // node tag -> index in nodes_, -1 for unused tags
};

}  // namespace sphcast
