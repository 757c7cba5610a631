#include "geometry/WallSurfacePatches.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>

namespace sphcast {

namespace {

constexpr double sampleStep = 0.125;   // dx
constexpr double sampleMargin = 0.09;  // dx: covers the points between samples (0.088 dx)
constexpr double footDepth = 1.5;      // dx: the deepest particle whose foot counts
constexpr double footReach = 2.0;      // dx: the farthest foot a sample looks for
constexpr double sameFace = 0.9;       // cos 25 degrees
constexpr double closeFace = 0.985;    // cos 10 degrees
constexpr double servedReach = 2.0;    // dx: a foot whose particle is this near a sample
                                       // serves it (a neighbour of metal half a spacing in
                                       // front, for a support radius of 2.5 dx or more)

Eigen::Vector3i cellOf(const Eigen::Vector3d& p, double spacing) {
  return (p / spacing).array().floor().cast<int>();
}

std::int64_t cellKey(const Eigen::Vector3i& c) {
  // 21 bits per axis: a mold spans far fewer than a million cells along any axis.
  const auto bits = [](int v) { return static_cast<std::int64_t>(v + (1 << 20)) & 0x1FFFFF; };
  return bits(c.x()) | bits(c.y()) << 21 | bits(c.z()) << 42;
}

using Cells = std::unordered_map<std::int64_t, std::vector<int>>;

// Calls visit(k) for the particles binned in the cells within `reach` cells of p's.
template <class Visit>
void forEachNear(const Cells& cells, const Eigen::Vector3d& p, double spacing, int reach,
                 Visit&& visit) {
  const Eigen::Vector3i centre = cellOf(p, spacing);
  for (int i = -reach; i <= reach; ++i) {
    for (int j = -reach; j <= reach; ++j) {
      for (int l = -reach; l <= reach; ++l) {
        const auto cell = cells.find(cellKey(centre + Eigen::Vector3i(i, j, l)));
        if (cell == cells.end()) continue;
        for (const int k : cell->second) visit(k);
      }
    }
  }
}

// The feet of the particles at most footDepth deep, binned in cells of one spacing.
class FootGrid {
 public:
  FootGrid(const WallParticles& particles, double spacing) : spacing_(spacing) {
    feet_.resize(particles.size());
    for (std::size_t k = 0; k < particles.size(); ++k) {
      if (particles.wallDistances[k] > footDepth * spacing) continue;
      feet_[k] = particles.positions[k] + particles.wallDistances[k] * particles.normals[k];
      cells_[cellKey(cellOf(feet_[k], spacing))].push_back(static_cast<int>(k));
    }
  }

  // The nearest foot to sample s on a face of normal n (either orientation) that belongs to
  // the same face (normal within 25 degrees, within footReach); -1 if none.
  int nearestOfFace(const Eigen::Vector3d& s, const Eigen::Vector3d& n,
                    const WallParticles& particles) const {
    return nearestOfFace(s, n, particles, sameFace, footReach);
  }

  // The foot that stands for sample s, given `nearest` of its face: one whose normal is within
  // 10 degrees of n if that lies at most dx/2 farther, so that a foot on an edge, its normal
  // fanned between two faces, does not stand for a face whose own feet are as near; on a curved
  // face the nearest foot itself.
  int standingFor(const Eigen::Vector3d& s, const Eigen::Vector3d& n, int nearest,
                  const WallParticles& particles) const {
    const double reach = (s - foot(nearest)).norm() / spacing_ + 0.5;
    const int alike = nearestOfFace(s, n, particles, closeFace, std::min(reach, footReach));
    return alike >= 0 ? alike : nearest;
  }

  int nearestOfFace(const Eigen::Vector3d& s, const Eigen::Vector3d& n,
                    const WallParticles& particles, double alike, double within) const {
    double best = within * within * spacing_ * spacing_;
    int nearest = -1;
    forEachOfFace(s, n, particles, alike, static_cast<int>(std::ceil(within)),
                  [&](int k, double squared) {
                    if (squared < best) best = squared, nearest = k;
                  });
    return nearest;
  }

