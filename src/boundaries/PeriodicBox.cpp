// Periodic faces: the minimum image and the wrap of a periodic axis, and the reader of
// physicsModels' periodic entry.
#include "boundaries/PeriodicBox.h"

#include <string>
#include <vector>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "core/dictionary/Dimensions.h"

namespace sphcast {
namespace {
const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};

const char* axisName(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }
}  // namespace

void PeriodicBox::setPeriodic(int axis, Real lower, Real period) {
  if (axis < 0 || axis > 2) {
    throw Error("PeriodicBox: axis " + std::to_string(axis) + " is not 0, 1 or 2 (x, y, z)");
  }
  if (!std::isfinite(lower) || !std::isfinite(period) || !(period > Real(0))) {
    throw Error(std::string("PeriodicBox: periodic axis ") + axisName(axis) +
                " needs a finite "
                "lower bound and a period > 0, got lower " +
                std::to_string(lower) + ", period " + std::to_string(period));
  }
  lower_[axis] = lower;
  period_[axis] = period;
  inversePeriod_[axis] = Real(1) / period;
}

Vector PeriodicBox::wrap(const Vector& x) const {
  Vector wrapped = x;
  for (int a = 0; a < 3; ++a) {
    if (!isPeriodic(a)) continue;
    wrapped[a] -= period_[a] * std::floor((x[a] - lower_[a]) * inversePeriod_[a]);
    if (wrapped[a] >= lower_[a] + period_[a]) wrapped[a] = lower_[a];  // round-off at the top
  }
  return wrapped;
}

// periodic { x (0 0.2); z (-0.01 0.01); }: each axis named with its interval [lower, upper).
PeriodicBox readPeriodicBox(const Dictionary& periodic, Real supportRadius, int dimension) {
  PeriodicBox box;
  const std::vector<std::string> axes{"x", "y", "z"};
  periodic.checkKeys(axes);
  for (int axis = 0; axis < 3; ++axis) {
    const std::string& key = axes[static_cast<std::size_t>(axis)];
    if (!periodic.found(key)) continue;
    const auto interval = periodic.get<Eigen::Vector2d>(key, length);
    const double period = interval[1] - interval[0];
    // the minimum image is unique only for pairs closer than half a period
    if (!(period > 2 * static_cast<double>(supportRadius))) {
      throw DictionaryError(periodic.location(key),
                            "periodic interval of " + key + " must be longer than twice the " +
                                "supportRadius (" + std::to_string(supportRadius) + " m) in " +
                                periodic.name());
    }
    if (dimension == 2 && axis == 2) {
      throw DictionaryError(periodic.location(key), "a 2D case has no periodic z axis");
    }
    box.setPeriodic(axis, static_cast<Real>(interval[0]), static_cast<Real>(period));
  }
  return box;
}

}  // namespace sphcast
