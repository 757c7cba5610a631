#include "geometry/GmshModel.h"

#include "geometry/GmshGeometry.h"

namespace sphcast {

std::vector<PhysicalGroup> readPhysicalGroups(const std::filesystem::path& geometryFile) {
  const GmshGeometry geometry(geometryFile, 0.0);
  return geometry.groups();
}

}  // namespace sphcast
