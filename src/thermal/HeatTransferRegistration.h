#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/Registry.h"
#include "core/dictionary/Dictionary.h"
#include "thermal/HeatTransferModel.h"

namespace sphcast {

// The heat paths by their names in constant/physicsModels, each its own switch:
//
//   heatTransfer
//   {
//       clouds           (metal mold);      // the clouds that carry heat (solver reads it)
//       fixedTemperature { mold 300; }      // optional: clouds held at T, K (solver reads it)
//       conduction       on;                                   // eq. (13)   HeatConduction.h
//       moldContact      { coefficients ((AC4CH iron 150)); }  // eq. (14)   MoldContactTransfer.h
//       atmosphere       { T 300; coefficients ((iron 80)); }  // eq. (15)   AtmosphereTransfer.h
//       radiation        { T 300; materials (iron); }          // eq. (16)   RadiationTransfer.h
//       exposedArea      gradient;    // optional: gradient (default) | granularity (eq. (11)),
//                                     // the A_i of atmosphere and radiation (sph/ExposedArea.h)
//       interval         auto;        // optional, with a flow: auto (default) | everyStep
//                                     // (the solver reads it: thermal/HeatSetup.h)
//   }
//
// A path is built when its entry is a sub-dictionary or a switch that is on (on, yes, true);
// off or absent: never built, costs nothing. Any other key is an error listing the valid ones.
std::vector<std::string> heatTransferKeys();

// The paths by their names, in the order of eq. (17), which is the order their rates are
// summed; each built from the context and heatTransfer, from which it takes its own entry.
using HeatTransferPaths =
    Registry<HeatTransferModel, const HeatTransferContext&, const Dictionary&>;
HeatTransferPaths& heatTransferPaths();

// Builds the paths heatTransfer switches on, in the registry's order. Sets needsExposedArea
// when a path reads A_i.
std::vector<std::unique_ptr<HeatTransferModel>> buildHeatTransferPaths(
    const HeatTransferContext& context, const Dictionary& heatTransfer, bool& needsExposedArea);

}  // namespace sphcast
