#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace sphcast {

// A physical group of a gmsh model: what the particleizeMoldDict names as patches.
struct PhysicalGroup {
  int dimension = 0;  // 2: surface, 3: volume
  int tag = 0;
  std::string name;
  std::size_t entityCount = 0;
  std::array<double, 6> boundingBox{};  // xmin ymin zmin xmax ymax zmax
};

// Loads a .geo (meshed on the fly) or .msh file through the gmsh library and lists its
// physical groups. gmsh's own messages are silenced; its errors become an Error naming the file.
std::vector<PhysicalGroup> readPhysicalGroups(const std::filesystem::path& geometryFile);

}  // namespace sphcast
