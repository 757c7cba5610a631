#pragma once

#include <map>
#include <string>
#include <vector>

#include "case/CaseDescription.h"
#include "core/dictionary/Dictionary.h"
#include "inlets/PouringInlet.h"

namespace sphcast {

// constant/inlets (optional): pouring inlets that feed the flow's fluid (inlets/PouringInlet.h
// says how), one sub-dictionary each:
//
//   ladle
//   {
//       centre      (0 0 0.06);    // m: the disk's centre
//       direction   (0 0 -1);      // the pouring direction, normal to the disk
//       radius      0.008;         // m (2D: half the slot's width)
//       speed       0.5;           // m/s; or massRate 0.3; (kg/s: the speed follows)
//       T           970;           // K (a fluid without heat and with constant properties:
//       optional) mass        0.235;         // optional: kg to pour; or volume (m^3 at rho_s(T))
//       startTime   0;             // optional, s
//       endTime     1;             // optional, s
//   }
//
// 2D cases: the disk is a slot in the plane z = 0 (centre at z = 0, direction in the plane), and
// mass, massRate and volume are per metre of depth.
struct InletSetup {
  std::vector<PouringInletSettings> inlets;
  std::map<std::string, SourceLocation> declaredAt;
};

// They feed the case's fluid (case/CaseDescription.h), in its dimension.
InletSetup readInletSetup(const CaseDescription& description);

// The text of <time>/uniform/inlets.
std::string inletStateFile(const std::string& timeName,
                           const std::vector<const PouringInlet*>& inlets);

}  // namespace sphcast
