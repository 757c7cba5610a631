#include "geometry/TriangleMesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace sphcast {

namespace {

using Edge = std::pair<int, int>;

Edge edgeOf(const std::array<int, 3>& triangle, int edge) {
  const int a = triangle[static_cast<std::size_t>(edge)];
  const int b = triangle[static_cast<std::size_t>((edge + 1) % 3)];
  return {std::min(a, b), std::max(a, b)};
}

std::map<Edge, int> edgeUses(const TriangleMesh& mesh) {
  std::map<Edge, int> uses;
  for (const auto& triangle : mesh.triangles) {
    for (int edge = 0; edge < 3; ++edge) ++uses[edgeOf(triangle, edge)];
  }
  return uses;
}

// Squared distance from p to the box [lower, upper] (zero inside).
double squaredDistanceToBox(const Eigen::Vector3d& p, const Eigen::Vector3d& lower,
                            const Eigen::Vector3d& upper) {
  const Eigen::Vector3d outside =
      (lower - p).cwiseMax(Eigen::Vector3d::Zero()).cwiseMax(p - upper);
  return outside.squaredNorm();
}

constexpr int leafSize = 4;

}  // namespace

double TriangleMesh::area() const {
  double total = 0.0;
  for (const auto& t : triangles) {
    total += 0.5 * (vertices[static_cast<std::size_t>(t[1])] - vertices[static_cast<std::size_t>(t[0])])
                       .cross(vertices[static_cast<std::size_t>(t[2])] -
                              vertices[static_cast<std::size_t>(t[0])])
                       .norm();
  }
  return total;
}

double TriangleMesh::enclosedVolume() const {
  double sixTimesVolume = 0.0;
  for (const auto& t : triangles) {
    const auto& a = vertices[static_cast<std::size_t>(t[0])];
    const auto& b = vertices[static_cast<std::size_t>(t[1])];
    const auto& c = vertices[static_cast<std::size_t>(t[2])];
    sixTimesVolume += a.dot(b.cross(c));
  }
  return std::abs(sixTimesVolume) / 6.0;
}

Eigen::Vector3d TriangleMesh::lower() const {
  Eigen::Vector3d result = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  for (const auto& v : vertices) result = result.cwiseMin(v);
  return result;
}

Eigen::Vector3d TriangleMesh::upper() const {
  Eigen::Vector3d result = Eigen::Vector3d::Constant(std::numeric_limits<double>::lowest());
  for (const auto& v : vertices) result = result.cwiseMax(v);
  return result;
}

std::size_t TriangleMesh::freeEdgeCount() const {
  // Sorted edges: a free edge is one that differs from both its neighbours in the order.
  std::vector<Edge> edges;
  edges.reserve(3 * triangles.size());
  for (const auto& triangle : triangles) {
    for (int edge = 0; edge < 3; ++edge) edges.push_back(edgeOf(triangle, edge));
  }
  std::sort(edges.begin(), edges.end());
  std::size_t free = 0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const bool sameAsPrevious = e > 0 && edges[e - 1] == edges[e];
    const bool sameAsNext = e + 1 < edges.size() && edges[e + 1] == edges[e];
    if (!sameAsPrevious && !sameAsNext) ++free;
  }
  return free;
}

void TriangleMesh::removeUnusedVertices() {
  std::vector<int> newIndex(vertices.size(), -1);
  std::vector<Eigen::Vector3d> used;
  for (auto& t : triangles) {
    for (int& v : t) {
      auto& index = newIndex[static_cast<std::size_t>(v)];
      if (index < 0) {
        index = static_cast<int>(used.size());
        used.push_back(vertices[static_cast<std::size_t>(v)]);
      }
      v = index;
    }
  }
  vertices = std::move(used);
}

void TriangleMesh::append(const TriangleMesh& other) {
  const int offset = static_cast<int>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const auto& t : other.triangles) {
    triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  owners.insert(owners.end(), other.owners.begin(), other.owners.end());
  if (!faces.empty() || !other.faces.empty()) {
    faces.resize(triangles.size() - other.size(), -1);
    if (other.faces.empty()) {
      faces.resize(triangles.size(), -1);
    } else {
      faces.insert(faces.end(), other.faces.begin(), other.faces.end());
    }
  }
}

