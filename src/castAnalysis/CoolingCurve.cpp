#include "castAnalysis/CoolingCurve.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sphcast {

namespace {

struct Line {
  double t0, T0, slope;  // T = T0 + slope (t - t0)
};

// The two lines meet where T0a + sa (t - t0a) = T0b + sb (t - t0b).
CoolingCurveBreak meet(const Line& a, const Line& b) {
  CoolingCurveBreak at;
  if (a.slope == b.slope) return at;
  at.time = (b.T0 - a.T0 + a.slope * a.t0 - b.slope * b.t0) / (a.slope - b.slope);
  at.temperature = a.T0 + a.slope * (at.time - a.t0);
  at.found = true;
  return at;
}

}  // namespace

CoolingCurveBreaks findCoolingCurveBreaks(const std::vector<double>& time,
                                          const std::vector<double>& temperature, double ratio,
                                          int window) {
  std::vector<double> t, T;
  for (std::size_t k = 0; k < time.size() && k < temperature.size(); ++k) {
    if (std::isfinite(temperature[k])) {
      t.push_back(time[k]);
      T.push_back(temperature[k]);
    }
  }
  CoolingCurveBreaks breaks;
  const auto n = static_cast<long>(t.size());
  const long w = window;
  // the segment k..k+1 may hold the kink: lines through [k - w, k] and [k + 1, k + 1 + w]
  const auto before = [&](long k) {
    return Line{t[k], T[k], (T[k] - T[k - w]) / (t[k] - t[k - w])};
  };
  const auto after = [&](long k) {
    return Line{t[k + 1], T[k + 1], (T[k + 1 + w] - T[k + 1]) / (t[k + 1 + w] - t[k + 1])};
  };
  // the first k where the lines' slopes differ by `ratio` may have a window across the kink:
  // of it and the next w, the k whose lines differ most has both windows clear of it
  const auto sharpest = [&](long first, long step, auto change) {
    long best = first;
    for (long k = first; k != first + step * (w + 1) && k >= w && k + 1 + w < n; k += step) {
      if (change(k) > change(best)) best = k;
    }
    return meet(before(best), after(best));
  };
  // a slope counts as cooling from 1 % of the curve's fastest: a flat stretch (a melt still
  // holding its superheat) has slopes of round-off whose ratios mean nothing
  double fastest = 0;
  for (long k = w; k + 1 + w < n; ++k) fastest = std::max(fastest, -before(k).slope);
  const double cooling = -0.01 * fastest;
  const auto slowing = [&](long k) { return before(k).slope / after(k).slope; };
  const auto quickening = [&](long k) { return after(k).slope / before(k).slope; };
  for (long k = w; k + 1 + w < n; ++k) {
    const Line a = before(k), b = after(k);
    if (a.slope < cooling && b.slope > a.slope / ratio) {  // cooling slows: the arrest
      breaks.arrest = sharpest(k, 1, slowing);
      break;
    }
  }
  for (long k = n - 2 - w; k >= w; --k) {
    const Line a = before(k), b = after(k);
    if (b.slope < cooling && a.slope > b.slope / ratio) {  // cooling speeds up: the end
      breaks.end = sharpest(k, -1, quickening);
      break;
    }
  }
  return breaks;
}

double firstTimeAtOrBelow(const std::vector<double>& time, const std::vector<double>& temperature,
                          double level) {
  for (std::size_t k = 0; k < time.size() && k < temperature.size(); ++k) {
    if (!(temperature[k] <= level)) continue;
    if (k == 0 || !std::isfinite(temperature[k - 1])) return time[k];
    const double f = (temperature[k - 1] - level) / (temperature[k - 1] - temperature[k]);
    return time[k - 1] + f * (time[k] - time[k - 1]);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace sphcast
