#include "geometry/PlanarFaces.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace sphcast {

namespace {

// A vertex farther than this from the face's plane makes the face curved.
constexpr double flatnessTolerance = 1e-6;  // in units of dx
// A straight-edge direction that carries this share of a face's border sets its frame.
constexpr double dominantBorderShare = 0.2;

bool alongAnAxis(const Eigen::Vector3d& unit) { return unit.cwiseAbs().maxCoeff() > 1.0 - 1e-12; }

// The direction (either sign) along which most of the border of a face runs, or zero when no
// direction carries dominantBorderShare of it.
Eigen::Vector3d dominantEdgeDirection(const TriangleMesh& wall, const std::vector<int>& triangles) {
  std::map<std::pair<int, int>, int> uses;
  for (const int t : triangles) {
    const auto& triangle = wall.triangles[static_cast<std::size_t>(t)];
    for (std::size_t e = 0; e < 3; ++e) {
      const int a = triangle[e], b = triangle[(e + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  std::vector<std::pair<Eigen::Vector3d, double>> directions;  // unit direction, border length
  double perimeter = 0.0;
  for (const auto& [edge, count] : uses) {
    if (count != 1) continue;  // inner edge of the face
    const Eigen::Vector3d along = wall.vertices[static_cast<std::size_t>(edge.second)] -
                                  wall.vertices[static_cast<std::size_t>(edge.first)];
    const double length = along.norm();
    if (length == 0.0) continue;
    perimeter += length;
    const Eigen::Vector3d unit = along / length;
    const auto same = std::find_if(directions.begin(), directions.end(), [&](const auto& d) {
      return std::abs(d.first.dot(unit)) > 1.0 - 1e-9;
    });
    if (same == directions.end()) {
      directions.emplace_back(unit, length);
    } else {
      same->second += length;
    }
  }
  const auto longest =
      std::max_element(directions.begin(), directions.end(),
                       [](const auto& a, const auto& b) { return a.second < b.second; });
  if (longest == directions.end() || longest->second < dominantBorderShare * perimeter) {
    return Eigen::Vector3d::Zero();
  }
  return longest->first;
}

}  // namespace

std::vector<PlanarFace> findPlanarFaces(const TriangleMesh& wall, const TriangleMesh& cavity,
                                        double spacing) {
  std::vector<PlanarFace> planar;
  if (wall.faces.size() != wall.size()) return planar;
  std::map<int, std::vector<int>> trianglesOfFace;
  for (std::size_t t = 0; t < wall.size(); ++t) {
    trianglesOfFace[wall.faces[t]].push_back(static_cast<int>(t));
  }
  for (const auto& [faceId, triangles] : trianglesOfFace) {
    // The normal of the largest triangle sets the sign; the area-weighted sum the direction.
    Eigen::Vector3d reference = Eigen::Vector3d::Zero(), centroid = Eigen::Vector3d::Zero();
    for (const int t : triangles) {
      const auto& v = wall.triangles[static_cast<std::size_t>(t)];
      const auto& a = wall.vertices[static_cast<std::size_t>(v[0])];
      const auto& b = wall.vertices[static_cast<std::size_t>(v[1])];
      const auto& c = wall.vertices[static_cast<std::size_t>(v[2])];
      const Eigen::Vector3d twiceArea = (b - a).cross(c - a);
      if (twiceArea.squaredNorm() > reference.squaredNorm()) {
        reference = twiceArea;
        centroid = (a + b + c) / 3.0;
      }
    }
    if (reference.squaredNorm() == 0.0) continue;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const int t : triangles) {
      const auto& v = wall.triangles[static_cast<std::size_t>(t)];
      const auto& a = wall.vertices[static_cast<std::size_t>(v[0])];
      const Eigen::Vector3d twiceArea =
          (wall.vertices[static_cast<std::size_t>(v[1])] - a)
              .cross(wall.vertices[static_cast<std::size_t>(v[2])] - a);
      sum += twiceArea.dot(reference) >= 0.0 ? twiceArea : Eigen::Vector3d(-twiceArea);
    }
    Eigen::Vector3d normal = sum.normalized();
    bool flat = true;
    for (const int t : triangles) {
      for (const int v : wall.triangles[static_cast<std::size_t>(t)]) {
        flat =
            flat && std::abs(normal.dot(wall.vertices[static_cast<std::size_t>(v)] - centroid)) <=
                        flatnessTolerance * spacing;
      }
    }
    if (!flat) continue;
    // Out of the material is into the cavity: step a hair off the face and ask the cavity.
    if (!cavity.encloses(centroid + 1e-3 * spacing * normal)) normal = -normal;

    PlanarFace face;
    face.face = faceId;
    const Eigen::Vector3d edge = dominantEdgeDirection(wall, triangles);
    if (alongAnAxis(normal) && (edge.isZero() || alongAnAxis(edge))) {
      Eigen::Index axis = 0;
      normal.cwiseAbs().maxCoeff(&axis);
      face.globalLattice = true;
      face.normal = Eigen::Vector3d::Unit(axis) * (normal[axis] > 0.0 ? 1.0 : -1.0);
      face.axis1 = Eigen::Vector3d::Unit((axis + 1) % 3);
      face.axis2 = Eigen::Vector3d::Unit((axis + 2) % 3);
      face.origin = face.normal * face.normal.dot(centroid);
    } else {
      face.normal = normal;
      Eigen::Vector3d axis1;
      if (edge.isZero()) {  // no straight edge dominates: the global axis most in the plane
        Eigen::Index axis = 0;
        normal.cwiseAbs().minCoeff(&axis);
        axis1 = Eigen::Vector3d::Unit(axis);
      } else {
        axis1 = edge;
      }
      face.axis1 = (axis1 - normal * normal.dot(axis1)).normalized();
      face.axis2 = normal.cross(face.axis1);
      face.origin = normal * normal.dot(centroid);
    }
    Eigen::Vector2d lower = Eigen::Vector2d::Constant(std::numeric_limits<double>::max());
    Eigen::Vector2d upper = Eigen::Vector2d::Constant(std::numeric_limits<double>::lowest());
    for (const int t : triangles) {
      for (const int v : wall.triangles[static_cast<std::size_t>(t)]) {
        const Eigen::Vector3d& p = wall.vertices[static_cast<std::size_t>(v)];
        const Eigen::Vector2d inPlane(face.axis1.dot(p - face.origin),
                                      face.axis2.dot(p - face.origin));
        lower = lower.cwiseMin(inPlane);
        upper = upper.cwiseMax(inPlane);
      }
    }
    if (!face.globalLattice) {  // the origin at the corner of the face's rectangle
      face.origin += face.axis1 * lower.x() + face.axis2 * lower.y();
      upper -= lower;
      lower.setZero();
    }
    face.lower = lower;
    face.upper = upper;
    planar.push_back(face);
  }
  return planar;
}

}  // namespace sphcast
