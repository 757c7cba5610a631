#include "solver/HeatStepSchedule.h"

namespace sphcast {

bool HeatStepSchedule::stepsAfter(double deltaT, bool mustStep,
                                  const std::function<double()>& heatStableDeltaT) {
  if (everyStep_) {
    deltaT_ = deltaT;
    return true;
  }
  if (due_ == 0) due_ = heatStepFraction * heatStableDeltaT();
  pending_ += deltaT;
  if (pending_ < due_ && !mustStep) return false;
  deltaT_ = pending_;
  pending_ = 0;
  due_ = 0;
  return true;
}

double HeatStepSchedule::takePending() {
  const double pending = pending_;
  pending_ = 0;
  return pending;
}

}  // namespace sphcast
