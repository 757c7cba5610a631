// A rigid body's motion without fluid: the kick-drift-kick of RigidBody against the exact
// motion under constant force, its constraints, end stop, release, prescribed motion, mass
// properties and its state's round trip through uniform/dynamicBodies.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "BodyTestCases.h"
#include "bodies/BodySetup.h"
#include "bodies/RigidBody.h"
#include "case/CaseDescription.h"
#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "particles/FieldNames.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

const Real dx = 0.001;

RigidBodySettings densityBody(double density = 7850) {
  RigidBodySettings settings;
  settings.name = "body";
  settings.cloud = "body";
  settings.density = density;
  return settings;
}

// n steps of dt with no fluid load (the first from time 0: the start's loads first, as the
// solver sets them)
void stepWithoutFluid(RigidBody& body, double dt, int steps, double& time) {
  if (time == 0) body.setLoadsAndKick(Vector::Zero(), Vector::Zero(), 0, 0);
  for (int n = 0; n < steps; ++n) {
    time += dt;
    body.kickAndDrift(dt, time);
    body.setLoadsAndKick(Vector::Zero(), Vector::Zero(), dt, time);
  }
}

TEST(RigidBody, MassPropertiesOfALatticeBoxAreTheBoxsExactly) {
  // every particle a cube of its volume: the sums are the box's mass, centre and inertia
  auto cloud = testing::boxBody(10, 6, 4, dx, Vector(0.01, -0.02, 0.003), false);
  RigidBody body(densityBody(), cloud, Vector::Zero());
  const double a = 10 * dx, b = 6 * dx, c = 4 * dx;
  const double mass = 7850 * a * b * c;
  EXPECT_NEAR(body.mass(), mass, 1e-12 * mass);
  EXPECT_LT((body.centre() - Vector(0.01 + a / 2, -0.02 + b / 2, 0.003 + c / 2)).norm(), 1e-15);
  // a torque about z alone spins it at tau t / I_zz, I_zz = m (a^2 + b^2) / 12
  double time = 0;
  const double dt = 1e-4;
  const Vector torque(0, 0, 1e-6);
  body.setLoadsAndKick(Vector::Zero(), torque, 0, 0);
  for (int n = 0; n < 10; ++n) {
    time += dt;
    body.kickAndDrift(dt, time);
    // a fluid torque about the origin: tau + c x F with F = 0
    body.setLoadsAndKick(Vector::Zero(), torque, dt, time);
  }
  const double inertia = mass * (a * a + b * b) / 12;
  EXPECT_NEAR(body.angularVelocity().z(), 1e-6 * time / inertia, 1e-9 * 1e-6 * time / inertia);
}

TEST(RigidBody, FreeBodyFallsAsHalfGTSquaredAndKeepsItsVelocity) {
  auto cloud = testing::boxBody(4, 4, 4, dx, Vector::Zero(), false);
  const Vector start = cloud.positions()[5];
  const Vector g(0, 0, -9.81);
  RigidBody body(densityBody(), cloud, g);
  double time = 0;
  const double dt = 1e-3;
  stepWithoutFluid(body, dt, 200, time);
  const Vector exact = Real(0.5) * g * time * time;
  EXPECT_LT((body.displacement() - exact).norm(), 1e-13);
  EXPECT_LT((body.velocity() - g * time).norm(), 1e-13);
  EXPECT_LT((cloud.positions()[5] - (start + exact)).norm(), 1e-13);
  EXPECT_LT((cloud.vectorField(field::U)[5] - g * time).norm(), 1e-13);
  EXPECT_LT((cloud.vectorField(field::acceleration)[5] - g).norm(), 1e-13);
  // a body moving at v with no force: x = v t (the state read back with a velocity)
  auto moving = testing::boxBody(4, 4, 4, dx, Vector::Zero(), false);
  RigidBody coasting(densityBody(), moving, Vector::Zero());
  const Dictionary state = Dictionary::parse(
      "body { centreOfMass (0.002 0.002 0.002); orientation (1 0 0 0); velocity (0.3 -0.2 0.1); "
      "angularMomentum (0 0 0); acceleration (0 0 0); torque (0 0 0); force (0 0 0); "
      "fluidForce (0 0 0); atEndStop no; }");
  coasting.readState(state.subDict("body"), 0);
  double t = 0;
  stepWithoutFluid(coasting, dt, 300, t);
  EXPECT_LT((coasting.displacement() - Vector(0.3, -0.2, 0.1) * t).norm(), 1e-14);
}

