#pragma once

#include <string>
#include <vector>

#include "core/CaseFolder.h"
#include "core/TimeControl.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// Writes one complete time folder atomically (also used by setCastFields for 0/).
void writeTimeFolder(const CaseFolder& caseFolder, const TimeState& time,
                     const std::vector<const ParticleCloud*>& clouds);

// Rewrites <case>.pvd from what is on disk: every cloud of every time folder, and the static
// clouds of constant/particles at every time, so ParaView plays the whole series.
void writeCaseIndex(const CaseFolder& caseFolder);

// Every cloud stored in a time folder (one .vtp each), sorted by name.
std::vector<ParticleCloud> readTimeFolderClouds(const CaseFolder& caseFolder,
                                                const std::string& timeName);

}  // namespace sphcast
