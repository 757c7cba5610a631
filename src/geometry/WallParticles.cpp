#include "geometry/WallParticles.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace sphcast {

namespace {

// Particles are thinned to at least this many spacings apart (see WallParticles.h).
constexpr double thinningDistance = 0.75;

using CellKey = std::uint64_t;

// Packs three signed cell indices (|index| < 2^20) into one hash key.
CellKey cellKey(std::int64_t i, std::int64_t j, std::int64_t k) {
  constexpr std::int64_t bias = std::int64_t{1} << 20;
  return (static_cast<CellKey>(i + bias) << 42) | (static_cast<CellKey>(j + bias) << 21) |
         static_cast<CellKey>(k + bias);
}

// Points hashed by cubic cells, for "is anything within r" and nearest-neighbour queries.
class PointGrid {
 public:
  explicit PointGrid(double cellSize) : cellSize_(cellSize) {}

  void insert(const Eigen::Vector3d& p, int index) { cells_[keyOf(p)].push_back(index); }

  // Calls visit(index) for every point in the 27 cells around p.
  template <class Visit>
  void forEachNear(const Eigen::Vector3d& p, Visit visit) const {
    const std::int64_t i = cell(p.x()), j = cell(p.y()), k = cell(p.z());
    for (std::int64_t dk = -1; dk <= 1; ++dk) {
      for (std::int64_t dj = -1; dj <= 1; ++dj) {
        for (std::int64_t di = -1; di <= 1; ++di) {
          const auto found = cells_.find(cellKey(i + di, j + dj, k + dk));
          if (found == cells_.end()) continue;
          for (const int index : found->second) visit(index);
        }
      }
    }
  }

 private:
  std::int64_t cell(double x) const { return static_cast<std::int64_t>(std::floor(x / cellSize_)); }
  CellKey keyOf(const Eigen::Vector3d& p) const { return cellKey(cell(p.x()), cell(p.y()), cell(p.z())); }

