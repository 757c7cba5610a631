#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

namespace sphcast {

// A triangulated surface in plain arrays, as gmsh meshes it: vertices shared between triangles
// (so edges can be matched), and per triangle the index of what it belongs to (a patch).
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> owners;  // one per triangle
  // The CAD face (gmsh surface entity) of each triangle, where known; empty when not.
  std::vector<int> faces;

  std::size_t size() const { return triangles.size(); }
  double area() const;
  // Enclosed volume by the divergence theorem; exact for a closed, consistently oriented mesh
  // (absolute value taken, so either orientation gives the same).
  double enclosedVolume() const;
  Eigen::Vector3d lower() const;
  Eigen::Vector3d upper() const;
  // Edges used by exactly one triangle: a closed surface has none.
  std::size_t freeEdgeCount() const;
  // Drops vertices no triangle uses (renumbering the others).
  void removeUnusedVertices();
  // Appends another mesh (vertices are not merged across meshes).
  void append(const TriangleMesh& other);
  // Whether p lies inside the closed surface, by the parity of the surface's crossings of a ray
  // from p (Moller & Trumbore, "Fast, minimum storage ray-triangle intersection", 1997); a ray
  // that grazes an edge or a vertex is cast again in another direction. O(triangles) per call.
  bool encloses(const Eigen::Vector3d& p) const;
};

// Which part of a triangle a closest point lies on: its inside, an edge (0: v0v1, 1: v1v2,
// 2: v2v0) or a vertex (0, 1, 2).
enum class TriangleFeature { face, edge0, edge1, edge2, vertex0, vertex1, vertex2 };

struct ClosestPoint {
  Eigen::Vector3d point;
  double distance = 0.0;
  int triangle = -1;  // -1: nothing within the search radius
  TriangleFeature feature = TriangleFeature::face;
};

// Closest point of triangle abc to p, after Ericson, Real-Time Collision Detection (2005),
// §5.1.5 (Voronoi regions of the vertices, edges and face).
ClosestPoint closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// Nearest-triangle queries on a TriangleMesh through a bounding-volume hierarchy of axis-aligned
// boxes (median split along the longest axis; depth-first search that skips boxes farther than
// the best distance so far). The mesh must outlive the tree.
class TriangleDistanceTree {
 public:
  explicit TriangleDistanceTree(const TriangleMesh& mesh);
  // The closest point of the mesh to p, looking no farther than maxDistance.
  ClosestPoint closest(const Eigen::Vector3d& p, double maxDistance) const;
  // Whether the feature is on the border of the mesh (an edge used by one triangle only, or a
  // vertex of such an edge): the mesh is an open surface there.
  bool onFreeBorder(const ClosestPoint& hit) const;

 private:
  struct Node {
    Eigen::Vector3d lower, upper;
    int first = 0, count = 0;  // leaf: triangles order_[first, first + count)
    int left = -1, right = -1;
  };
  int build(int first, int count);
  void search(int node, const Eigen::Vector3d& p, ClosestPoint& best) const;

  const TriangleMesh& mesh_;
  std::vector<int> order_;
  std::vector<Eigen::Vector3d> centroids_;
  std::vector<Node> nodes_;
  std::vector<std::array<bool, 3>> freeEdges_;  // per triangle, per edge
  std::vector<bool> freeVertices_;
};

}  // namespace sphcast
