#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/Real.h"

namespace sphcast {

class Dictionary;

// What a wall sets for the flow at its surface. The flow meets a wall through mirror particles
// (Adami, Hu & Adams 2012; sph/FlowRates.h, accumulateWallPair): each wall particle k carries
// the pressure extrapolated from the fluid and the mirror velocity 2 v_wall - v_i, so the
// interface pressure resists any approach whatever the condition. The condition decides the
// rest, and a new one joins here (its name in the reader, its terms below) without touching
// the flow's pair loops:
//   velocity     noSlip: the shear of the fluid's velocity relative to the wall, extended
//                linearly through the surface (Morris, Fox & Zhu 1997): beta (v_i - v_wall),
//                beta = 1 + d_k / d_i;
//                slip: no viscous shear, the fluid slides held back only by the interface's
//                dissipation along oblique pairs.
//   dissipation  relativeVelocity: the interface's dissipation (and deltaSPH's artificial
//                viscosity) see the whole relative velocity;
//                normalApproach: only the approach to the wall, 2 ((v_i - v_wall) . n)
//                (n . (-e_ik)), so sliding along a wall is not dragged (doc/physics.md §7).
// Set for every wall by system/sphSchemes (wallSlip, wallDissipation) and for one wall by its
// own entry in physicsModels' flow { walls { <cloud> { wallSlip slip; } } }.
struct WallCondition {
  enum class Velocity { noSlip, slip };
  enum class Dissipation { relativeVelocity, normalApproach };

  Velocity velocity = Velocity::noSlip;
  Dissipation dissipation = Dissipation::relativeVelocity;

  bool slip() const { return velocity == Velocity::slip; }
  bool normalApproach() const { return dissipation == Dissipation::normalApproach; }

  // The velocity difference the pair's viscous term shears, from v_i - v_wall and beta.
  Vector shearVelocity(Real beta, const Vector& relative) const {
    return slip() ? Vector::Zero() : Vector(beta * relative);
  }
  // The relative velocity deltaSPH's artificial viscosity damps against the mirror: its normal
  // part at a slip wall or with normalApproach (against the whole of it this is a shear viscosity
  // of order alpha h c / 10, hundreds of times water's, held at the wall).
  Vector artificialViscosityVelocity(const Vector& relative, const Vector& normal) const {
    return slip() || normalApproach() ? Vector(relative.dot(normal) * normal) : relative;
  }
  // "wallSlip noSlip, wallDissipation relativeVelocity": the entries that set it, for the log.
  std::string describe() const;
};

// The valid names of each entry, in the order the documents list them.
const std::vector<std::string>& wallSlipNames();
const std::vector<std::string>& wallDissipationNames();

// `dict`'s wallSlip and wallDissipation over `defaults` (an absent entry keeps the default); a
// misspelt name throws DictionaryError listing the valid ones.
WallCondition readWallCondition(const Dictionary& dict, const WallCondition& defaults);

// The condition of every wall cloud: `all` unless the cloud has its own.
struct WallConditions {
  WallCondition all;
  std::map<std::string, WallCondition> own;

  const WallCondition& of(const std::string& cloud) const {
    const auto found = own.find(cloud);
    return found == own.end() ? all : found->second;
  }
};

}  // namespace sphcast
