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
      auto& box = group.boundingBox;
      gmsh::model::getBoundingBox(dimension, tag, box[0], box[1], box[2], box[3], box[4], box[5]);
      groups.push_back(group);
    }
  } catch (const std::exception& gmshError) {
    throw Error("gmsh cannot read '" + geometryFile.string() + "': " + gmshError.what());
  } catch (...) {
    throw Error("gmsh cannot read '" + geometryFile.string() + "'");
  }
  return groups;
}

}  // namespace sphcast
