// particleizeMold: mold particles from gmsh geometry. Reads system/particleizeMoldDict, makes the
// wall particles of every patch (geometry/MoldParticleization.h) and writes them, once all
// are made, to constant/particles/<cloud>.vtp with the patch list constant/particles/patches.
#include <filesystem>

#include "core/AtomicFile.h"
#include "core/CaseFolder.h"
#include "core/CommandLine.h"
#include "core/Log.h"
#include "geometry/MoldParticleization.h"
#include "io/VtpCloud.h"

namespace {

int particleizeMold(int argc, const char* const argv[]) {
  sphcast::CommandLine args("particleizeMold",
                            "Turns the mold geometry of system/particleizeMoldDict (gmsh .geo or "
                            ".msh) into wall particles in constant/particles/.");
  if (!args.parse(argc, argv)) return 0;
  const sphcast::CaseFolder caseFolder(args.casePath());
  sphcast::printBanner(args.application(), caseFolder.root().string());
  const sphcast::RunClock clock;

  const sphcast::ParticleizedMold mold = sphcast::particleizeMold(caseFolder);

  const auto folder = caseFolder.constantFile("particles");
  std::filesystem::create_directories(folder);
  for (const auto& cloud : mold.clouds) {
    const auto file = folder / (cloud.name() + ".vtp");
    sphcast::writeCloudVtp(cloud, file);
    sphcast::info() << "Wrote " << file.string() << " (" << cloud.size() << " particles)\n";
  }
  sphcast::writeFileAtomically(folder / "patches", sphcast::patchesDictionaryText(mold));
  sphcast::info() << "Wrote " << (folder / "patches").string() << "\n\n"
                  << clock.timesLine() << "\n\nEnd\n";
  return 0;
}

}  // namespace

int main(int argc, char* argv[]) {
  return sphcast::runApplication("particleizeMold", particleizeMold, argc, argv);
}
