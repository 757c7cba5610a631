#pragma once

#include <vector>

namespace sphcast {

// What a foundry's thermal analysis reads off a cooling curve T(t): where its slope breaks at the
// start of freezing (the latent heat slows the cooling: the liquidus arrest) and at its end (the
// cooling speeds up again: the solidus), and when the curve crosses given temperatures.
//
// A break is found where the cooling slope over `window` samples after a point differs from the
// one over `window` samples before it by more than `ratio` (slower for the arrest, the first such
// point; faster for the end, the last; a slope counts as cooling from 1 % of the fastest); its time
// and temperature are where the two straight lines through those samples meet, so a
// piecewise-linear curve gives its kink exactly, whatever the sampling. NaN samples (no metal near
// the thermocouple) are skipped.
struct CoolingCurveBreak {
  bool found = false;
  double time = 0;
  double temperature = 0;
};

struct CoolingCurveBreaks {
  CoolingCurveBreak arrest;  // start of freezing
  CoolingCurveBreak end;     // end of freezing
};

CoolingCurveBreaks findCoolingCurveBreaks(const std::vector<double>& time,
                                          const std::vector<double>& temperature,
                                          double ratio = 2.0, int window = 3);

// The first time the curve falls to `level`, interpolated linearly; NaN if it never does.
double firstTimeAtOrBelow(const std::vector<double>& time, const std::vector<double>& temperature,
                          double level);

}  // namespace sphcast
