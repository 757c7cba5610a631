#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "case/CaseDescription.h"
#include "core/Real.h"
#include "core/dictionary/Dictionary.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The initial fields of setCastFieldsDict's clouds (CastFieldsSetup.h gives the dictionary):
//
//   fields { U (0 0 0); T 970; rho 2400; }     // values, on every particle of the cloud (or
//                                              // of setFields' selection)
//   fields { T 970; rho standard; }            // rho_s(T) of the cloud's material
//   fields { T 970; rho hydrostatic; }         // rho_s (1 + |g| d / c^2) at depth d

// How a new cloud's rho is computed from its material, read and checked before the fill.
struct DensityStart {
  std::string model;         // standard | hydrostatic
  double restDensity = 0.0;  // rho_s at the initial T
  std::string origin;        // for the log: the table, and T where it matters
  Vector gravity = Vector::Zero();
  double soundSpeed = 0.0;
};

// What the whole case knows that a fill may need (case/CaseDescription.h: each file read when
// first asked for, once).
class CastCaseSettings {
 public:
  explicit CastCaseSettings(const CaseDescription& description) : description_(description) {}

  const MaterialLibrary& materials() const { return description_.materials(); }
  // constant/g; without it, the missing file's error
  Vector gravity() const;
  // The material constant/physicsModels' `materials { cloud material; }` gives the cloud, and
  // where; nothing when the file or the entry is absent.
  std::optional<std::pair<std::string, SourceLocation>> mappedMaterial(
      const std::string& cloud) const;
  const Dictionary& schemes() const { return description_.schemes(); }
  // The flow's wallClearance (system/sphSchemes, in spacings to a wall surface), else its
  // default: setCastFields keeps the metal as far from the walls as the flow will.
  double flowWallClearance() const;
  double soundSpeed() const;  // c of system/sphSchemes, positive
  // supportRadius of system/sphSchemes, else 3 dx (said in the log); more than the spacing.
  double supportRadius(double spacing) const;

 private:
  const CaseDescription& description_;
};

// Sets U, T and a numeric rho on the particles where `selected` is true (all when it is empty).
// A rho computed from the material (standard, hydrostatic) is set by setMaterialDensity, and is
// refused unless densityModelsAllowed (the new clouds of `clouds`).
void setFieldValues(const Dictionary& fields, ParticleCloud& cloud,
                    const std::vector<bool>& selected, bool densityModelsAllowed);

// rho standard | hydrostatic of a new cloud from its material's rho_s(T); nothing when rho is
// absent or a number. The material: the cloud dictionary's `material`, else physicsModels'
// `materials` map, else the cloud's name (the two files may not disagree).
std::optional<DensityStart> readDensityStart(const Dictionary& cloudDict,
                                             const std::string& cloudName,
                                             const CastCaseSettings& settings);

// rho of the filled cloud as `start` says, logged.
void setMaterialDensity(const DensityStart& start, ParticleCloud& cloud, double spacing);

}  // namespace sphcast
