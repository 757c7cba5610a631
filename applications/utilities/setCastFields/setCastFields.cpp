// setCastFields: fills the regions of system/setCastFieldsDict with particles on a lattice,
// sets their initial fields and writes them as time 0.
#include <algorithm>
#include <filesystem>

#include "case/CaseDescription.h"
#include "core/CommandLine.h"
#include "core/Log.h"
#include "core/TimeControl.h"
#include "geometry/CastFieldsSetup.h"
#include "io/CaseWriter.h"
#include "io/TimeFolders.h"
#include "io/VtpCloud.h"
#include "particles/FieldNames.h"
#include "sph/FlowSetup.h"

namespace {

// The mold clouds particleizeMold wrote to constant/particles (none when there are none).
std::vector<sphcast::ParticleCloud> readMoldClouds(const sphcast::CaseFolder& caseFolder) {
  std::vector<std::filesystem::path> files;
  const auto folder = caseFolder.constantFile("particles");
  if (std::filesystem::is_directory(folder)) {
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      if (entry.path().extension() == ".vtp") files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<sphcast::ParticleCloud> clouds;
  for (const auto& file : files)
    clouds.push_back(sphcast::readCloudVtp(file, file.stem().string()));
  return clouds;
}

// The flow's fluid gets the pressure the solver starts it with, so that the first frame of the
// series carries p as every later one (ParaView colours the whole series by it).
void addStartPressure(const sphcast::CaseDescription& description,
                      std::vector<sphcast::ParticleCloud>& clouds) {
  const sphcast::FlowSetup flow = sphcast::readFlowSetup(description);
  if (!flow.enabled) return;
  for (sphcast::ParticleCloud& cloud : clouds) {
    if (cloud.name() != flow.fluidCloud) continue;
    cloud.addScalarField(sphcast::field::p) = sphcast::startPressure(flow, cloud);
    sphcast::info() << "Cloud " << cloud.name() << ": p as the flow starts it, c^2 (rho - rho_s)\n";
  }
}

int setCastFields(int argc, const char* const argv[]) {
  sphcast::CommandLine args("setCastFields",
                            "Fills the regions of system/setCastFieldsDict with particles and "
                            "writes them, with their initial fields, to the time folder 0.");
  if (!args.parse(argc, argv)) return 0;
  const sphcast::CaseFolder caseFolder(args.casePath());
  sphcast::printBanner(args.application(), caseFolder.root().string());

  const sphcast::CaseDescription description(caseFolder);
  auto clouds = sphcast::buildCastClouds(description, readMoldClouds(caseFolder));
  addStartPressure(description, clouds);
  std::vector<const sphcast::ParticleCloud*> written;
  for (const auto& cloud : clouds) {
    sphcast::info() << "Cloud " << cloud.name() << ": " << cloud.size() << " particles\n";
    written.push_back(&cloud);
  }
  const sphcast::TimeState zero;  // value 0, name "0", index 0
  sphcast::writeTimeFolder(caseFolder, zero, written);
  sphcast::writeCaseIndex(caseFolder);
  sphcast::warnOfStaleCaseIndexes(caseFolder);
  sphcast::info() << "Wrote " << (caseFolder.root() / "0").string() << "\n\nEnd\n";
  return 0;
}

}  // namespace

int main(int argc, char* argv[]) {
  return sphcast::runApplication("setCastFields", setCastFields, argc, argv);
}