  const Eigen::Vector3d& foot(int k) const { return feet_[static_cast<std::size_t>(k)]; }

  // The side of a face the mold material lies on at sample s (face normal n, either way round),
  // as the first feet of that face within 3 dx say: n or -n pointing out of the material; zero
  // when none is that near (a thin part whose lattice points all face the other way).
  Eigen::Vector3d outward(const Eigen::Vector3d& s, const Eigen::Vector3d& n,
                          const WallParticles& particles) const {
    double best = 9.0 * spacing_ * spacing_;
    int nearest = -1;
    forEachOfFace(s, n, particles, sameFace, 3, [&](int k, double squared) {
      if (squared < best) best = squared, nearest = k;
    });
    if (nearest < 0) return Eigen::Vector3d::Zero();
    return particles.normals[static_cast<std::size_t>(nearest)].dot(n) > 0.0 ? n
                                                                             : Eigen::Vector3d(-n);
  }

 private:
  // Calls visit(k, |s - foot_k|^2) for the feet within `reach` cells of s on the face of normal
  // n: normal within acos(alike) of n (either way round), foot within dx/4 of s's plane.
  template <class Visit>
  void forEachOfFace(const Eigen::Vector3d& s, const Eigen::Vector3d& n,
                     const WallParticles& particles, double alike, int reach, Visit&& visit) const {
    forEachNear(cells_, s, spacing_, reach, [&](int k) {
      if (std::abs(particles.normals[static_cast<std::size_t>(k)].dot(n)) < alike) return;
      const Eigen::Vector3d fromFoot = s - feet_[static_cast<std::size_t>(k)];
      if (std::abs(fromFoot.dot(n)) > 0.25 * spacing_) return;
      visit(k, fromFoot.squaredNorm());
    });
  }

  double spacing_;
  std::vector<Eigen::Vector3d> feet_;
  Cells cells_;
};

// All particles, binned in cells of one spacing, for the second feet.
class ParticleGrid {
 public:
  ParticleGrid(const WallParticles& particles, double spacing) : spacing_(spacing) {
    for (std::size_t k = 0; k < particles.size(); ++k)
      cells_[cellKey(cellOf(particles.positions[k], spacing))].push_back(static_cast<int>(k));
  }

  // The particle nearest to sample s (within servedReach) whose second foot is free or already
  // on this face (normal within 25 degrees, plane within dx/4 of s), which lies behind the face
  // (where `outward`, its normal out of the material, is known) and whose foot on the face's
  // plane lies on the surface (not past the face's edge); -1 if none.
  int nearestFree(const Eigen::Vector3d& s, const Eigen::Vector3d& n,
                  const Eigen::Vector3d& outward, const TriangleDistanceTree& surface,
                  double spacing, const std::vector<Eigen::Vector3d>& secondNormal,
                  const std::vector<double>& secondDepth, const WallParticles& particles) const {
    double best = servedReach * servedReach * spacing * spacing;
    int nearest = -1;
    forEachNear(cells_, s, spacing_, static_cast<int>(std::ceil(servedReach)), [&](int k) {
      const auto kk = static_cast<std::size_t>(k);
      const Eigen::Vector3d toSample = s - particles.positions[kk];
      const double squared = toSample.squaredNorm();
      if (squared >= best) return;
      if (!outward.isZero() && toSample.dot(outward) <= 0.0) return;
      if (!secondNormal[kk].isZero()) {
        if (std::abs(secondNormal[kk].dot(n)) < sameFace) return;
        const Eigen::Vector3d foot = particles.positions[kk] + secondDepth[kk] * secondNormal[kk];
        if (std::abs((s - foot).dot(secondNormal[kk])) > 0.25 * spacing) return;
      } else {
        const Eigen::Vector3d foot = particles.positions[kk] + toSample.dot(n) * n;
        if (surface.closest(foot, 0.1 * spacing).triangle < 0) return;
      }
      best = squared, nearest = k;
    });
    return nearest;
  }

