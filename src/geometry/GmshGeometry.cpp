#include "geometry/GmshGeometry.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "core/Error.h"
#include "geometry/WallCurves2D.h"

namespace sphcast {

namespace {

// gmsh 4.8 throws non-standard objects; its logger keeps the message.
[[noreturn]] void rethrowGmshError(const std::filesystem::path& file) {
  std::string reason;
  gmsh::logger::getLastError(reason);
  throw Error("gmsh cannot read '" + file.string() + "': " +
              (reason.empty() ? "unknown gmsh error" : reason));
}

std::vector<PhysicalGroup> listPhysicalGroups() {
  std::vector<PhysicalGroup> groups;
  gmsh::vectorpair dimTags;
  gmsh::model::getPhysicalGroups(dimTags);
  for (const auto& [dimension, tag] : dimTags) {
    PhysicalGroup group;
    group.dimension = dimension;
    group.tag = tag;
    gmsh::model::getPhysicalName(dimension, tag, group.name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dimension, tag, entities);
    group.entityCount = entities.size();
    // The group's box is the union of its entities' boxes.
    auto& box = group.boundingBox;
    box = {1e300, 1e300, 1e300, -1e300, -1e300, -1e300};
    for (const int entity : entities) {
      std::array<double, 6> b{};
      try {
        gmsh::model::getBoundingBox(dimension, entity, b[0], b[1], b[2], b[3], b[4], b[5]);
      } catch (...) {
        continue;  // a discrete entity of a .msh without elements has no box
      }
      for (std::size_t axis = 0; axis < 3; ++axis) {
        box[axis] = std::min(box[axis], b[axis]);
        box[axis + 3] = std::max(box[axis + 3], b[axis + 3]);
      }
    }
    groups.push_back(group);
  }
  return groups;
}

}  // namespace

void meshSurfacesForParticles(double maxTriangleSize) {
  // A plane is exact with triangles of any size, and so is a straight edge between planes: only
  // what is curved, and the edges and corners that bound it, need triangles of maxTriangleSize.
  std::set<int> coarseSurfaces, coarseCurves, coarsePoints;
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, 2);
  for (const auto& [dimension, tag] : entities) {
    std::string type;
    gmsh::model::getType(dimension, tag, type);
    if (type == "Plane") coarseSurfaces.insert(tag);
  }
  // Whether every entity of `upward` is in `coarse`.
  const auto allIn = [](const std::vector<int>& upward, const std::set<int>& coarse) {
    return std::all_of(upward.begin(), upward.end(),
                       [&](int tag) { return coarse.count(std::abs(tag)) > 0; });
  };
  gmsh::model::getEntities(entities, 1);
  for (const auto& [dimension, tag] : entities) {
    std::string type;
    gmsh::model::getType(dimension, tag, type);
    std::vector<int> upward, downward;
    gmsh::model::getAdjacencies(dimension, tag, upward, downward);
    if (type == "Line" && allIn(upward, coarseSurfaces)) coarseCurves.insert(tag);
  }
  gmsh::model::getEntities(entities, 0);
  for (const auto& [dimension, tag] : entities) {
    std::vector<int> upward, downward;
    gmsh::model::getAdjacencies(dimension, tag, upward, downward);
    if (allIn(upward, coarseCurves)) coarsePoints.insert(tag);
  }
  double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  const double coarseSize = std::max({x1 - x0, y1 - y0, z1 - z0, maxTriangleSize});
  gmsh::option::setNumber("Mesh.MeshSizeMax", coarseSize);
  gmsh::model::mesh::setSizeCallback(
      [=](int dimension, int tag, double, double, double) {
        const bool coarse = (dimension == 2 && coarseSurfaces.count(tag) > 0) ||
                            (dimension == 1 && coarseCurves.count(tag) > 0) ||
                            (dimension == 0 && coarsePoints.count(tag) > 0);
        return coarse ? coarseSize : maxTriangleSize;
      });
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::removeSizeCallback();
}