  double cellSize_;
  std::unordered_map<CellKey, std::vector<int>> cells_;
};

struct ShellCandidate {
  Eigen::Vector3d position;
  Eigen::Vector3d normal;
  double wallDistance;
  double offLayer;  // how far the lattice point was moved to reach its layer
  int owner;
  int layer;
  bool onFaceLattice;  // from a flat face's own lattice: its volume is dx^3
};

// Lattice cells of size `cellSize` that a triangle, grown by `reach`, touches: sorted, so the
// lattice points are visited in a reproducible order.
std::vector<std::array<std::int64_t, 3>> cellsNearWall(const TriangleMesh& wall, double cellSize,
                                                       double reach) {
  std::unordered_set<CellKey> seen;
  std::vector<std::array<std::int64_t, 3>> cells;
  for (const auto& t : wall.triangles) {
    Eigen::Vector3d lower = wall.vertices[static_cast<std::size_t>(t[0])];
    Eigen::Vector3d upper = lower;
    for (const int v : t) {
      lower = lower.cwiseMin(wall.vertices[static_cast<std::size_t>(v)]);
      upper = upper.cwiseMax(wall.vertices[static_cast<std::size_t>(v)]);
    }
    std::array<std::int64_t, 3> first{}, last{};
    for (int axis = 0; axis < 3; ++axis) {
      first[static_cast<std::size_t>(axis)] =
          static_cast<std::int64_t>(std::floor((lower[axis] - reach) / cellSize));
      last[static_cast<std::size_t>(axis)] =
          static_cast<std::int64_t>(std::floor((upper[axis] + reach) / cellSize));
    }
    for (std::int64_t k = first[2]; k <= last[2]; ++k) {
      for (std::int64_t j = first[1]; j <= last[1]; ++j) {
        for (std::int64_t i = first[0]; i <= last[0]; ++i) {
          if (seen.insert(cellKey(i, j, k)).second) cells.push_back({i, j, k});
        }
      }
    }
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

// The given triangles of `wall`, as a mesh of their own.
TriangleMesh subMesh(const TriangleMesh& wall, const std::vector<int>& triangles) {
  TriangleMesh mesh;
  std::unordered_map<int, int> newIndex;
  for (const int t : triangles) {
    std::array<int, 3> triangle{};
    for (std::size_t corner = 0; corner < 3; ++corner) {
      const int v = wall.triangles[static_cast<std::size_t>(t)][corner];
      const auto [entry, added] = newIndex.try_emplace(v, static_cast<int>(mesh.vertices.size()));
      if (added) mesh.vertices.push_back(wall.vertices[static_cast<std::size_t>(v)]);
      triangle[corner] = entry->second;
    }
    mesh.triangles.push_back(triangle);
    mesh.owners.push_back(wall.owners[static_cast<std::size_t>(t)]);
  }
  return mesh;
}

// The candidates of the flat faces' own lattices (see WallParticles.h), appended to `candidates`.
void addFaceLatticeCandidates(const TriangleMesh& wall, const TriangleDistanceTree& tree,
                              const std::vector<PlanarFace>& planarFaces,
                              const std::vector<int>& planarOfTriangle, double spacing, int layers,
                              std::vector<ShellCandidate>& candidates) {
  const double reach = (layers + 0.5) * spacing;
  std::vector<std::vector<int>> trianglesOfFace(planarFaces.size());
  for (std::size_t t = 0; t < planarOfTriangle.size(); ++t) {
    if (planarOfTriangle[t] < 0) continue;
    trianglesOfFace[static_cast<std::size_t>(planarOfTriangle[t])].push_back(static_cast<int>(t));
  }
  for (std::size_t f = 0; f < planarFaces.size(); ++f) {
    const PlanarFace& face = planarFaces[f];
    const TriangleMesh faceMesh = subMesh(wall, trianglesOfFace[f]);
    const TriangleDistanceTree faceTree(faceMesh);
    const auto first = [&](double lower) {
      return static_cast<std::int64_t>(std::floor(lower / spacing)) - layers - 1;
    };
    const auto last = [&](double upper) {
      return static_cast<std::int64_t>(std::ceil(upper / spacing)) + layers;
    };
    for (int layer = 0; layer < layers; ++layer) {
      for (std::int64_t j = first(face.lower.y()); j <= last(face.upper.y()); ++j) {
        for (std::int64_t i = first(face.lower.x()); i <= last(face.upper.x()); ++i) {
          const Eigen::Vector3d p = face.origin + face.axis1 * latticeCoordinate(i, spacing) +
                                    face.axis2 * latticeCoordinate(j, spacing) -
                                    face.normal * ((layer + 0.5) * spacing);
          const ClosestPoint hit = tree.closest(p, reach);
          if (hit.triangle < 0 || hit.distance < 1e-9 * spacing || tree.onFreeBorder(hit)) continue;
          // This face (or its border) must be the nearest wall, or tie with it: p is then behind
          // the face, or past one of its convex edges, and in the mold material either way. A
          // tie (p as far from two faces meeting at a ridge of the material) is decided by
          // distances, not by which triangle the search met first, so that the point is kept
          // however round-off orders the two.
          const ClosestPoint onFace = faceTree.closest(p, reach);
          if (onFace.triangle < 0 || onFace.distance > hit.distance + 1e-9 * spacing) continue;
          const Eigen::Vector3d outOfMaterial = (onFace.point - p) / onFace.distance;
          const bool behindTheFace = outOfMaterial.dot(face.normal) > 1.0 - 1e-9;
          const int bandLayer =
              behindTheFace
                  ? layer
                  : std::clamp(static_cast<int>(std::lround(onFace.distance / spacing - 0.5)), 0,
                               layers - 1);
          candidates.push_back({p, behindTheFace ? face.normal : outOfMaterial, onFace.distance,
                                0.0, faceMesh.owners[static_cast<std::size_t>(onFace.triangle)],
                                bandLayer, true});
        }
      }
    }
  }
}

}  // namespace

WallParticles generateShellParticles(const TriangleMesh& wall, const LatticeSolid& cavity,
                                     double spacing, int layers, int patchCount,
                                     const std::vector<PlanarFace>& planarFaces) {
  const TriangleDistanceTree tree(wall);
  const double reach = (layers + 0.5) * spacing;
  // Which flat face each triangle is on (-1: none).
  std::vector<int> planarOfTriangle(wall.size(), -1);
  if (wall.faces.size() == wall.size()) {
    std::unordered_map<int, int> planarOfFace;
    for (std::size_t f = 0; f < planarFaces.size(); ++f) {
      planarOfFace[planarFaces[f].face] = static_cast<int>(f);
    }
    for (std::size_t t = 0; t < wall.size(); ++t) {
      const auto found = planarOfFace.find(wall.faces[t]);
      if (found != planarOfFace.end()) planarOfTriangle[t] = found->second;
    }
  }
  // Whether a closest point lies on a flat face or its border, decided by the vertices of the
  // feature it lies on, so that a tie between the triangles on both sides of an edge cannot
  // change the answer.
  std::vector<bool> vertexOnFlatFace(wall.vertices.size(), false);
  for (std::size_t t = 0; t < wall.size(); ++t) {
    if (planarOfTriangle[t] < 0) continue;
    for (const int v : wall.triangles[t]) vertexOnFlatFace[static_cast<std::size_t>(v)] = true;
  }
  const auto nearestIsFlat = [&](const ClosestPoint& hit) {
    const auto triangle = static_cast<std::size_t>(hit.triangle);
    const auto& t = wall.triangles[triangle];
    const auto on = [&](std::size_t corner) -> bool {
      return vertexOnFlatFace[static_cast<std::size_t>(t[corner])];
    };
    switch (hit.feature) {
      case TriangleFeature::face: return planarOfTriangle[triangle] >= 0;
      case TriangleFeature::edge0: return on(0) && on(1);
      case TriangleFeature::edge1: return on(1) && on(2);
      case TriangleFeature::edge2: return on(2) && on(0);
      case TriangleFeature::vertex0: return on(0);
      case TriangleFeature::vertex1: return on(1);
      case TriangleFeature::vertex2: return on(2);
    }
    return false;
  };
  std::vector<ShellCandidate> candidates;
  addFaceLatticeCandidates(wall, tree, planarFaces, planarOfTriangle, spacing, layers, candidates);
  // Cells a whole number of lattice spacings wide, so each lattice point is in exactly one.
  const double cellSize = spacing * std::ceil(reach / spacing);
  const auto cells = cellsNearWall(wall, cellSize, reach);
  const auto latticePerCell = static_cast<std::int64_t>(std::llround(cellSize / spacing));

  // Which side of each CAD face (of each triangle, without CAD faces) the cavity lies on, as
  // the sign of (p - hit) . n_triangle over the cavity's own lattice points whose nearest wall
  // point is inside that face: a lattice point outside the cavity but on the cavity's side of
  // the face it is nearest to is not mold material. Such points lie over an open rim (above the
  // opening of an open mold, outside the closed cavity, yet nearest to the wall just below the
  // rim) and, projected behind the wall, made a lip into the opening (measured: 72 particles up
  // to 0.58 dx above the rim of an open cone at dx = 4 mm; 164 up to 2.5 dx in another).
  const bool byFace = wall.faces.size() == wall.size();
  auto sideGroup = [&](int triangle) {
    return byFace ? wall.faces[static_cast<std::size_t>(triangle)] : triangle;
  };
  auto faceSide = [&](const ClosestPoint& hit, const Eigen::Vector3d& p) {
    const auto& t = wall.triangles[static_cast<std::size_t>(hit.triangle)];
    const Eigen::Vector3d& a = wall.vertices[static_cast<std::size_t>(t[0])];
    const Eigen::Vector3d normal = (wall.vertices[static_cast<std::size_t>(t[1])] - a)
                                       .cross(wall.vertices[static_cast<std::size_t>(t[2])] - a);
    return (p - hit.point).dot(normal) > 0.0 ? 1 : -1;
  };
  std::unordered_map<int, long> cavitySide;  // sideGroup -> sum of the cavity points' sides
  struct MaterialPoint {
    Eigen::Vector3d position;
    ClosestPoint hit;
    int side;  // faceSide of its nearest point's triangle
  };
  std::vector<MaterialPoint> materialPoints;
  for (const auto& cell : cells) {
    for (std::int64_t k = cell[2] * latticePerCell; k < (cell[2] + 1) * latticePerCell; ++k) {
      for (std::int64_t j = cell[1] * latticePerCell; j < (cell[1] + 1) * latticePerCell; ++j) {
        for (std::int64_t i = cell[0] * latticePerCell; i < (cell[0] + 1) * latticePerCell; ++i) {
          const Eigen::Vector3d p(latticeCoordinate(i, spacing), latticeCoordinate(j, spacing),
                                  latticeCoordinate(k, spacing));
          const ClosestPoint hit = tree.closest(p, reach);
          if (hit.triangle < 0 || hit.distance < 1e-9 * spacing) continue;
          if (cavity.contains(p)) {
            if (hit.feature == TriangleFeature::face) {
              cavitySide[sideGroup(hit.triangle)] += faceSide(hit, p);
            }
            continue;
          }
          if (tree.onFreeBorder(hit)) continue;
          // Nearest to a flat face: the face's own lattice has its particles there already (and
          // their volume is dx^3), straight behind it or past its edges.
          if (nearestIsFlat(hit)) continue;
          // (an edge or vertex too: material around a feature edge lies on the far side of both
          // faces' planes from the cavity, so only points over an open rim are on its side)
          materialPoints.push_back({p, hit, faceSide(hit, p)});
        }
      }
    }
  }

  // Lattice points per patch and band [k dx, (k+1) dx) behind the wall: the band volumes.
  std::vector<double> bandPoints(static_cast<std::size_t>(patchCount * layers), 0.0);
  for (const MaterialPoint& m : materialPoints) {
    const ClosestPoint& hit = m.hit;
    const auto vote = cavitySide.find(sideGroup(hit.triangle));
    if (vote != cavitySide.end() && vote->second != 0 && (vote->second > 0) == (m.side > 0)) {
      continue;  // on the cavity's side of its face: over an open rim, not in the mold
    }
    const int owner = wall.owners[static_cast<std::size_t>(hit.triangle)];
    const auto band = static_cast<int>(std::floor(hit.distance / spacing));
    if (band < layers) bandPoints[static_cast<std::size_t>(owner * layers + band)] += 1.0;
    const Eigen::Vector3d outOfMaterial = (hit.point - m.position) / hit.distance;
    // The one or two layers nearest to this point's distance.
    const double layerCoordinate = hit.distance / spacing - 0.5;
    const auto below = static_cast<int>(std::floor(layerCoordinate));
    const auto above = static_cast<int>(std::ceil(layerCoordinate));
    for (int layer = std::max(below, 0); layer <= std::min(above, layers - 1); ++layer) {
      const double layerDistance = (layer + 0.5) * spacing;
      candidates.push_back({hit.point - outOfMaterial * layerDistance, outOfMaterial,
                            layerDistance, std::abs(hit.distance - layerDistance), owner, layer,
                            false});
    }
  }

  // Greedy thinning, candidates nearest to their layer first (stable: reproducible).
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    // Below 1e-9 dx two offsets are the same: keep lattice order among exact layer points.
    return candidates[a].offLayer < candidates[b].offLayer - 1e-9 * spacing;
  });
  const double minimumSquared = thinningDistance * thinningDistance * spacing * spacing;
  PointGrid accepted(spacing);
  std::vector<std::size_t> kept;
  for (const std::size_t c : order) {
    const Eigen::Vector3d& p = candidates[c].position;
    bool crowded = false;
    accepted.forEachNear(p, [&](int other) {
      crowded = crowded || (candidates[kept[static_cast<std::size_t>(other)]].position - p)
                                   .squaredNorm() < minimumSquared;
    });
    if (crowded) continue;
    accepted.insert(p, static_cast<int>(kept.size()));
    kept.push_back(c);
  }

