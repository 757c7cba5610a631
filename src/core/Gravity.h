#pragma once

#include "core/CaseFolder.h"
#include "core/Real.h"

namespace sphcast {

// constant/g as OpenFOAM writes it: `dimensions [0 1 -2 0 0 0 0]; value (0 0 -9.81);`.
Vector readGravity(const CaseFolder& caseFolder);

}  // namespace sphcast
