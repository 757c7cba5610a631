#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/CaseFolder.h"
#include "core/Real.h"
#include "core/dictionary/Dictionary.h"
#include "materials/MaterialLibrary.h"
#include "particles/CellGrid.h"

namespace sphcast {

// What constant/physicsModels asks of the heat transfer (thermal/HeatTransferRegistration.h
// lists the paths), and the clouds' materials:
//
//   materials    { metal AC4CH; mold iron; }   // optional: cloud -> material of
//                                              // constant/physicalProperties (default: a cloud's
//                                              // material is the one named like the cloud)
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
//
// system/sphSchemes gives supportRadius (h) to a case with heat and no flow.
struct HeatSetup {
  bool enabled = false;
  Dictionary heatTransfer;  // the sub-dictionary, for the paths to read
  std::vector<std::string> clouds;
  SourceLocation cloudsAt;
  std::map<std::string, double> fixedTemperature;  // cloud -> K
  // cloud -> (patch id, K) of its held patches, and their names for the log
  std::map<std::string, std::vector<std::pair<std::int64_t, double>>> heldPatches;
  std::map<std::string, std::vector<std::string>> heldPatchNames;
  std::map<std::string, std::string> materialOfCloud;
  std::map<std::string, SourceLocation> materialNamedAt;  // where each cloud's material is named
  // How often the heat paths run while a flow steps: every flow step, or (auto) in steps of
  // their own once the flow's steps add up to half of the heat's stable step, and at every
  // write (CastingSolver::evolve).
  bool heatEveryFlowStep = false;
  int dimension = 3;
  Real supportRadius = 0;
  PeriodicBox periodic;  // physicsModels' periodic axes (the flow's when there is one)
  std::optional<MaterialLibrary> materials;

  // The material of a heat cloud (error at the place it is named, listing the materials).
  const Material& materialOf(const std::string& cloud) const;
};

// Reads and checks physicsModels (and physicalProperties, sphSchemes when heat is on);
// errors name file, line and key.
HeatSetup readHeatSetup(const CaseFolder& caseFolder);

}  // namespace sphcast