GmshGeometry::GmshGeometry(const std::filesystem::path& file, double maxTriangleSize)
    : file_(file) {
  if (!std::filesystem::is_regular_file(file)) {
    throw Error("geometry file '" + file.string() + "' does not exist");
  }
  const std::string extension = file.extension().string();
  if (extension != ".geo" && extension != ".msh") {
    throw Error("geometry file '" + file.string() + "': unknown kind; valid kinds are (.geo .msh)");
  }
  gmsh::initialize();
  try {
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
    gmsh::open(file.string());
    groups_ = listPhysicalGroups();
    if (maxTriangleSize > 0.0) {
      if (extension == ".geo") meshSurfacesForParticles(maxTriangleSize);
      std::vector<std::size_t> tags;
      std::vector<double> coordinates, parametric;
      gmsh::model::mesh::getNodes(tags, coordinates, parametric, -1, -1, false, false);
      const std::size_t largestTag = tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
      nodeIndex_.assign(largestTag + 1, -1);
      nodes_.reserve(tags.size());
      for (std::size_t n = 0; n < tags.size(); ++n) {
        nodeIndex_[tags[n]] = static_cast<int>(n);
        nodes_.emplace_back(coordinates[3 * n], coordinates[3 * n + 1], coordinates[3 * n + 2]);
      }
    }
  } catch (const Error&) {
    gmsh::finalize();
    throw;
  } catch (...) {
    try {
      rethrowGmshError(file);
    } catch (...) {
      gmsh::finalize();
      throw;
    }
  }
}

GmshGeometry::~GmshGeometry() { gmsh::finalize(); }

const PhysicalGroup* GmshGeometry::findGroup(const std::string& name) const {
  const auto found = std::find_if(groups_.begin(), groups_.end(),
                                  [&](const PhysicalGroup& group) { return group.name == name; });
  return found == groups_.end() ? nullptr : &*found;
}

int GmshGeometry::vertexIndex(std::size_t nodeTag) const {
  if (nodeTag >= nodeIndex_.size() || nodeIndex_[nodeTag] < 0) {
    throw Error("mesh of '" + file_.string() + "' uses node " + std::to_string(nodeTag) +
                " that it does not define");
  }
  return nodeIndex_[nodeTag];
}

TriangleMesh GmshGeometry::surfaceTriangles(const std::vector<std::pair<int, int>>& surfaces) const {
  TriangleMesh mesh;
  mesh.vertices = nodes_;  // by node index, so surfaces share their common nodes
  for (const auto& [surface, owner] : surfaces) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> elementTags, nodeTags;
    gmsh::model::mesh::getElements(types, elementTags, nodeTags, 2, surface);
    for (std::size_t t = 0; t < types.size(); ++t) {
      // Corner nodes come first in gmsh's numbering: 3 of a (curved) triangle, 4 of a quad.
      const int type = types[t];
      const std::size_t nodesPerElement = type == 2 ? 3 : type == 9 ? 6 : type == 3 ? 4
                                        : type == 16 ? 8 : type == 10 ? 9 : 0;
      if (nodesPerElement == 0) {
        throw Error("mesh of '" + file_.string() + "': surface " + std::to_string(surface) +
                    " has elements of gmsh type " + std::to_string(type) +
                    "; only triangles and quadrangles are understood");
      }
      const auto& nodes = nodeTags[t];
      for (std::size_t e = 0; e + nodesPerElement <= nodes.size(); e += nodesPerElement) {
        const int a = vertexIndex(nodes[e]), b = vertexIndex(nodes[e + 1]),
                  c = vertexIndex(nodes[e + 2]);
        mesh.triangles.push_back({a, b, c});
        mesh.owners.push_back(owner);
        mesh.faces.push_back(surface);
        if (type == 3 || type == 16 || type == 10) {
          mesh.triangles.push_back({a, c, vertexIndex(nodes[e + 3])});
          mesh.owners.push_back(owner);
          mesh.faces.push_back(surface);
        }
      }
    }
  }
  mesh.removeUnusedVertices();
  return mesh;
}

TriangleMesh GmshGeometry::tetrahedraBoundary(const std::vector<int>& volumeTags) const {
  std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> faces;  // sorted -> uses, face
  for (const int volume : volumeTags) {
    std::vector<std::size_t> elementTags, nodeTags;
    gmsh::model::mesh::getElementsByType(4, elementTags, nodeTags, volume);
    for (std::size_t e = 0; e + 4 <= nodeTags.size(); e += 4) {
      const std::array<int, 4> v = {vertexIndex(nodeTags[e]), vertexIndex(nodeTags[e + 1]),
                                    vertexIndex(nodeTags[e + 2]), vertexIndex(nodeTags[e + 3])};
      const std::array<std::array<int, 3>, 4> tetFaces = {
          {{v[0], v[2], v[1]}, {v[0], v[1], v[3]}, {v[1], v[2], v[3]}, {v[0], v[3], v[2]}}};
      for (const auto& face : tetFaces) {
        auto key = face;
        std::sort(key.begin(), key.end());
        auto& entry = faces[key];
        ++entry.first;
        entry.second = face;
      }
    }
  }
  TriangleMesh mesh;
  mesh.vertices = nodes_;
  for (const auto& [key, entry] : faces) {
    if (entry.first != 1) continue;
    mesh.triangles.push_back(entry.second);
    mesh.owners.push_back(0);
  }
  mesh.removeUnusedVertices();
  return mesh;
}