 private:
  double spacing_;
  Cells cells_;
};

// Per triangle, its edges that no other triangle shares (the rim of an open shell), as their end
// points.
std::vector<std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>> freeEdgesOfTriangles(
    const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  const auto edge = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  for (const auto& triangle : mesh.triangles) {
    for (int e = 0; e < 3; ++e) ++uses[edge(triangle[e], triangle[(e + 1) % 3])];
  }
  std::vector<std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>> free(mesh.size());
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    const auto& triangle = mesh.triangles[t];
    for (int e = 0; e < 3; ++e) {
      const int a = triangle[e], b = triangle[(e + 1) % 3];
      if (uses[edge(a, b)] == 1) {
        free[t].emplace_back(mesh.vertices[static_cast<std::size_t>(a)],
                             mesh.vertices[static_cast<std::size_t>(b)]);
      }
    }
  }
  return free;
}

Eigen::Vector3d triangleNormal(const TriangleMesh& mesh, int t) {
  const auto& triangle = mesh.triangles[static_cast<std::size_t>(t)];
  const Eigen::Vector3d& a = mesh.vertices[static_cast<std::size_t>(triangle[0])];
  return (mesh.vertices[static_cast<std::size_t>(triangle[1])] - a)
      .cross(mesh.vertices[static_cast<std::size_t>(triangle[2])] - a)
      .normalized();
}

// Calls visit(s) for points of triangle abc no farther apart than `step` in rows parallel to its
// longest edge (so that a sliver costs its area, not its longest edge squared), edges included.
template <class Visit>
void sampleTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    double step, Visit&& visit) {
  // p0 p1: the longest edge; p2: the vertex opposite it.
  Eigen::Vector3d p0 = a, p1 = b, p2 = c;
  if ((c - b).norm() > (p1 - p0).norm()) p0 = b, p1 = c, p2 = a;
  if ((a - c).norm() > (p1 - p0).norm()) p0 = c, p1 = a, p2 = b;
  const double length = (p1 - p0).norm();
  if (length == 0.0) return;
  const Eigen::Vector3d along = (p1 - p0) / length;
  const double apex = (p2 - p0).dot(along);  // p2's place along the edge
  const Eigen::Vector3d up = (p2 - p0) - apex * along;
  const double height = up.norm();
  const int rows = std::max(1, static_cast<int>(std::ceil(height / step)));
  for (int r = 0; r <= rows; ++r) {
    const double t = static_cast<double>(r) / rows;  // 0 on the edge, 1 at p2
    const double from = apex * t, to = length + (apex - length) * t;
    const int points = std::max(1, static_cast<int>(std::ceil((to - from) / step)));
    for (int q = 0; q <= points; ++q) {
      visit(p0 + t * up + (from + (to - from) * q / points) * along);
    }
  }
}

}  // namespace

