// sphCastFoam: the casting solver. Reads the case, runs the time loop, writes time folders.
#include "core/CaseFolder.h"
#include "core/CommandLine.h"
#include "core/Log.h"
#include "solver/CastingSolver.h"

namespace {

int sphCastFoam(int argc, const char* const argv[]) {
  sphcast::CommandLine args("sphCastFoam",
                            "Runs the casting simulation of a case from its start time "
                            "(system/controlDict) to endTime.");
  if (!args.parse(argc, argv)) return 0;
  const sphcast::CaseFolder caseFolder(args.casePath());
  sphcast::printBanner(args.application(), caseFolder.root().string());
  sphcast::CastingSolver solver(caseFolder);
  solver.run();
  return 0;
}

}  // namespace

int main(int argc, char* argv[]) {
  return sphcast::runApplication("sphCastFoam", sphCastFoam, argc, argv);
}
