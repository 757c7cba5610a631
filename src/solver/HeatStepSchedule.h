#pragma once

#include <functional>

namespace sphcast {

// When the heat paths step while a flow steps, and over what time (heatTransfer's interval,
// thermal/HeatSetup.h; doc/physics.md §10.5). Without a flow, or with `interval everyStep`,
// every step is a heat step of the step's length. Otherwise (auto) the flow's steps (far
// shorter: acoustic, against the diffusion limit) add up until they reach heatStepFraction of
// the heat's own stable step, and the heat then takes one step of their sum at the positions of
// the end (the particles carry their u as they move; what lags is only the exchange between
// them, by at most that sum). Every written time is a heat step, so that a restart from it
// starts with nothing pending and reproduces the uninterrupted run.
//
// The fraction, measured (a half-full sphere of AC4CH at 900 K sloshing in an iron mold at
// 300 K, conduction and contact, 0.2 s, 2,621 flow steps; the largest change of T from the
// start is 16.4 K in the metal, 18.3 K in the mold): against heat at every flow step, the
// largest difference of a metal particle's T at 0.2 s is 1.20 / 0.61 / 0.13 / 0.015 K (mean
// 0.15 / 0.074 / 0.017 / 0.0025 K) with the fraction 0.5 / 0.25 / 0.1 / 0.03, in 10 / 20 /
// 50 / 141 heat steps: the error of the big steps is first order in their length, the steep
// start of a contact being what they resolve worst. 0.1 costs 50 heat steps instead of 2,621
// (0.25 s of heat in a 21 s run, against 13.4 s of a 35 s run).
class HeatStepSchedule {
 public:
  static constexpr double heatStepFraction = 0.1;

  explicit HeatStepSchedule(bool everyStep) : everyStep_(everyStep) {}

  bool everyStep() const { return everyStep_; }

  // After a flow step of deltaT: whether the heat steps now, over deltaT(). mustStep: nothing
  // may stay pending (the state will be written, or the run ends). heatStableDeltaT: the heat's
  // stable step of the present state, asked at the first flow step after each heat step.
  bool stepsAfter(double deltaT, bool mustStep, const std::function<double()>& heatStableDeltaT);
  // A heat step of deltaT apart from the flow's (the cooling mode's, a flush of the pending).
  void stepApart(double deltaT) { deltaT_ = deltaT; }
  // The flow time that no heat step has taken yet, now taken (0 when none).
  double takePending();
  void countStep() { ++steps_; }

  double deltaT() const { return deltaT_; }  // of the latest heat step
  long steps() const { return steps_; }

 private:
  bool everyStep_;
  double pending_ = 0;  // flow time since the last heat step
  double due_ = 0;      // the pending time that makes a heat step (0: to be asked)
  double deltaT_ = 0;
  long steps_ = 0;
};

}  // namespace sphcast
