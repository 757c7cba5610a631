// sphCastFoam: the casting solver. Reads the case, runs the time loop, writes time folders;
// with -parallel under mpirun, decomposed over the ranks by system/decomposeParDict.
#include "core/CaseFolder.h"
#include "core/CommandLine.h"
#include "core/Log.h"
#include "parallel/Communicator.h"
#include "solver/CastingSolver.h"

namespace {

int sphCastFoam(int argc, const char* const argv[]) {
  sphcast::CommandLine args("sphCastFoam",
                            "Runs the casting simulation of a case from its start time "
                            "(system/controlDict) to endTime.");
  args.options()("parallel",
                 "run decomposed over the ranks mpirun started, as system/decomposeParDict "
                 "says (mpirun -np N sphCastFoam -parallel)");
  if (!args.parse(argc, argv)) return 0;
  const sphcast::ParallelRun mpi(args.has("parallel"));
  const sphcast::Communicator world = sphcast::Communicator::world();
  if (!world.master()) sphcast::silenceInfo(true);  // rank 0 prints the log
  const sphcast::CaseFolder caseFolder(args.casePath());
  sphcast::printBanner(args.application(), caseFolder.root().string());
  if (world.size() > 1) sphcast::info() << "Parallel: " << world.size() << " ranks (MPI)\n";
  sphcast::CastingSolver solver(caseFolder, world);
  solver.run();
  return 0;
}

}  // namespace

int main(int argc, char* argv[]) {
  return sphcast::runApplication("sphCastFoam", sphCastFoam, argc, argv);
}