TEST(RigidBody, AxisConstraintKeepsTheBodyOnItsAxisAndLockedRotationStays) {
  auto cloud = testing::boxBody(4, 4, 4, dx, Vector::Zero(), false);
  RigidBodySettings settings = densityBody();
  settings.translation = RigidBodySettings::Translation::axis;
  settings.axis = Vector(1, 0, 1).normalized();
  settings.rotationLocked = true;
  const Vector g(3, -4, -9.81);
  RigidBody body(settings, cloud, g);
  double time = 0;
  const double dt = 1e-3;
  body.setLoadsAndKick(Vector(0, 0.1, 0), Vector(0.2, 0.1, -0.3), 0, 0);
  for (int n = 0; n < 100; ++n) {
    time += dt;
    body.kickAndDrift(dt, time);
    // an off-centre fluid force: a torque that a locked rotation ignores
    body.setLoadsAndKick(Vector(0, 0.1, 0), Vector(0.2, 0.1, -0.3), dt, time);
  }
  const Vector d = body.displacement();
  EXPECT_LT((d - d.dot(settings.axis) * settings.axis).norm(), 1e-16);
  const double along = (g + Vector(0, 0.1, 0) / body.mass()).dot(settings.axis);
  EXPECT_NEAR(d.dot(settings.axis), 0.5 * along * time * time, 1e-12);
  EXPECT_EQ(body.orientation().coeffs(), Quaternion::Identity().coeffs());
  EXPECT_EQ(body.angularVelocity(), Vector::Zero());
}

TEST(RigidBody, EndStopHoldsTheBodyAtTheStopWithoutRebound) {
  auto cloud = testing::boxBody(4, 4, 4, dx, Vector::Zero(), false);
  RigidBodySettings settings = densityBody();
  settings.translation = RigidBodySettings::Translation::axis;
  settings.endStop = Vector(0, 0, -0.01);
  RigidBody body(settings, cloud, Vector(0, 0, -9.81));
  double time = 0;
  stepWithoutFluid(body, 1e-3, 100, time);  // falls 0.049 m: past the stop after 45 ms
  EXPECT_TRUE(body.atEndStop());
  EXPECT_EQ(body.displacement().z(), -0.01);
  EXPECT_EQ(body.velocity().z(), 0);
  // pulled back up by a fluid force larger than its weight, it leaves the stop
  const Vector lift(0, 0, 2 * body.mass() * 9.81);
  for (int n = 0; n < 10; ++n) {
    time += 1e-3;
    body.kickAndDrift(1e-3, time);
    body.setLoadsAndKick(lift, Vector::Zero(), 1e-3, time);
  }
  EXPECT_FALSE(body.atEndStop());
  EXPECT_GT(body.displacement().z(), -0.01);
}

TEST(RigidBody, HeldUntilReleaseThenFalls) {
  auto cloud = testing::boxBody(3, 3, 3, dx, Vector::Zero(), false);
  RigidBodySettings settings = densityBody();
  settings.releaseTime = 0.0505;  // held in the steps that start before it
  const Vector g(0, 0, -9.81);
  RigidBody body(settings, cloud, g);
  double time = 0;
  stepWithoutFluid(body, 1e-3, 51, time);
  EXPECT_EQ(body.displacement(), Vector::Zero());
  EXPECT_EQ(body.velocity(), Vector::Zero());
  EXPECT_EQ(cloud.vectorField(field::U)[0], Vector::Zero());
  const double release = time;  // the first step to start after releaseTime
  stepWithoutFluid(body, 1e-3, 50, time);
  const double free = time - release;
  EXPECT_NEAR(body.displacement().z(), -0.5 * 9.81 * free * free, 1e-12);
}

TEST(RigidBody, PrescribedDisplacementIsFollowedAndItsSlopeIsTheVelocity) {
  auto cloud = testing::boxBody(3, 3, 3, dx, Vector::Zero(), false);
  RigidBodySettings settings = densityBody();
  settings.displacement = {
      {0.0, Vector::Zero()}, {0.1, Vector(0, 0, -0.01)}, {0.2, Vector(0, 0, -0.01)}};
  RigidBody body(settings, cloud, Vector(0, 0, -9.81));
  double time = 0;
  stepWithoutFluid(body, 0.004, 10, time);  // 0.04 s
  EXPECT_NEAR(body.displacement().z(), -0.004, 1e-15);
  EXPECT_NEAR(body.velocity().z(), -0.1, 1e-12);
  stepWithoutFluid(body, 0.004, 40, time);  // 0.2 s: at rest at the table's end
  EXPECT_NEAR(body.displacement().z(), -0.01, 1e-15);
  EXPECT_NEAR(body.velocity().z(), 0, 1e-12);
}