void addWallSurfacePatches(WallParticles& particles, const TriangleMesh& surface, double spacing) {
  const std::size_t count = particles.size();
  const FootGrid feet(particles, spacing);
  const ParticleGrid near(particles, spacing);
  const TriangleDistanceTree tree(surface);
  std::vector<double> farthest(count, 0.0), secondFarthest(count, 0.0);
  std::vector<Eigen::Vector3d> secondNormal(count, Eigen::Vector3d::Zero());
  std::vector<double> secondDepth(count, 0.0);
  const auto reachAlong = [](const Eigen::Vector3d& fromFoot, const Eigen::Vector3d& normal,
                             double& radius) {
    const double off = fromFoot.dot(normal);
    radius = std::max(radius, std::sqrt(std::max(0.0, fromFoot.squaredNorm() - off * off)));
  };
  const auto freeEdges = freeEdgesOfTriangles(surface);
  std::vector<char> atRim(count, 0);
  for (std::size_t t = 0; t < surface.size(); ++t) {
    const auto& triangle = surface.triangles[t];
    const Eigen::Vector3d& a = surface.vertices[static_cast<std::size_t>(triangle[0])];
    const Eigen::Vector3d& b = surface.vertices[static_cast<std::size_t>(triangle[1])];
    const Eigen::Vector3d& c = surface.vertices[static_cast<std::size_t>(triangle[2])];
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    if (cross.norm() == 0.0) continue;
    const Eigen::Vector3d n = cross.normalized();
    const auto onRim = [&](const Eigen::Vector3d& s) {
      for (const auto& [p, q] : freeEdges[t]) {
        const Eigen::Vector3d along = q - p;
        const double u = std::clamp((s - p).dot(along) / along.squaredNorm(), 0.0, 1.0);
        if ((s - p - u * along).norm() < 1e-6 * spacing) return true;
      }
      return false;
    };
    sampleTriangle(a, b, c, sampleStep * spacing, [&](const Eigen::Vector3d& s) {
      const int k = feet.nearestOfFace(s, n, particles);
      if (k >= 0 &&
          (s - particles.positions[static_cast<std::size_t>(k)]).norm() <= servedReach * spacing) {
        const int f = feet.standingFor(s, n, k, particles);
        reachAlong(s - feet.foot(f), particles.normals[static_cast<std::size_t>(f)],
                   farthest[static_cast<std::size_t>(f)]);
        if (!freeEdges[t].empty() && onRim(s)) atRim[static_cast<std::size_t>(f)] = 1;
        return;
      }
      // No foot of this face near: the nearest particle that can stand for it takes a second
      // foot here (a thin part of the mold, an acute edge, a face its first layer misses).
      const Eigen::Vector3d side = feet.outward(s, n, particles);
      const int m =
          near.nearestFree(s, n, side, tree, spacing, secondNormal, secondDepth, particles);
      if (m < 0) {
        if (k >= 0) {
          reachAlong(s - feet.foot(k), particles.normals[static_cast<std::size_t>(k)],
                     farthest[static_cast<std::size_t>(k)]);
        }
        return;
      }
      const auto mm = static_cast<std::size_t>(m);
      if (secondNormal[mm].isZero()) {
        // out of the material: as the face's first feet say, else away from the particle
        const Eigen::Vector3d& x = particles.positions[mm];
        Eigen::Vector3d normal = !side.isZero()          ? side
                                 : (s - x).dot(n) >= 0.0 ? n
                                                         : Eigen::Vector3d(-n);
        // the foot is x's nearest point on this face, where its plane is the tangent one: on a
        // curved face, a few steps from the sample (project onto the tangent plane, take the
        // surface's nearest point there)
        Eigen::Vector3d onFace = s;
        for (int step = 0; step < 3; ++step) {
          const ClosestPoint hit = tree.closest(x + (onFace - x).dot(normal) * normal, spacing);
          if (hit.triangle < 0) break;
          const Eigen::Vector3d there = triangleNormal(surface, hit.triangle);
          if (std::abs(there.dot(normal)) < sameFace) break;
          onFace = hit.point;
          normal = there.dot(normal) > 0.0 ? there : Eigen::Vector3d(-there);
        }
        secondNormal[mm] = normal;
        secondDepth[mm] = (onFace - x).dot(normal);
      }
      reachAlong(s - (particles.positions[mm] + secondDepth[mm] * secondNormal[mm]),
                 secondNormal[mm], secondFarthest[mm]);
    });
  }
  particles.patchRadii.assign(count, 0.0);
  for (std::size_t k = 0; k < count; ++k) {
    if (farthest[k] > 0.0) particles.patchRadii[k] = farthest[k] + sampleMargin * spacing;
  }
  if (std::any_of(atRim.begin(), atRim.end(), [](char rim) { return rim != 0; }))
    particles.patchesAtRim.assign(atRim.begin(), atRim.end());
  const bool anySecond =
      std::any_of(secondFarthest.begin(), secondFarthest.end(), [](double r) { return r > 0.0; });
  if (!anySecond) return;
  particles.secondNormals = secondNormal;
  particles.secondWallDistances = secondDepth;
  particles.secondPatchRadii.assign(count, 0.0);
  for (std::size_t k = 0; k < count; ++k) {
    if (!secondNormal[k].isZero())
      particles.secondPatchRadii[k] = secondFarthest[k] + sampleMargin * spacing;
  }
}

}  // namespace sphcast