TriangleMesh GmshGeometry::boundaryOfVolumes(const std::vector<int>& volumeTags) const {
  gmsh::vectorpair volumes, boundary;
  for (const int tag : volumeTags) volumes.emplace_back(3, tag);
  std::vector<std::pair<int, int>> surfaces;
  try {
    gmsh::model::getBoundary(volumes, boundary, true, false, false);
  } catch (...) {
    rethrowGmshError(file_);
  }
  for (const auto& [dimension, tag] : boundary) {
    if (dimension == 2) surfaces.emplace_back(std::abs(tag), 0);
  }
  TriangleMesh mesh = surfaceTriangles(surfaces);
  // A .msh may lack the boundary's surface elements (MSH 2.2 keeps no topology; gmsh saves only
  // the elements of physical groups, so an unnamed lid is missing): the faces of the tetrahedra
  // then give the closed boundary.
  if (mesh.size() == 0 || mesh.freeEdgeCount() > 0) {
    TriangleMesh fromTetrahedra = tetrahedraBoundary(volumeTags);
    if (fromTetrahedra.size() > 0) mesh = std::move(fromTetrahedra);
  }
  return mesh;
}

TriangleMesh GmshGeometry::surfacesOf(const std::vector<OwnedGroup>& surfaceGroups) const {
  std::vector<std::pair<int, int>> surfaces;
  for (const auto& [group, owner] : surfaceGroups) {
    for (const int surface : entitiesOf(*group)) surfaces.emplace_back(surface, owner);
  }
  return surfaceTriangles(surfaces);
}

double GmshGeometry::groupMeasure(const PhysicalGroup& group) const {
  double measure = 0.0;
  for (const int entity : entitiesOf(group)) {
    try {
      double mass = 0.0;
      gmsh::model::occ::getMass(group.dimension, entity, mass);
      measure += mass;
      continue;
    } catch (...) {
      // not an OpenCASCADE entity
    }
    const auto& box = group.boundingBox;
    const double size = std::max({box[3] - box[0], box[4] - box[1], box[5] - box[2]});
    if (group.dimension == 1) {
      const auto points = sampledCurve(entity, size / 256.0);
      for (std::size_t j = 0; j + 1 < points.size(); ++j) measure += (points[j + 1] - points[j]).norm();
      continue;
    }
    if (group.dimension == 2 && std::abs(box[2]) <= 1e-6 * size && std::abs(box[5]) <= 1e-6 * size) {
      PlaneRegion region;
      for (const int curve : boundaryCurvesOf({entity})) region.add(planarCurve(curve, size / 256.0));
      measure += region.area();
      continue;
    }
    if (!nodes_.empty()) {
      const TriangleMesh mesh = group.dimension == 2
                                    ? surfaceTriangles({{entity, 0}})
                                    : boundaryOfVolumes({entity});
      measure += group.dimension == 2 ? mesh.area() : mesh.enclosedVolume();
      continue;
    }
    std::array<double, 6> b{};
    gmsh::model::getBoundingBox(group.dimension, entity, b[0], b[1], b[2], b[3], b[4], b[5]);
    const double x = b[3] - b[0], y = b[4] - b[1], z = b[5] - b[2];
    measure += group.dimension == 2 ? 2.0 * (x * y + y * z + z * x) : x * y * z;
  }
  return measure;
}

std::vector<int> GmshGeometry::entitiesOf(const PhysicalGroup& group) const {
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(group.dimension, group.tag, entities);
  return entities;
}

std::vector<int> GmshGeometry::volumesOf(const PhysicalGroup& volumeGroup) const {
  return entitiesOf(volumeGroup);
}

