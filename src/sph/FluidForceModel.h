#pragma once

#include <string>
#include <vector>

#include "core/Real.h"

namespace sphcast {

// A force on the fluid beyond the flow's own (pressure, viscosity, gravity): surface tension
// now, others later. The flow zeroes the acceleration and writes its own first, then asks each
// force model it was given to add (never overwrite) its part, at every evaluation of the rates
// (start, every step, both passes of deltaSPH's step). One virtual call per pass, never per pair.
class FluidForceModel {
 public:
  virtual ~FluidForceModel() = default;
  // The name of its step limit in the log ("capillary").
  virtual std::string limitName() const = 0;
  // Adds the model's acceleration to the fluid's `acceleration` field, for the neighbourhood's
  // last update.
  virtual void addAcceleration() = 0;
  // The largest step the model allows in the current state, seconds (infinity: none).
  virtual double stableDeltaT() const = 0;
  // Wall time spent in addAcceleration, seconds since construction.
  virtual double seconds() const = 0;
  // A model that needs the colour gradient g_i = -sum_j V_j grad_i W_ij over the fluid and the
  // walls (V_j = m_j / rho_j, the walls' `volume`; uncorrected kernel gradients) returns where
  // the flow should write it: the flow sums it in its own pair loop, which has every grad W at
  // hand, before addAcceleration, one per fluid particle; the particles its loop skips (frozen
  // metal with no melt within two hops) are left NaN. The model empties it once read.
  virtual std::vector<Vector>* colourGradientBuffer() { return nullptr; }
};

}  // namespace sphcast
