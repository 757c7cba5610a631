#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "case/CaseDescription.h"
#include "core/dictionary/Dictionary.h"

namespace sphcast {

// What constant/physicsModels asks of the heat transfer (thermal/HeatTransferRegistration.h
// lists the paths; the clouds, their materials, the dimension and h are the case's:
// case/CaseDescription.h):
//
//   heatTransfer
//   {
//       clouds           (metal mold);        // the clouds that carry heat: of the start time,
//                                             // or mold clouds of constant/particles (then
//                                             // written to every time folder from now on)
//       fixedTemperature { mold 300; }        // optional: clouds, or patches of mold clouds
//                                             // (constant/particles/patches), held at T (K)
//       interval         auto;                // optional: auto | everyStep (see below)
//       conduction on;  moldContact {...}  atmosphere {...}  radiation {...}
//   }
struct HeatSetup {
  bool enabled = false;
  Dictionary heatTransfer;  // the sub-dictionary, for the paths to read
  std::vector<std::string> clouds;
  std::map<std::string, double> fixedTemperature;  // cloud -> K
  // cloud -> (patch id, K) of its held patches, and their names for the log
  std::map<std::string, std::vector<std::pair<std::int64_t, double>>> heldPatches;
  std::map<std::string, std::vector<std::string>> heldPatchNames;
  // How often the heat paths run while a flow steps: every flow step, or (auto) in steps of
  // their own once the flow's steps add up to half of the heat's stable step, and at every
  // write (CastingSolver::evolve).
  bool heatEveryFlowStep = false;
};

// Reads and checks heatTransfer (and that every heat cloud's material is in
// physicalProperties); errors name file, line and key.
HeatSetup readHeatSetup(const CaseDescription& description);

}  // namespace sphcast