std::vector<int> GmshGeometry::volumesMeshedAgainst(int surface) const {
  // The surface's first triangle, as sorted vertex indices.
  std::vector<std::size_t> triangleTags, triangleNodes;
  gmsh::model::mesh::getElementsByType(2, triangleTags, triangleNodes, surface);
  if (triangleNodes.size() < 3) return {};
  std::array<int, 3> probe = {vertexIndex(triangleNodes[0]), vertexIndex(triangleNodes[1]),
                              vertexIndex(triangleNodes[2])};
  std::sort(probe.begin(), probe.end());
  std::vector<int> volumes;
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, 3);
  for (const auto& [dimension, volume] : entities) {
    std::vector<std::size_t> elementTags, nodeTags;
    gmsh::model::mesh::getElementsByType(4, elementTags, nodeTags, volume);
    for (std::size_t e = 0; e + 4 <= nodeTags.size(); e += 4) {
      std::array<int, 4> v = {vertexIndex(nodeTags[e]), vertexIndex(nodeTags[e + 1]),
                              vertexIndex(nodeTags[e + 2]), vertexIndex(nodeTags[e + 3])};
      std::sort(v.begin(), v.end());
      // The probe is a face of this tetrahedron when its three vertices are among the four.
      if (std::includes(v.begin(), v.end(), probe.begin(), probe.end())) {
        volumes.push_back(volume);
        break;
      }
    }
  }
  return volumes;
}

std::vector<int> GmshGeometry::volumesBoundedBy(const PhysicalGroup& surfaceGroup) const {
  std::vector<int> volumes;
  for (const int surface : entitiesOf(surfaceGroup)) {
    std::vector<int> upward, downward;
    gmsh::model::getAdjacencies(2, surface, upward, downward);
    if (upward.empty()) upward = volumesMeshedAgainst(surface);
    if (upward.size() != 1) {
      std::ostringstream message;
      message << "cannot tell which side of physical group '" << surfaceGroup.name
              << "' is the cavity: its surface " << surface << " in '" << file_.string()
              << "' bounds " << upward.size()
              << " volumes; the shell goes outside the one volume (the cavity) its surfaces bound"
              << (upward.empty() && file_.extension() == ".msh"
                      ? " (a .msh must hold that volume's tetrahedra: mesh it in 3D, or give the .geo)"
                      : "");
      throw Error(message.str());
    }
    volumes.push_back(upward.front());
  }
  std::sort(volumes.begin(), volumes.end());
  volumes.erase(std::unique(volumes.begin(), volumes.end()), volumes.end());
  return volumes;
}

std::vector<Eigen::Vector3d> GmshGeometry::sampledCurve(int curve, double maxSegment) const {
  std::string type;
  gmsh::model::getType(1, curve, type);
  // x, y, z of the curve's end points.
  const auto ends = [curve] {
    std::vector<int> upward, endPoints;
    gmsh::model::getAdjacencies(1, curve, upward, endPoints);
    std::vector<double> coordinates;
    for (const int end : endPoints) {
      std::vector<double> point;
      gmsh::model::getValue(0, end, {}, point);
      coordinates.insert(coordinates.end(), point.begin(), point.end());
    }
    return coordinates;
  };
  std::vector<double> coordinates;
  if (type == "Line") {
    coordinates = ends();
  } else if (type.find("Discrete") != std::string::npos) {
    coordinates = meshedCurve(curve);
    // A curve whose elements the .msh left out (gmsh saves only the physical groups'): the
    // chord between its ends, enough to bound a cavity for telling the sides of its walls.
    if (coordinates.empty()) coordinates = ends();
  } else {
    std::vector<double> lower, upper;
    try {
      gmsh::model::getParametrizationBounds(1, curve, lower, upper);
    } catch (...) {
      throw Error("curve " + std::to_string(curve) + " of '" + file_.string() + "' (" + type +
                  ") has no parametrisation to follow it by");
    }
    // A first look for the length, then points at most maxSegment apart.
    auto sample = [&](std::size_t pieces) {
      std::vector<double> parameters(pieces + 1);
      for (std::size_t j = 0; j <= pieces; ++j) {
        parameters[j] = lower[0] + (upper[0] - lower[0]) * static_cast<double>(j) / static_cast<double>(pieces);
      }
      gmsh::model::getValue(1, curve, parameters, coordinates);
    };
    sample(64);
    double length = 0.0;
    for (std::size_t j = 3; j + 2 < coordinates.size(); j += 3) {
      length += std::hypot(coordinates[j] - coordinates[j - 3], coordinates[j + 1] - coordinates[j - 2],
                           coordinates[j + 2] - coordinates[j - 1]);
    }
    sample(std::max<std::size_t>(64, static_cast<std::size_t>(std::ceil(1.01 * length / maxSegment))));
  }
  std::vector<Eigen::Vector3d> points;
  for (std::size_t j = 0; j + 2 < coordinates.size(); j += 3) {
    points.emplace_back(coordinates[j], coordinates[j + 1], coordinates[j + 2]);
  }
  return points;
}