bool TriangleMesh::encloses(const Eigen::Vector3d& p) const {
  // Directions with no simple ratio between their components, so that no axis-aligned or
  // diagonal edge of a drawn mold is parallel to them.
  const std::array<Eigen::Vector3d, 4> directions = {
      Eigen::Vector3d(0.5773502691896258, 0.3141592653589793, 0.7548776662466927).normalized(),
      Eigen::Vector3d(-0.2718281828459045, 0.8660254037844386, 0.4142135623730951).normalized(),
      Eigen::Vector3d(0.6180339887498949, -0.5772156649015329, -0.3819660112501051).normalized(),
      Eigen::Vector3d(-0.7071067811865476, -0.1234567890123457, 0.6931471805599453).normalized()};
  // Barycentric margin below which a crossing is too close to an edge to count reliably.
  constexpr double grazing = 1e-9;
  bool inside = false;
  for (const Eigen::Vector3d& direction : directions) {
    int crossings = 0;
    bool ambiguous = false;
    for (const auto& t : triangles) {
      const Eigen::Vector3d& a = vertices[static_cast<std::size_t>(t[0])];
      const Eigen::Vector3d ab = vertices[static_cast<std::size_t>(t[1])] - a;
      const Eigen::Vector3d ac = vertices[static_cast<std::size_t>(t[2])] - a;
      const Eigen::Vector3d normalOfRay = direction.cross(ac);
      const double determinant = ab.dot(normalOfRay);
      if (std::abs(determinant) < 1e-300) continue;  // parallel to the triangle
      const Eigen::Vector3d ap = p - a;
      const double u = ap.dot(normalOfRay) / determinant;
      if (u < -grazing || u > 1.0 + grazing) continue;
      const Eigen::Vector3d apCrossAb = ap.cross(ab);
      const double v = direction.dot(apCrossAb) / determinant;
      if (v < -grazing || u + v > 1.0 + grazing) continue;
      const double along = ac.dot(apCrossAb) / determinant;
      if (along <= 0.0) continue;
      if (u < grazing || v < grazing || u + v > 1.0 - grazing) {
        ambiguous = true;
        break;
      }
      ++crossings;
    }
    inside = crossings % 2 == 1;
    if (!ambiguous) break;
  }
  return inside;
}

ClosestPoint closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  ClosestPoint result;
  auto finish = [&](const Eigen::Vector3d& point, TriangleFeature feature) {
    result.point = point;
    result.feature = feature;
    result.distance = (p - point).norm();
    return result;
  };
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return finish(a, TriangleFeature::vertex0);
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return finish(b, TriangleFeature::vertex1);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    return finish(a + ab * (d1 / (d1 - d3)), TriangleFeature::edge0);
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return finish(c, TriangleFeature::vertex2);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    return finish(a + ac * (d2 / (d2 - d6)), TriangleFeature::edge2);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return finish(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))), TriangleFeature::edge1);
  }
  const double denominator = 1.0 / (va + vb + vc);
  return finish(a + ab * (vb * denominator) + ac * (vc * denominator), TriangleFeature::face);
}

TriangleDistanceTree::TriangleDistanceTree(const TriangleMesh& mesh) : mesh_(mesh) {
  const auto triangleCount = static_cast<int>(mesh.size());
  order_.resize(mesh.size());
  std::iota(order_.begin(), order_.end(), 0);
  centroids_.reserve(mesh.size());
  for (const auto& t : mesh.triangles) {
    centroids_.push_back((mesh.vertices[static_cast<std::size_t>(t[0])] +
                          mesh.vertices[static_cast<std::size_t>(t[1])] +
                          mesh.vertices[static_cast<std::size_t>(t[2])]) /
                         3.0);
  }
  nodes_.reserve(2 * mesh.size() / leafSize + 2);
  if (triangleCount > 0) build(0, triangleCount);

  const auto uses = edgeUses(mesh);
  freeEdges_.resize(mesh.size());
  freeVertices_.assign(mesh.vertices.size(), false);
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    for (int edge = 0; edge < 3; ++edge) {
      const Edge e = edgeOf(mesh.triangles[i], edge);
      const bool free = uses.at(e) == 1;
      freeEdges_[i][static_cast<std::size_t>(edge)] = free;
      if (free) {
        freeVertices_[static_cast<std::size_t>(e.first)] = true;
        freeVertices_[static_cast<std::size_t>(e.second)] = true;
      }
    }
  }
}