// A press's curve: a force ramped from 0 to 1 mN over 0.1 s and held, and the same as a pressure
// of 0 to 100 Pa on 10 mm^2: the kick-drift-kick integrates a force linear in time exactly in
// the velocity (v = -F1 (0.05 + (t - 0.1)) / m at t > 0.1 s, to round-off), and its travel to
// second order in dt (within 1e-3 of the exact cubic-then-parabolic path at dt = 1 ms); the two
// forms give the same motion, and a constant force adds to a pressure's.
TEST(RigidBody, APressCurveMovesTheBodyByItsImpulse) {
  const double force = 1e-3, ramp = 0.1, dt = 1e-3;
  RigidBodySettings byForce = densityBody();
  byForce.translation = RigidBodySettings::Translation::axis;
  byForce.appliedForce = {{0.0, Vector::Zero()}, {ramp, Vector(0, 0, -force)}};
  RigidBodySettings byPressure = densityBody();
  byPressure.translation = RigidBodySettings::Translation::axis;
  byPressure.appliedPressure = {{0.0, 0.0}, {ramp, 100.0}};
  byPressure.pressedArea = 1e-5;
  byPressure.pressDirection = Vector(0, 0, -1);
  auto first = testing::boxBody(4, 4, 4, dx, Vector::Zero(), false);
  auto second = testing::boxBody(4, 4, 4, dx, Vector::Zero(), false);
  RigidBody pressed(byForce, first, Vector::Zero());
  RigidBody pushed(byPressure, second, Vector::Zero());
  double t1 = 0, t2 = 0;
  stepWithoutFluid(pressed, dt, 250, t1);
  stepWithoutFluid(pushed, dt, 250, t2);
  const double m = pressed.mass(), t = t1;
  const double v = -force * (ramp / 2 + (t - ramp)) / m;
  const double x = -force * ramp * ramp / (6 * m) - force * ramp / (2 * m) * (t - ramp) -
                   force * (t - ramp) * (t - ramp) / (2 * m);
  EXPECT_NEAR(pressed.velocity().z(), v, 1e-9 * std::abs(v));
  EXPECT_NEAR(pressed.displacement().z(), x, 1e-3 * std::abs(x));
  EXPECT_NEAR(pushed.velocity().z(), pressed.velocity().z(), 1e-12 * std::abs(v));
  EXPECT_NEAR(pushed.displacement().z(), pressed.displacement().z(), 1e-12 * std::abs(x));
  RigidBodySettings both = byPressure;
  both.appliedForce = {{0.0, Vector(0, 0, -force)}};  // one point: a constant
  EXPECT_LT((both.appliedForceAt(0.05) - Vector(0, 0, -1.5 * force)).norm(), 1e-15);
  EXPECT_LT((both.appliedForceAt(7) - Vector(0, 0, -2 * force)).norm(), 1e-15);
  EXPECT_LT((byPressure.appliedForceAt(-1)).norm(), 1e-15);  // held at the table's ends
}

