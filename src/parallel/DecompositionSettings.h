#pragma once

#include <string>

#include "core/CaseFolder.h"
#include "core/dictionary/SourceLocation.h"

namespace sphcast {

// system/decomposeParDict, as OpenFOAM users write it:
//
//   numberOfSubdomains  4;
//   method              recursiveBisection;
//   maxImbalance        0.1;   // optional: re-balance when the most loaded rank carries more
//                              // than (1 + maxImbalance) times the mean
struct DecompositionSettings {
  int subdomains = 1;
  std::string method = "recursiveBisection";
  double maxImbalance = 0.1;
  SourceLocation subdomainsAt;  // where numberOfSubdomains is written
};

// Reads and checks system/decomposeParDict for a run on `ranks` ranks: a missing file, an
// unknown key or method, a count that is not a positive integer or that differs from the ranks
// mpirun started, a maxImbalance that is not positive: an Error naming the file, line and key.
DecompositionSettings readDecompositionSettings(const CaseFolder& caseFolder, int ranks);

}  // namespace sphcast