int TriangleDistanceTree::build(int first, int count) {
  Node node;
  node.lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  node.upper = Eigen::Vector3d::Constant(std::numeric_limits<double>::lowest());
  for (int i = first; i < first + count; ++i) {
    for (const int v : mesh_.triangles[static_cast<std::size_t>(order_[static_cast<std::size_t>(i)])]) {
      node.lower = node.lower.cwiseMin(mesh_.vertices[static_cast<std::size_t>(v)]);
      node.upper = node.upper.cwiseMax(mesh_.vertices[static_cast<std::size_t>(v)]);
    }
  }
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(node);
  if (count <= leafSize) {
    nodes_[static_cast<std::size_t>(index)].first = first;
    nodes_[static_cast<std::size_t>(index)].count = count;
    return index;
  }
  int axis = 0;
  (node.upper - node.lower).maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
                   order_.begin() + first + count, [&](int i, int j) {
                     return centroids_[static_cast<std::size_t>(i)][axis] <
                            centroids_[static_cast<std::size_t>(j)][axis];
                   });
  const int left = build(first, half);
  const int right = build(first + half, count - half);
  nodes_[static_cast<std::size_t>(index)].left = left;
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

void TriangleDistanceTree::search(int nodeIndex, const Eigen::Vector3d& p,
                                  ClosestPoint& best) const {
  const Node& node = nodes_[static_cast<std::size_t>(nodeIndex)];
  if (node.left < 0) {
    for (int i = node.first; i < node.first + node.count; ++i) {
      const int triangle = order_[static_cast<std::size_t>(i)];
      const auto& t = mesh_.triangles[static_cast<std::size_t>(triangle)];
      ClosestPoint hit = closestPointOnTriangle(p, mesh_.vertices[static_cast<std::size_t>(t[0])],
                                                mesh_.vertices[static_cast<std::size_t>(t[1])],
                                                mesh_.vertices[static_cast<std::size_t>(t[2])]);
      if (hit.distance < best.distance) {
        hit.triangle = triangle;
        best = hit;
      }
    }
    return;
  }
  const Node& left = nodes_[static_cast<std::size_t>(node.left)];
  const Node& right = nodes_[static_cast<std::size_t>(node.right)];
  const double toLeft = squaredDistanceToBox(p, left.lower, left.upper);
  const double toRight = squaredDistanceToBox(p, right.lower, right.upper);
  // Nearer box first, so that the farther one is usually skipped.
  const bool leftFirst = toLeft <= toRight;
  const std::pair<int, double> order[2] = {
      leftFirst ? std::pair{node.left, toLeft} : std::pair{node.right, toRight},
      leftFirst ? std::pair{node.right, toRight} : std::pair{node.left, toLeft}};
  for (const auto& [child, squaredDistance] : order) {
    if (squaredDistance < best.distance * best.distance) search(child, p, best);
  }
}

ClosestPoint TriangleDistanceTree::closest(const Eigen::Vector3d& p, double maxDistance) const {
  ClosestPoint best;
  best.distance = maxDistance;
  if (!nodes_.empty()) search(0, p, best);
  return best;
}

bool TriangleDistanceTree::onFreeBorder(const ClosestPoint& hit) const {
  if (hit.triangle < 0) return false;
  const auto triangle = static_cast<std::size_t>(hit.triangle);
  const auto& t = mesh_.triangles[triangle];
  switch (hit.feature) {
    case TriangleFeature::face: return false;
    case TriangleFeature::edge0: return freeEdges_[triangle][0];
    case TriangleFeature::edge1: return freeEdges_[triangle][1];
    case TriangleFeature::edge2: return freeEdges_[triangle][2];
    case TriangleFeature::vertex0: return freeVertices_[static_cast<std::size_t>(t[0])];
    case TriangleFeature::vertex1: return freeVertices_[static_cast<std::size_t>(t[1])];
    case TriangleFeature::vertex2: return freeVertices_[static_cast<std::size_t>(t[2])];
  }
  return false;
}

}  // namespace sphcast