std::vector<double> GmshGeometry::meshedCurve(int curve) const {
  // The curve's line elements (2- or 3-node: the first two nodes are the ends), chained from an
  // end node (any node of a closed curve); none without elements.
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elementTags, nodeTags;
  gmsh::model::mesh::getElements(types, elementTags, nodeTags, 1, curve);
  std::map<std::size_t, std::vector<std::size_t>> neighbours;
  for (std::size_t t = 0; t < types.size(); ++t) {
    const std::size_t nodesPerElement = types[t] == 1 ? 2 : types[t] == 8 ? 3 : 0;
    for (std::size_t e = 0; nodesPerElement > 0 && e + nodesPerElement <= nodeTags[t].size();
         e += nodesPerElement) {
      neighbours[nodeTags[t][e]].push_back(nodeTags[t][e + 1]);
      neighbours[nodeTags[t][e + 1]].push_back(nodeTags[t][e]);
    }
  }
  if (neighbours.empty()) return {};
  std::size_t start = neighbours.begin()->first;
  for (const auto& [node, next] : neighbours) {
    if (next.size() == 1) start = node;
    if (next.size() > 2) {
      throw Error("curve " + std::to_string(curve) + " of '" + file_.string() +
                  "' branches at node " + std::to_string(node) + "; a curve is one chain of lines");
    }
  }
  std::vector<double> coordinates;
  std::size_t previous = 0, node = start;
  for (std::size_t count = 0; count <= neighbours.size(); ++count) {
    std::vector<double> point, parametric;
    gmsh::model::mesh::getNode(node, point, parametric);
    coordinates.insert(coordinates.end(), point.begin(), point.end());
    const auto& next = neighbours[node];
    const auto onward = std::find_if(next.begin(), next.end(), [&](std::size_t n) {
      return n != previous;
    });
    if (onward == next.end() || (count > 0 && node == start)) break;
    previous = node;
    node = *onward;
  }
  return coordinates;
}

std::vector<Eigen::Vector2d> GmshGeometry::planarCurve(int curve, double maxSegment) const {
  std::vector<Eigen::Vector2d> points;
  for (const Eigen::Vector3d& p : sampledCurve(curve, maxSegment)) {
    if (std::abs(p.z()) > 1e-12 * (1.0 + p.norm())) {
      throw Error("curve " + std::to_string(curve) + " of '" + file_.string() + "' leaves the plane z = 0 (z = " +
                  std::to_string(p.z()) + "); a 2D geometry lies in the plane z = 0");
    }
    points.emplace_back(p.x(), p.y());
  }
  return points;
}

std::vector<int> GmshGeometry::surfacesBoundedBy(const PhysicalGroup& curveGroup) const {
  std::vector<int> surfaces;
  for (const int curve : entitiesOf(curveGroup)) {
    std::vector<int> upward, downward;
    gmsh::model::getAdjacencies(1, curve, upward, downward);
    if (upward.size() != 1) {
      std::ostringstream message;
      message << "cannot tell which side of physical group '" << curveGroup.name
              << "' is the cavity: its curve " << curve << " in '" << file_.string() << "' bounds "
              << upward.size()
              << " surfaces; the shell goes outside the one surface (the cavity) its curves bound, "
                 "or give the cavity's Physical Surface with the key 'cavity'";
      throw Error(message.str());
    }
    surfaces.push_back(upward.front());
  }
  std::sort(surfaces.begin(), surfaces.end());
  surfaces.erase(std::unique(surfaces.begin(), surfaces.end()), surfaces.end());
  return surfaces;
}

std::vector<int> GmshGeometry::boundaryCurvesOf(const std::vector<int>& surfaceTags) const {
  gmsh::vectorpair surfaces, boundary;
  for (const int tag : surfaceTags) surfaces.emplace_back(2, tag);
  try {
    gmsh::model::getBoundary(surfaces, boundary, true, false, false);
  } catch (...) {
    rethrowGmshError(file_);
  }
  std::vector<int> curves;
  for (const auto& [dimension, tag] : boundary) {
    if (dimension == 1) curves.push_back(std::abs(tag));
  }
  return curves;
}

}  // namespace sphcast
