#include "boundaries/WallCondition.h"

#include "core/dictionary/Dictionary.h"

namespace sphcast {

const std::vector<std::string>& wallSlipNames() {
  static const std::vector<std::string> names{"noSlip", "slip"};
  return names;
}

const std::vector<std::string>& wallDissipationNames() {
  static const std::vector<std::string> names{"relativeVelocity", "normalApproach"};
  return names;
}

std::string WallCondition::describe() const {
  return "wallSlip " + wallSlipNames()[slip() ? 1 : 0] + ", wallDissipation " +
         wallDissipationNames()[normalApproach() ? 1 : 0];
}

WallCondition readWallCondition(const Dictionary& dict, const WallCondition& defaults) {
  WallCondition condition = defaults;
  if (dict.found("wallSlip")) {
    condition.velocity = dict.getChoice("wallSlip", wallSlipNames()) == "slip"
                             ? WallCondition::Velocity::slip
                             : WallCondition::Velocity::noSlip;
  }
  if (dict.found("wallDissipation")) {
    condition.dissipation =
        dict.getChoice("wallDissipation", wallDissipationNames()) == "normalApproach"
            ? WallCondition::Dissipation::normalApproach
            : WallCondition::Dissipation::relativeVelocity;
  }
  return condition;
}

}  // namespace sphcast
