#include "io/CaseWriter.h"

#include <filesystem>

#include "core/AtomicFile.h"
#include "core/Error.h"

namespace fs = std::filesystem;

namespace sphcast {

CaseWriter::CaseWriter(const CaseFolder& caseFolder, int purgeWrite, const Communicator& comm)
    : caseFolder_(caseFolder), comm_(comm), purgeWrite_(purgeWrite) {
  if (comm_.master()) warnOfStaleCaseIndexes(caseFolder_);
}

void CaseWriter::write(const TimeState& time, const std::vector<const ParticleCloud*>& clouds,
                       const std::vector<UniformFile>& uniformFiles) {
  writeTimeFolder(caseFolder_, time, clouds, uniformFiles, comm_);
  if (writtenTimes_.empty() || writtenTimes_.back() != time.name)
    writtenTimes_.push_back(time.name);
  if (!comm_.master()) return;
  // purgeWrite as OpenFOAM: only times this run wrote are removed, never the start time.
  while (purgeWrite_ > 0 && writtenTimes_.size() > static_cast<std::size_t>(purgeWrite_)) {
    // Out of sight first, so a kill during the removal leaves no half time folder in the case.
    const fs::path purged = caseFolder_.purgedFolder(writtenTimes_.front());
    renameAtomically(caseFolder_.root() / writtenTimes_.front(), purged);
    fs::remove_all(purged);
    writtenTimes_.pop_front();
  }
  writeCaseIndex(caseFolder_);
}

void CaseWriter::rewriteStart(const TimeState& time,
                              const std::vector<const ParticleCloud*>& clouds,
                              const std::vector<UniformFile>& uniformFiles) {
  writeTimeFolder(caseFolder_, time, clouds, uniformFiles, comm_);
  if (comm_.master()) writeCaseIndex(caseFolder_);
}

}  // namespace sphcast
