// particleizeMold: mold particles from gmsh geometry. This version reads
// system/particleizeMoldDict, loads every geometry file with gmsh and checks that each patch it
// names is a physical group of the mesh (listing the groups present). Particle generation
// itself arrives with issue #4: until then it says so, writes nothing and exits non-zero.
#include <algorithm>
#include <iomanip>
#include <sstream>

#include "core/CaseFolder.h"
#include "core/CommandLine.h"
#include "core/Error.h"
#include "core/Log.h"
#include "core/dictionary/Dictionary.h"
#include "geometry/GmshModel.h"

namespace {

int particleizeMold(int argc, const char* const argv[]) {
  sphcast::CommandLine args("particleizeMold",
                            "Turns the mold geometry of system/particleizeMoldDict (gmsh .geo or "
                            ".msh) into wall particles in constant/particles/.");
  if (!args.parse(argc, argv)) return 0;
  const sphcast::CaseFolder caseFolder(args.casePath());
  sphcast::printBanner(args.application(), caseFolder.root().string());

  const auto dict = sphcast::Dictionary::read(caseFolder.systemFile("particleizeMoldDict"));
  dict.checkKeys({"geometry", "spacing", "wallLayers", "patches"});
  const auto files = dict.get<std::vector<std::string>>("geometry");
  std::vector<sphcast::PhysicalGroup> groups;
  for (const std::string& file : files) {
    const auto path = caseFolder.constant() / "geometry" / file;
    sphcast::info() << "Reading " << path.string() << '\n';
    for (const auto& group : sphcast::readPhysicalGroups(path)) {
      const auto& box = group.boundingBox;
      sphcast::info() << "    physical group " << std::setw(20) << std::left << group.name
                      << " dimension " << group.dimension << ", " << group.entityCount
                      << " entities, bounds (" << box[0] << ' ' << box[1] << ' ' << box[2]
                      << ") (" << box[3] << ' ' << box[4] << ' ' << box[5] << ")\n";
      groups.push_back(group);
    }
  }
  const auto& patches = dict.subDict("patches");
  for (const std::string& patch : patches.keys()) {
    const bool present = std::any_of(groups.begin(), groups.end(),
                                     [&](const auto& group) { return group.name == patch; });
    if (!present) {
      std::ostringstream names;
      for (const auto& group : groups) names << ' ' << group.name;
      throw sphcast::DictionaryError(patches.location(patch),
                                     "patch '" + patch + "' is not a physical group of the "
                                     "geometry; the groups present are (" + names.str() + " )");
    }
  }
  throw sphcast::Error(
      "the geometry and its patches are valid, but mold particle generation is not "
      "implemented yet (issue #4): nothing was written");
}

}  // namespace

int main(int argc, char* argv[]) {
  return sphcast::runApplication("particleizeMold", particleizeMold, argc, argv);
}