  std::vector<double> layerCounts(bandPoints.size(), 0.0);
  for (const std::size_t c : kept) {
    if (candidates[c].onFaceLattice) continue;
    layerCounts[static_cast<std::size_t>(candidates[c].owner * layers + candidates[c].layer)] += 1.0;
  }
  WallParticles shell;
  const double cellVolume = spacing * spacing * spacing;
  for (const std::size_t c : kept) {
    const ShellCandidate& candidate = candidates[c];
    const auto band = static_cast<std::size_t>(candidate.owner * layers + candidate.layer);
    shell.positions.push_back(candidate.position);
    shell.normals.push_back(candidate.normal);
    shell.wallDistances.push_back(candidate.wallDistance);
    const bool sharesItsBand = !candidate.onFaceLattice && bandPoints[band] > 0.0;
    shell.volumes.push_back(sharesItsBand ? cellVolume * bandPoints[band] / layerCounts[band]
                                          : cellVolume);
    shell.owners.push_back(candidate.owner);
  }
  return shell;
}

void WallParticles::append(const WallParticles& more) {
  positions.insert(positions.end(), more.positions.begin(), more.positions.end());
  normals.insert(normals.end(), more.normals.begin(), more.normals.end());
  wallDistances.insert(wallDistances.end(), more.wallDistances.begin(), more.wallDistances.end());
  volumes.insert(volumes.end(), more.volumes.begin(), more.volumes.end());
  owners.insert(owners.end(), more.owners.begin(), more.owners.end());
  // The optional per-particle fields, padded where one side lacks them.
  const std::size_t before = positions.size() - more.size();
  const auto join = [&](auto& mine, const auto& theirs, const auto& absent) {
    if (mine.empty() && theirs.empty()) return;
    mine.resize(before, absent);
    mine.insert(mine.end(), theirs.begin(), theirs.end());
    mine.resize(positions.size(), absent);
  };
  join(patchRadii, more.patchRadii, 0.0);
  join(secondNormals, more.secondNormals, Eigen::Vector3d::Zero().eval());
  join(secondWallDistances, more.secondWallDistances, 0.0);
  join(secondPatchRadii, more.secondPatchRadii, 0.0);
  join(patchesAtRim, more.patchesAtRim, 0.0);
  join(spacings, more.spacings, 0.0);
}

