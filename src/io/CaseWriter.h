#pragma once

#include <deque>
#include <string>
#include <vector>

#include "core/CaseFolder.h"
#include "core/TimeControl.h"
#include "io/TimeFolders.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// Writes time folders the way doc/design.md §2 asks: every cloud and uniform/time into a hidden
// folder first, then one rename, so a run killed at any moment leaves only complete folders;
// then the oldest written times beyond purgeWrite are removed and <case>.pvd is rewritten.
class CaseWriter {
 public:
  // Warns of a stale <old case name>.pvd left by a copy of the case (warnOfStaleCaseIndexes).
  // comm: the ranks that write each time together (a parallel run's pieces); rank 0 writes
  // the rest, purges and rewrites the .pvd.
  CaseWriter(const CaseFolder& caseFolder, int purgeWrite,
             const Communicator& comm = Communicator::self());

  // Writes <time>/<cloud>.vtp for every cloud, <time>/uniform/time and the uniform files.
  void write(const TimeState& time, const std::vector<const ParticleCloud*>& clouds,
             const std::vector<UniformFile>& uniformFiles = {});
  // Writes the start time again (with the fields the models added); never purged.
  void rewriteStart(const TimeState& time, const std::vector<const ParticleCloud*>& clouds,
                    const std::vector<UniformFile>& uniformFiles = {});

  void setPurgeWrite(int purgeWrite) { purgeWrite_ = purgeWrite; }

 private:
  const CaseFolder& caseFolder_;
  Communicator comm_;
  int purgeWrite_;
  std::deque<std::string> writtenTimes_;  // by this run, oldest first (purgeWrite)
};

}  // namespace sphcast
