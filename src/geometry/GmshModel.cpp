#include "geometry/GmshModel.h"

#include <gmsh.h>

#include <algorithm>

#include "core/Error.h"

namespace sphcast {

namespace {

// gmsh keeps one global model: initialise for the duration of a read, always finalise.
class GmshSession {
 public:
  GmshSession() {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

}  // namespace

std::vector<PhysicalGroup> readPhysicalGroups(const std::filesystem::path& geometryFile) {
  if (!std::filesystem::is_regular_file(geometryFile)) {
    throw Error("geometry file '" + geometryFile.string() + "' does not exist");
  }
  const std::string extension = geometryFile.extension().string();
  if (extension != ".geo" && extension != ".msh") {
    throw Error("geometry file '" + geometryFile.string() +
                "': unknown kind; valid kinds are (.geo .msh)");
  }
  GmshSession session;
  std::vector<PhysicalGroup> groups;
  try {
    gmsh::open(geometryFile.string());
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
        std::array<double, 6> entityBox{};
        auto& b = entityBox;
        gmsh::model::getBoundingBox(dimension, entity, b[0], b[1], b[2], b[3], b[4], b[5]);
        for (int axis = 0; axis < 3; ++axis) {
          box[axis] = std::min(box[axis], b[axis]);
          box[axis + 3] = std::max(box[axis + 3], b[axis + 3]);
        }
      }
      groups.push_back(group);
    }
  } catch (...) {
    // gmsh 4.8 throws non-standard objects; its logger keeps the message.
    std::string reason;
    gmsh::logger::getLastError(reason);
    throw Error("gmsh cannot read '" + geometryFile.string() + "': " +
                (reason.empty() ? "unknown gmsh error" : reason));
  }
  return groups;
}

}  // namespace sphcast
