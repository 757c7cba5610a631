#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/CaseFolder.h"
#include "core/TimeControl.h"
#include "parallel/Communicator.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// A file of <time>/uniform/ beside `time`: its name and its text (the rigid bodies' state).
struct UniformFile {
  std::string name;
  std::string text;
};

// Writes one complete time folder atomically (also used by setCastFields for 0/). Collective
// over comm: with more than one rank each writes its particles as its piece of every cloud
// (<cloud>.pvtp with <cloud>/<cloud>_<rank>.vtp, io/PvtpCloud.h), and rank 0 the rest.
void writeTimeFolder(const CaseFolder& caseFolder, const TimeState& time,
                     const std::vector<const ParticleCloud*>& clouds,
                     const std::vector<UniformFile>& uniformFiles = {},
                     const Communicator& comm = Communicator::self());

// Rewrites <case>.pvd from what is on disk: every cloud of every time folder, and the static
// clouds of constant/particles at every time that has no cloud of their name (a mold carrying
// heat is written to the time folders: its T is there), so ParaView plays the whole series.
void writeCaseIndex(const CaseFolder& caseFolder);

// The .pvd files of the case folder other than <case>.pvd that index nothing but this case's
// time folders and constant/particles: left by a copy of the case under another folder name
// (the index is named after the folder), and no longer updated. Other .pvd files are the
// user's own and not listed.
std::vector<std::filesystem::path> staleCaseIndexes(const CaseFolder& caseFolder);

// A warning for each of staleCaseIndexes, naming the index that is kept up to date. They are
// not removed: a .pvd in the case may be the user's.
void warnOfStaleCaseIndexes(const CaseFolder& caseFolder);

// The names of the clouds stored in a time folder (a .vtp or a .pvtp each), sorted.
std::vector<std::string> timeFolderCloudNames(const CaseFolder& caseFolder,
                                              const std::string& timeName);

// Every cloud stored in a time folder (a .vtp each, or a parallel run's .pvtp with its pieces),
// sorted by name. Collective: rank r of comm's N reads pieces r, r + N, ... of each .pvtp of
// several pieces; a .vtp (a serial run's, setCastFields') or a .pvtp of one piece rank 0 alone
// reads, whole, and the other ranks get the cloud's fields without particles (a start of 10^8
// particles is read once, not once per rank; the decomposition then sends every particle to
// its rank). A serial tool reads everything.
std::vector<ParticleCloud> readTimeFolderClouds(const CaseFolder& caseFolder,
                                                const std::string& timeName,
                                                const Communicator& comm = Communicator::self());

}  // namespace sphcast
