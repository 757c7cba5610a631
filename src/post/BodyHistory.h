#pragma once

#include <string>
#include <vector>

#include "post/FunctionObject.h"

namespace sphcast {

class RigidBody;

// The history of the rigid bodies of constant/dynamicBodies (bodies/RigidBody.h), one file per
// body, postProcessing/<name>/<startTime>/<body>.dat, a row per sample:
//
//   time  displacement(x y z) m  velocity(x y z) m/s  fluidForce(x y z) N  force(x y z) N
//   atEndStop (1 or 0)  appliedForce(x y z) N (the press's: appliedForce and appliedPressure)
//
// sphCastFoam adds one named dynamicBodies to every run with bodies, every step (castPostProcess's
// bodyMotion reads it); `dynamicBodies { type bodyHistory; bodies (punch); }` in controlDict's
// functions gives another sampling or a choice of bodies (all by default).
class BodyHistory : public FunctionObject {
 public:
  BodyHistory(const std::string& name, const Dictionary& dict,
              const FunctionObjectContext& context);

 protected:
  void sample(double time) override;

 private:
  std::vector<const RigidBody*> bodies_;
};

}  // namespace sphcast