// constant/dynamicBodies' loads as a press specifies them, and their mistakes at their lines.
TEST(RigidBody, LoadCurvesAreReadAndTheirMistakesNamed) {
  const testing::TemporaryCase folder;
  auto read = [&](const std::string& body) {
    folder.write("constant/dynamicBodies", "punch\n{\n" + body + "}\n");
    return readBodySetup(CaseDescription(CaseFolder(folder.root())));
  };
  auto error = [&](const std::string& body) -> std::string {
    try {
      read(body);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  const BodySetup setup = read(
      "density 7850;\nappliedForce ((0 (0 0 0)) (0.1 (0 0 -500)));\n"
      "appliedPressure ((0 0) (0.2 1e7));\npressedArea 0.0195;\npressDirection (0 0 -2);\n");
  ASSERT_EQ(setup.bodies.size(), 1u);
  const RigidBodySettings& punch = setup.bodies[0];
  ASSERT_EQ(punch.appliedForce.size(), 2u);
  ASSERT_EQ(punch.appliedPressure.size(), 2u);
  EXPECT_DOUBLE_EQ(punch.pressedArea, 0.0195);
  EXPECT_LT((punch.pressDirection - Vector(0, 0, -1)).norm(), 1e-15);
  EXPECT_NEAR(punch.appliedForceAt(0.2).z(), -500 - 1e7 * 0.0195, 1e-6);
  EXPECT_EQ(read("density 7850;\nappliedPressure 2e6;\npressedArea 0.01;\n"
                 "pressDirection (0 0 -1);\n")
                .bodies[0]
                .appliedForceAt(3)
                .z(),
            Real(-2e4));
  const std::string noArea = error("density 7850;\nappliedPressure 1e6;\n");
  EXPECT_NE(noArea.find("dynamicBodies:4"), std::string::npos) << noArea;
  EXPECT_NE(noArea.find("pressedArea"), std::string::npos) << noArea;
  const std::string falling =
      error("density 7850;\nappliedForce ((0 (0 0 0)) (0.2 (0 0 -1)) (0.1 (0 0 -2)));\n");
  EXPECT_NE(falling.find("dynamicBodies:4"), std::string::npos) << falling;
  EXPECT_NE(falling.find("the times must rise"), std::string::npos) << falling;
  const std::string form = error("density 7850;\nappliedForce (0 0);\n");
  EXPECT_NE(form.find("((t0 (Fx Fy Fz))"), std::string::npos) << form;
  const std::string stray = error("density 7850;\npressedArea 0.01;\n");
  EXPECT_NE(stray.find("is for 'appliedPressure'"), std::string::npos) << stray;
  const std::string zeroArea =
      error("density 7850;\nappliedPressure 1e6;\npressedArea 0;\npressDirection (0 0 -1);\n");
  EXPECT_NE(zeroArea.find("positive area"), std::string::npos) << zeroArea;
}

TEST(RigidBody, TorqueFreeSpinConservesAngularMomentumAndTurnsTheParticles) {
  auto cloud = testing::boxBody(6, 6, 6, dx, Vector::Zero(), false);  // a cube: I isotropic
  const Vector corner = cloud.positions()[0];
  // a second foot (particleizeMold's, on a thin part) turns with the body as the first does
  cloud.addVectorField(field::secondNormal).assign(cloud.size(), Vector::UnitX());
  RigidBody body(densityBody(), cloud, Vector::Zero());
  const Vector centre = body.centre();
  const double omega = 20;  // rad/s about z
  const double inertia = body.mass() * 2 * std::pow(6 * dx, 2) / 12;
  std::ostringstream momentum;
  momentum.precision(17);
  momentum << "(0 0 " << omega * inertia << ")";
  const Dictionary state = Dictionary::parse(
      "body { centreOfMass (0.003 0.003 0.003); orientation (1 0 0 0); velocity (0 0 0); "
      "angularMomentum " +
      momentum.str() +
      "; acceleration (0 0 0); torque (0 0 0); "
      "force (0 0 0); fluidForce (0 0 0); atEndStop no; }");
  body.readState(state.subDict("body"), 0);
  double time = 0;
  const double dt = 1e-4;
  stepWithoutFluid(body, dt, 500, time);  // a quarter turn is 0.0785 s: 0.05 s is 57 degrees
  const double angle = std::atan2(2 * (body.orientation().w() * body.orientation().z()),
                                  1 - 2 * std::pow(body.orientation().z(), 2));
  EXPECT_NEAR(angle, std::fmod(omega * time, 2 * std::numbers::pi), 1e-6);
  const Vector arm = corner - centre;
  const Vector turned(std::cos(angle) * arm.x() - std::sin(angle) * arm.y(),
                      std::sin(angle) * arm.x() + std::cos(angle) * arm.y(), arm.z());
  EXPECT_LT((cloud.positions()[0] - (centre + turned)).norm(), 1e-12);
  EXPECT_NEAR(cloud.vectorField(field::normal)[0].norm(), 1, 1e-14);
  EXPECT_LT((cloud.vectorField(field::secondNormal)[0] -
             Vector(std::cos(angle), std::sin(angle), 0))
                .norm(),
            1e-6);
  // U of a particle: w x r
  EXPECT_LT((cloud.vectorField(field::U)[0] - Vector(0, 0, omega).cross(turned)).norm(), 1e-9);
}

TEST(RigidBody, StateReadBackContinuesBitForBit) {
  auto cloudA = testing::boxBody(4, 3, 2, dx, Vector::Zero(), false);
  auto cloudB = cloudA;
  const Vector g(0.5, 0, -9.81);
  RigidBody a(densityBody(), cloudA, g);
  double time = 0;
  for (int n = 0; n < 30; ++n) {
    time += 1e-3;
    a.kickAndDrift(1e-3, time);
    a.setLoadsAndKick(Vector(0.001, 0.002, 0), Vector(1e-6, 0, 2e-6), 1e-3, time);
  }
  RigidBody b(densityBody(), cloudB, g);
  const Dictionary state = Dictionary::parse(a.stateDictionary());
  b.readState(state.subDict("body"), time);
  double timeB = time;
  for (int n = 0; n < 30; ++n) {
    time += 1e-3;
    timeB += 1e-3;
    a.kickAndDrift(1e-3, time);
    a.setLoadsAndKick(Vector(0.001, 0.002, 0), Vector(1e-6, 0, 2e-6), 1e-3, time);
    b.kickAndDrift(1e-3, timeB);
    b.setLoadsAndKick(Vector(0.001, 0.002, 0), Vector(1e-6, 0, 2e-6), 1e-3, timeB);
  }
  EXPECT_EQ(a.centre(), b.centre());
  EXPECT_EQ(a.orientation().coeffs(), b.orientation().coeffs());
  EXPECT_EQ(cloudA.positions(), cloudB.positions());
}

}  // namespace
}  // namespace sphcast
