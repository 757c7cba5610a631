#pragma once

#include <optional>

#include "core/CaseFolder.h"
#include "core/Real.h"

namespace sphcast {

// constant/g as OpenFOAM writes it: `dimensions [0 1 -2 0 0 0 0]; value (0 0 -9.81);`.
Vector readGravity(const CaseFolder& caseFolder);
// constant/g when the file exists, else nothing: a case that only conducts heat needs none.
std::optional<Vector> readGravityIfPresent(const CaseFolder& caseFolder);

}  // namespace sphcast
