#pragma once

#include <array>
#include <string>

#include "core/CaseFolder.h"
#include "core/dictionary/SourceLocation.h"

namespace sphcast {

// system/decomposeParDict, as OpenFOAM users write it:
//
//   numberOfSubdomains  4;
//   method              recursiveBisection;   // optional, the default; or hierarchical, simple,
//                                             // scotch, ptscotch, metis, kahip (see below)
//   hierarchicalCoeffs  { n (2 2 1); order xyz; }   // or simpleCoeffs { n (2 2 1); }, or coeffs
//   maxImbalance        0.1;   // optional: re-balance when the most loaded rank carries more
//                              // than (1 + maxImbalance) times the mean
//
// Two methods cut the particles: recursive bisection (each box cut across its longest axis at
// its weight's share) and hierarchical (n[0] slabs along the first axis of `order`, each cut
// into n[1] along the second, then n[2] along the third, every cut at its own particles' weight
// quantile). OpenFOAM's others map to them, and the log says so: `simple` to hierarchical in
// order xyz (simple's cuts are planes through the whole domain, which leave a casting's ranks
// unbalanced wherever the metal is not a box), and the graph partitioners of a mesh's cells
// (scotch, ptscotch, metis, parMetis, kahip) to recursive bisection, the particles' way to
// balanced, compact subdomains. The keys an OpenFOAM dictionary carries for a mesh (the other
// methods' coeffs, distributed, roots, the face constraints) are accepted and ignored.
struct DecompositionSettings {
  int subdomains = 1;
  std::string method = "recursiveBisection";  // what runs: recursiveBisection | hierarchical
  std::string requested;                      // the dictionary's method ("": none given)
  std::array<int, 3> counts{1, 1, 1};         // hierarchical: n along x, y, z
  std::array<int, 3> order{0, 1, 2};          // hierarchical: the axes in the order cut
  std::string note;                           // for the log: how the requested method maps
  double maxImbalance = 0.1;
  SourceLocation subdomainsAt;  // where numberOfSubdomains is written
};

// Reads and checks system/decomposeParDict for a run on `ranks` ranks in `dimension`s: a
// missing file, an unknown key or method, a count that is not a positive integer or that
// differs from the ranks mpirun started, an n whose product is not that count (or that cuts z
// in 2D), a maxImbalance that is not positive: an Error naming the file, line and key.
DecompositionSettings readDecompositionSettings(const CaseFolder& caseFolder, int ranks,
                                                int dimension = 3);

// "recursive bisection" or "hierarchical cuts n (2 2 1), order xyz", for the log.
std::string describeMethod(const DecompositionSettings& settings);

}  // namespace sphcast
