#include "core/Gravity.h"

#include <filesystem>

#include "core/dictionary/Dictionary.h"

namespace sphcast {

Vector readGravity(const CaseFolder& caseFolder) {
  const Dictionary g = Dictionary::read(caseFolder.constantFile("g"));
  g.checkKeys({"dimensions", "value"});
  const Dimensions acceleration{{0, 1, -2, 0, 0, 0, 0}};
  // OpenFOAM writes the dimensions apart; a set inside `value` is checked by get() too.
  if (g.found("dimensions")) g.checkDimensions("dimensions", acceleration);
  return g.get<Vector>("value", acceleration);
}

std::optional<Vector> readGravityIfPresent(const CaseFolder& caseFolder) {
  if (!std::filesystem::exists(caseFolder.constantFile("g"))) return std::nullopt;
  return readGravity(caseFolder);
}

}  // namespace sphcast
