#pragma once

#include <array>
#include <cmath>

#include "core/HostDevice.h"
#include "core/Real.h"

namespace sphcast {

class Dictionary;

// Which axes of the domain are periodic: axis a is periodic over [lower[a], lower[a] + period[a])
// when period[a] > 0, i.e. x and x + period[a] e_a are the same point. A pair loop takes the
// displacement x_i - x_j from separation() (the minimum image), never from x_i - x_j directly;
// with no periodic axis the two are identical. Cheap to copy, no pointers: pass it by value
// into a pair loop (or a GPU kernel).
class PeriodicBox {
 public:
  // No periodic axis.
  PeriodicBox() = default;

  // Makes `axis` (0, 1, 2 for x, y, z) periodic over [lower, lower + period); throws Error for a
  // bad axis or a period that is not finite and > 0.
  void setPeriodic(int axis, Real lower, Real period);

  bool isPeriodic(int axis) const { return period_[axis] > Real(0); }
  bool anyPeriodic() const { return isPeriodic(0) || isPeriodic(1) || isPeriodic(2); }
  Real lower(int axis) const { return lower_[axis]; }
  Real period(int axis) const { return period_[axis]; }

  // The minimum-image displacement x_i - x_j: on each periodic axis the image of x_j nearest to
  // x_i. Unique for pairs closer than period / 2, which the grid guarantees within its radius
  // (it requires period > 2 h). Branch-free: a non-periodic axis has period 0 and 1/period 0.
  SPHCAST_HOST_DEVICE Vector separation(const Vector& xi, const Vector& xj) const {
    // component by component on scalars: a Vector written one component at a time and read
    // back whole stalls on store forwarding (measured: +45 % on a periodic neighbour search)
    return Vector(minimumImage(xi[0] - xj[0], 0), minimumImage(xi[1] - xj[1], 1),
                  minimumImage(xi[2] - xj[2], 2));
  }

  // Component `axis` of separation() from d = x_i[axis] - x_j[axis].
  SPHCAST_HOST_DEVICE Real minimumImage(Real d, int axis) const {
    return d - period_[axis] * roundHalfAway(d * inversePeriod_[axis]);
  }

  // std::round(y) (nearest integer, halves away from zero, the sign of zero kept), bit for bit,
  // inline and without integer conversions: |y| < 1.5 (every pair of a grid's stencil whose
  // positions lie in the box) is 0 or +-1 by one comparison; anything else takes std::round.
  // Without SSE4.1 std::round is a call into libm, and a call inside a pair loop spills every
  // live floating-point register (all are caller-saved).
  SPHCAST_HOST_DEVICE static Real roundHalfAway(Real y) {
    const Real magnitude = std::fabs(y);
    if (!(magnitude < Real(1.5))) return std::round(y);
    return std::copysign(magnitude >= Real(0.5) ? Real(1) : Real(0), y);
  }

  // x moved into [lower, lower + period) on every periodic axis (for the integrator after a
  // drift); non-periodic axes are left as they are.
  Vector wrap(const Vector& x) const;

 private:
  std::array<Real, 3> lower_{0, 0, 0};
  std::array<Real, 3> period_{0, 0, 0};
  std::array<Real, 3> inversePeriod_{0, 0, 0};
};

// Runs pass(separation) with the separation x_i - x_j the box needs: its minimum image when an
// axis is periodic, the plain difference otherwise (chosen once per pass, not per pair).
template <class Pass>
void withSeparation(const PeriodicBox& periodic, Pass&& pass) {
  if (periodic.anyPeriodic()) {
    pass([periodic](const Vector& a, const Vector& b) { return periodic.separation(a, b); });
  } else {
    pass([](const Vector& a, const Vector& b) { return Vector(a - b); });
  }
}

// periodic { x (0 0.2); z (-0.01 0.01); } of constant/physicsModels: each axis named with its
// interval [lower, upper), longer than twice the support radius; a 2D case has no z axis.
// Throws DictionaryError naming the entry.
PeriodicBox readPeriodicBox(const Dictionary& periodic, Real supportRadius, int dimension);

}  // namespace sphcast
