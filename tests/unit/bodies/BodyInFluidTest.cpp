// A rigid body in the flow: a 2D block, twice as dense as the liquid, dropped onto a pool in a
// tank. The body's load is the exact negative of its pairs' terms on the fluid, so metal plus
// body change momentum by the external impulse alone (gravity and the tank's walls, whose load
// is measured the same way) in every step, to round-off; and the result does not depend on the
// thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>

#include "BodyTestCases.h"
#include "bodies/RigidBody.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "sph/FlowTestCases.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

const Real dx = 0.002;
const Vector gravity(0, -9.81, 0);

struct DropResult {
  double largestMomentumError = 0;  // per step, over |dt (M_f + M_b) g|
  double largestImpulse =
      0;  // the largest step impulse of the body's fluid load, over its weight's
  Vector centre = Vector::Zero();
  Vector bodyVelocity = Vector::Zero();
  std::size_t clearanceContacts = 0;
};

Vector fluidMomentum(const ParticleCloud& fluid) {
  Vector momentum = Vector::Zero();
  const auto& v = fluid.vectorField(field::U);
  const auto& m = fluid.scalarField(field::mass);
  for (std::size_t i = 0; i < fluid.size(); ++i) momentum += m[i] * v[i];
  return momentum;
}

DropResult dropBodyOntoPool(int steps) {
  const int columns = 30, rows = 12;
  auto fluid = testing::fluidBlock2D(columns, rows, dx, Vector::Zero(), 1000, 0.01);
  auto tank = testing::tankWalls2D(columns, rows + 14, dx);
  // 8 x 4 cells, its bottom 1.5 dx above the pool, off centre so that it also turns
  auto block = testing::boxBody(8, 4, 1, dx, Vector(9 * dx, (rows + 1.5) * dx, 0), true, "block");
  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = 20;
  settings.gravity = gravity;
  Neighbourhood neighbourhood(settings.supportRadius, settings.periodic);
  RigidBodySettings bodySettings;
  bodySettings.name = "block";
  bodySettings.cloud = "block";
  bodySettings.density = 2000;
  RigidBody body(bodySettings, block, gravity);
  WeaklyCompressibleFlow flow(settings, fluid, {&tank, &block}, neighbourhood);
  neighbourhood.addCloud(block, Neighbourhood::Motion::rigid);
  flow.measureLoadOn(tank);
  flow.measureLoadOn(block);
  neighbourhood.update();
  flow.start();
  body.setLoadsAndKick(flow.wallLoad(block).force, flow.wallLoad(block).torque, 0, 0);
  double fluidMass = 0;
  for (const Real m : fluid.scalarField(field::mass)) fluidMass += m;

  DropResult result;
  double time = 0;
  std::string limiter;
  for (int n = 0; n < steps; ++n) {
    const double dt = std::min(flow.stepLimits(0.25).smallest(limiter), body.stableDeltaT(dx));
    const Vector before = fluidMomentum(fluid) + body.mass() * body.velocity();
    const Vector tankBefore = flow.wallLoad(tank).force;
    const Vector bodyBefore = flow.wallLoad(block).force;
    time += dt;
    flow.kickAndDrift(dt);
    body.kickAndDrift(dt, time);
    neighbourhood.update();
    flow.keepClearOfWalls();
    const WallLoad& onBody = flow.wallLoad(block);
    body.takeImpulse(onBody.clearanceImpulse, onBody.clearanceAngularImpulse, dt, time);
    result.clearanceContacts += flow.lastWallClearance().corrected;
    const Vector tankClearance = flow.wallLoad(tank).clearanceImpulse;
    flow.computeRatesAndKick(dt);
    body.setLoadsAndKick(onBody.force, onBody.torque, dt, time);
    const Vector after = fluidMomentum(fluid) + body.mass() * body.velocity();
    // the external impulse: gravity on both, the tank's walls on the fluid
    const Vector external = dt * (fluidMass + body.mass()) * gravity -
                            0.5 * dt * (tankBefore + flow.wallLoad(tank).force) - tankClearance;
    const double scale = dt * (fluidMass + body.mass()) * gravity.norm();
    result.largestMomentumError =
        std::max(result.largestMomentumError, (after - before - external).norm() / scale);
    result.largestImpulse =
        std::max(result.largestImpulse,
                 (0.5 * dt * (bodyBefore + onBody.force) + onBody.clearanceImpulse).norm() /
                     (dt * body.mass() * gravity.norm()));
  }
  result.centre = body.centre();
  result.bodyVelocity = body.velocity();
  return result;
}

TEST(BodyInFluid, MetalPlusBodyMomentumChangesByTheExternalImpulseAlone) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  // 1,600 steps, 0.04 s: it falls 1.5 dx in 0.025 s and then ploughs into the pool
  const DropResult one = dropBodyOntoPool(1600);
  omp_set_num_threads(2);
  const DropResult two = dropBodyOntoPool(1600);
  omp_set_num_threads(threads);
  // the body hit the pool: the fluid's load on it exceeds its weight
  EXPECT_GT(one.largestImpulse, 1.0);
  std::printf("largest load over weight %.3f, momentum error %.3g, centre y %.6f\n",
              one.largestImpulse, one.largestMomentumError, static_cast<double>(one.centre.y()));
  EXPECT_LT(one.largestMomentumError, 1e-11);
  EXPECT_EQ(one.centre, two.centre);
  EXPECT_EQ(one.bodyVelocity, two.bodyVelocity);
}

}  // namespace
}  // namespace sphcast