WallParticles fillVolumeParticles(const TriangleMesh& boundary, double spacing, int patch) {
  const LatticeSolid solid(boundary, spacing);
  const TriangleDistanceTree tree(boundary);
  WallParticles volume;
  volume.positions = solid.interiorPoints();
  const double cellVolume = spacing * spacing * spacing;
  const auto count = static_cast<std::ptrdiff_t>(volume.size());
  volume.normals.resize(volume.size());
  volume.wallDistances.resize(volume.size());
  volume.volumes.assign(volume.size(), cellVolume);
  volume.owners.assign(volume.size(), patch);
  // Each point's nearest wall on its own: the same result on any number of threads.
#pragma omp parallel for schedule(dynamic, 4096)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    const Eigen::Vector3d& p = volume.positions[static_cast<std::size_t>(i)];
    const ClosestPoint hit = tree.closest(p, std::numeric_limits<double>::max());
    Eigen::Vector3d outward;
    if (hit.distance > 1e-9 * spacing) {
      outward = (hit.point - p) / hit.distance;
    } else {  // on the surface: the triangle's normal, whichever way it points
      const auto& t = boundary.triangles[static_cast<std::size_t>(hit.triangle)];
      const auto& a = boundary.vertices[static_cast<std::size_t>(t[0])];
      outward = (boundary.vertices[static_cast<std::size_t>(t[1])] - a)
                    .cross(boundary.vertices[static_cast<std::size_t>(t[2])] - a)
                    .normalized();
    }
    volume.normals[static_cast<std::size_t>(i)] = outward;
    volume.wallDistances[static_cast<std::size_t>(i)] = hit.distance;
  }
  return volume;
}

