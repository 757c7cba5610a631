#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "boundaries/PeriodicBox.h"
#include "core/CaseFolder.h"
#include "core/Real.h"
#include "core/dictionary/Dictionary.h"
#include "materials/MaterialLibrary.h"

namespace sphcast {

// What a case is, read once and shared by every tool and every model family (doc/design.md
// §3): constant/physicsModels, system/sphSchemes, constant/physicalProperties and constant/g,
// each parsed at most once, and what they say of the whole case rather than of one model:
//
//   constant/physicsModels:  dimension 2;                // optional, 3 by default; 2D cases
//                                                        // lie in the x-y plane at one z
//                            periodic { x (0 0.2); }     // optional: periodic axes and their
//                                                        // intervals, longer than 2 h
//                            materials { metal AC4CH; }  // optional: a cloud's material (by
//                                                        // default the one named like it)
//                            flow { model ...; fluid metal; walls (mold); }  // the roles:
//                            heatTransfer { clouds (metal mold); ... }       // who is what
//   system/sphSchemes:       supportRadius 0.0045;       // h, m
//                            soundSpeed    50;           // c, m/s (the flow's and the fill's)
//
// The model families read their own sub-dictionaries from here (sph/FlowSetup.h,
// thermal/HeatSetup.h, surface/SurfaceTensionSetup.h, solidification/SolidificationSetup.h,
// bodies/BodySetup.h, inlets/InletSetup.h); none takes another family's result. A file that
// no one asks for is not read: a case without heat needs no constant/physicalProperties, a
// case without flow no constant/g. Errors name the file, line and key.
class CaseDescription {
 public:
  // Reads constant/physicsModels (when present) and constant/g (when present), and checks the
  // top-level keys of physicsModels and the roles.
  explicit CaseDescription(const CaseFolder& caseFolder);

  const CaseFolder& folder() const { return folder_; }

  // constant/physicsModels, or an empty dictionary when the case has none.
  bool hasPhysicsModels() const { return hasModels_; }
  const Dictionary& physicsModels() const { return models_; }
  // The sub-dictionary `key` of physicsModels, or nullptr when it is absent.
  const Dictionary* modelsEntry(std::string_view key) const;

  // system/sphSchemes, read at the first call (its absence is the reader's error).
  bool hasSchemes() const;
  const Dictionary& schemes() const;
  // constant/physicalProperties, read and checked in full at the first call.
  const MaterialLibrary& materials() const;
  // constant/g when the case has it.
  const std::optional<Vector>& gravity() const { return gravity_; }

  int dimension() const { return dimension_; }
  // h, supportRadius of system/sphSchemes (positive, a length), and where it is written.
  Real supportRadius() const;
  SourceLocation supportRadiusAt() const;
  // c of eq. (3), soundSpeed of system/sphSchemes (positive, a speed).
  Real soundSpeed() const;
  // physicsModels' periodic axes (none without the entry); needs h when there are any.
  PeriodicBox periodic() const;

  // The roles of the clouds: the flow's fluid and walls (a flow whose model is not none), the
  // clouds that carry heat (heatTransfer's clouds).
  bool hasFlow() const { return !fluidCloud_.empty(); }
  const std::string& fluidCloud() const { return fluidCloud_; }
  const std::vector<std::string>& wallClouds() const { return wallClouds_; }
  // The walls given with conditions of their own, flow { walls { mold { wallSlip slip; } } }
  // (boundaries/WallCondition.h reads them): each cloud with its entry, in the file's order.
  std::vector<std::pair<std::string, const Dictionary*>> wallEntries() const;
  SourceLocation fluidCloudAt() const;
  bool hasHeat() const { return !heatClouds_.empty(); }
  const std::vector<std::string>& heatClouds() const { return heatClouds_; }
  const SourceLocation& heatCloudsAt() const { return heatCloudsAt_; }
  bool carriesHeat(const std::string& cloud) const;

  // The material of `cloud`: the one `materials { cloud material; }` names (an error there
  // when physicalProperties lacks it), else the one named like the cloud (an error at
  // `namedAt`, the entry `key` that gave the cloud its role).
  const Material& materialOf(const std::string& cloud, const SourceLocation& namedAt,
                             std::string_view key) const;
  // The material of a heat cloud, with heatTransfer's clouds as the place it is named.
  const Material& heatCloudMaterial(const std::string& cloud) const;
  // The fluid's, with flow's fluid as the place it is named.
  const Material& fluidMaterial() const;

 private:
  CaseFolder folder_;
  bool hasModels_ = false;
  Dictionary models_;
  std::optional<Vector> gravity_;
  int dimension_ = 3;
  std::string fluidCloud_;
  std::vector<std::string> wallClouds_;
  std::vector<std::string> heatClouds_;
  SourceLocation heatCloudsAt_;
  // read when first asked for
  mutable std::optional<Dictionary> schemes_;
  mutable std::optional<MaterialLibrary> materials_;
};

}  // namespace sphcast
