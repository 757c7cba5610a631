#pragma once

#include <string>
#include <vector>

#include "post/FunctionObject.h"

namespace sphcast {

// type energyBalance: the heat budget of the heat clouds over time (thermal/EnergyEquation.h
// keeps the accounts), one file `energyBalance`:
//
//   time  E_<cloud>...  lost_atmosphere  lost_radiation  lost_fixedTemperature  lost_spilled
//         imbalance  relativeImbalance
//
// E_c = sum m_i u_i of cloud c (J); lost_<path> the heat that left all clouds through the path
// since the run's first start (J; spilled: with the metal that left the domain,
// solver/MetalSpill.h); imbalance = sum_c (E_c - E_c(start)) + sum of lost (J),
// round-off when the paths conserve energy; relativeImbalance = imbalance / sum_c |E_c(start)|,
// the scale of that round-off (about 1e-16 per step: u is measured from 0 K, so E_c is the
// whole heat content, not what was exchanged).
// Keys: clouds (metal mold ...), clouds that carry heat (their u, mass and accounts).
class EnergyBalance : public FunctionObject {
 public:
  EnergyBalance(const std::string& name, const Dictionary& dict,
                const FunctionObjectContext& context);

 private:
  void sample(double time) override;

  std::vector<const ParticleCloud*> clouds_;
  std::string header_;
};

}  // namespace sphcast
