#include "sph/RiemannSolver.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "sph/EquationOfState.h"

namespace sphcast {
namespace {

const Vector towardsRight(1, 0, 0);
constexpr Real c = 50;

TEST(AcousticRiemannInterface, EqualStatesGiveThatState) {
  const InterfaceSide side{2400, 1.5e4, Vector(0.3, -0.2, 0.1)};
  const auto star = AcousticRiemannInterface{}(side, side, towardsRight, c);
  EXPECT_DOUBLE_EQ(star.pressure, 1.5e4);
  EXPECT_NEAR((star.velocity - side.velocity).norm(), 0, 1e-15);
}

TEST(AcousticRiemannInterface, AHydrostaticJumpAtRestLeavesTheVelocityAtRest) {
  // Two particles of a column at rest, left one dx = 5 mm below the right one: p_L - p_R =
  // rho g dx. Given as restingJump, v* = 0 (no density change at rest); without it v* points
  // from high to low pressure by rho g dx / (2 rho c) = g dx / (2 c).
  const Real g = Real(9.81);
  const Real dx = Real(0.005);
  const InterfaceSide left{1000, 1000 * g * dx, Vector::Zero()};
  const InterfaceSide right{1000, 0, Vector::Zero()};
  const Vector up(0, 1, 0);
  const auto atRest = AcousticRiemannInterface{}(left, right, up, c, 1000 * g * dx);
  EXPECT_EQ(atRest.velocity, Vector::Zero());
  EXPECT_DOUBLE_EQ(atRest.pressure, 0.5 * 1000 * g * dx);
  const auto plain = AcousticRiemannInterface{}(left, right, up, c);
  EXPECT_NEAR(plain.velocity.y(), g * dx / (2 * c), 1e-15);
  // a jump beyond the hydrostatic one still drives v*
  const InterfaceSide pushed{1000, 2000 * g * dx, Vector::Zero()};
  const auto driven = AcousticRiemannInterface{}(pushed, right, up, c, 1000 * g * dx);
  EXPECT_NEAR(driven.velocity.y(), g * dx / (2 * c), 1e-15);
}

TEST(AcousticRiemannInterface, StrongCompressionGivesTheAcousticImpedanceJump) {
  // U_L - U_R = 20 m/s >= c/3: limiter 1, so P* = P_mean + rho c (U_L - U_R) / 2 exactly.
  const InterfaceSide left{2400, 0, Vector(10, 0, 0)};
  const InterfaceSide right{2400, 0, Vector(-10, 0, 0)};
  const auto star = AcousticRiemannInterface{}(left, right, towardsRight, c);
  EXPECT_DOUBLE_EQ(star.pressure, 0.5 * 2400 * c * 20);
  EXPECT_NEAR(star.velocity.norm(), 0, 1e-15);
}

TEST(AcousticRiemannInterface, WeakCompressionIsDampedByTheLimiter) {
  // U_L - U_R = 0.02 m/s: limiter 3 * 0.02 / 50 = 1.2e-3.
  const InterfaceSide left{2400, 100, Vector(0.01, 0, 0)};
  const InterfaceSide right{2400, 100, Vector(-0.01, 0, 0)};
  const auto star = AcousticRiemannInterface{}(left, right, towardsRight, c);
  EXPECT_DOUBLE_EQ(star.pressure, 100 + 0.5 * 1.2e-3 * 2400 * c * 0.02);
}

TEST(AcousticRiemannInterface, ExpansionAddsNoPressureDissipation) {
  const InterfaceSide left{2400, 100, Vector(-1, 0, 0)};
  const InterfaceSide right{2400, 300, Vector(1, 0, 0)};
  const auto star = AcousticRiemannInterface{}(left, right, towardsRight, c);
  EXPECT_DOUBLE_EQ(star.pressure, 200);
  // The pressure difference pushes the interface towards the low-pressure side.
  EXPECT_DOUBLE_EQ(star.velocity.x(), (100.0 - 300.0) / (2 * 2400 * c));
}

TEST(AcousticRiemannInterface, TangentialVelocityIsTheMean) {
  const InterfaceSide left{2400, 0, Vector(0, 2, 0)};
  const InterfaceSide right{2400, 0, Vector(0, -1, 3)};
  const auto star = AcousticRiemannInterface{}(left, right, towardsRight, c);
  EXPECT_DOUBLE_EQ(star.velocity.y(), 0.5);
  EXPECT_DOUBLE_EQ(star.velocity.z(), 1.5);
  EXPECT_DOUBLE_EQ(star.pressure, 0);
}

TEST(AcousticRiemannInterface, SwappingTheSidesGivesTheSameInterface) {
  const InterfaceSide a{2390, 120, Vector(0.4, 0.1, 0)};
  const InterfaceSide b{2410, -80, Vector(-0.3, 0.2, 0.5)};
  const auto ab = AcousticRiemannInterface{}(a, b, towardsRight, c);
  const auto ba = AcousticRiemannInterface{}(b, a, -towardsRight, c);
  EXPECT_DOUBLE_EQ(ab.pressure, ba.pressure);
  EXPECT_NEAR((ab.velocity - ba.velocity).norm(), 0, 1e-15);
}

// A wall pair's dissipation takes the compression it is given (the normal approach) in place of
// the pair line's: a fluid particle sliding along a wall at 2 m/s against its mirror (2 v_wall
// - v_i = -v_i) along an oblique pair line at 45 degrees compresses that line by 2 sqrt(2) m/s,
// and the limiter adds rho min(3 U, c) U / 2 to the pressure, a drag; given the normal
// approach, 0, it adds nothing, and given an approach U it adds rho min(3 U, c) U / 2.
TEST(AcousticRiemannInterface, AGivenCompressionReplacesThePairLines) {
  const Vector slide(2, 0, 0);
  const InterfaceSide fluid{2400, 1000, slide};
  const InterfaceSide mirror{2400, 1000, -slide};
  const Vector oblique = Vector(1, 0, -1).normalized();
  const Real alongLine = 2 * slide.dot(oblique);
  const auto fromLine = AcousticRiemannInterface{}(fluid, mirror, oblique, c);
  EXPECT_NEAR(fromLine.pressure, 1000 + 0.5 * 2400 * std::min(3 * alongLine, c) * alongLine,
              1e-9);
  const auto sliding =
      AcousticRiemannInterface{}.withCompression(fluid, mirror, oblique, 0, c);
  EXPECT_DOUBLE_EQ(sliding.pressure, 1000);
  const Real approach = 0.4;
  const auto approaching =
      AcousticRiemannInterface{}.withCompression(fluid, mirror, oblique, approach, c);
  EXPECT_NEAR(approaching.pressure, 1000 + 0.5 * 2400 * (3 * approach) * approach, 1e-9);
  // the velocity does not depend on it
  EXPECT_NEAR((sliding.velocity - fromLine.velocity).norm(), 0, 1e-15);
}

TEST(ArithmeticMeanInterface, IsStandardSph) {
  const InterfaceSide a{2390, 120, Vector(0.4, 0.1, 0)};
  const InterfaceSide b{2410, -80, Vector(-0.3, 0.2, 0.5)};
  const auto star = ArithmeticMeanInterface{}(a, b, towardsRight, c);
  EXPECT_DOUBLE_EQ(star.pressure, 20);
  EXPECT_NEAR((star.velocity - Vector(0.05, 0.15, 0.25)).norm(), 0, 1e-15);
}

TEST(LinearEquationOfState, IsPaperEquationThreeAndItsInverse) {
  const LinearEquationOfState eos{50};
  EXPECT_DOUBLE_EQ(eos.pressure(2410, 2400), 2500 * 10);
  EXPECT_DOUBLE_EQ(eos.density(eos.pressure(2391.5, 2400), 2400), 2391.5);
}

}  // namespace
}  // namespace sphcast