double estimateShellParticleCount(const TriangleMesh& wall, double spacing, int layers) {
  return wall.area() / (spacing * spacing) * layers;
}

std::vector<bool> closerThan(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<Eigen::Vector3d>& obstacles, double radius) {
  PointGrid grid(radius);
  for (std::size_t i = 0; i < obstacles.size(); ++i) grid.insert(obstacles[i], static_cast<int>(i));
  std::vector<bool> close(points.size(), false);
  for (std::size_t i = 0; i < points.size(); ++i) {
    grid.forEachNear(points[i], [&](int j) {
      if ((obstacles[static_cast<std::size_t>(j)] - points[i]).squaredNorm() < radius * radius) {
        close[i] = true;
      }
    });
  }
  return close;
}

std::vector<SpacingStatistics> nearestNeighbourStatistics(const WallParticles& particles,
                                                          int ownerCount, double spacing) {
  // Neighbours beyond 2 dx are not searched for: such a particle reports 2 dx.
  const double searchRadius = 2.0 * spacing;
  PointGrid grid(searchRadius);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    grid.insert(particles.positions[i], static_cast<int>(i));
  }
  std::vector<SpacingStatistics> statistics(static_cast<std::size_t>(ownerCount));
  for (auto& s : statistics) s.min = std::numeric_limits<double>::max();
  std::vector<double> nearestOf(particles.size());
  const auto count = static_cast<std::ptrdiff_t>(particles.size());
#pragma omp parallel for schedule(dynamic, 4096)
  for (std::ptrdiff_t n = 0; n < count; ++n) {
    const auto i = static_cast<std::size_t>(n);
    double nearestSquared = searchRadius * searchRadius;
    grid.forEachNear(particles.positions[i], [&](int j) {
      if (static_cast<std::size_t>(j) == i) return;
      nearestSquared = std::min(
          nearestSquared, (particles.positions[static_cast<std::size_t>(j)] - particles.positions[i])
                              .squaredNorm());
    });
    nearestOf[i] = std::sqrt(nearestSquared);
  }
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const double nearest = nearestOf[i];
    auto& s = statistics[static_cast<std::size_t>(particles.owners[i])];
    ++s.count;
    s.min = std::min(s.min, nearest);
    s.max = std::max(s.max, nearest);
    s.mean += nearest;
  }
  for (auto& s : statistics) {
    if (s.count == 0) s.min = 0.0;
    else s.mean /= static_cast<double>(s.count);
  }
  return statistics;
}

}  // namespace sphcast
