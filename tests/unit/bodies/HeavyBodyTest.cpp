// A hard case at the default settings: a 2D block ten times as dense as the liquid dropped into a
// pool three spacings deep. It squeezes the pool out from under it and comes to rest on the
// floor (BodyWallContact.h keeps it out of the tank): its bottom surface never goes below the
// floor's, no liquid particle ends up inside the block or behind the tank's surfaces (the exact
// ones, not the particles) and the step never collapses. The splash's density is reported, not
// held (see the end).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "BodyTestCases.h"
#include "bodies/BodyWallContact.h"
#include "bodies/RigidBody.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "sph/FlowTestCases.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

TEST(HeavyBody, DroppedIntoAShallowPoolRestsOnTheFloorAndHoldsTheLiquidOut) {
  const Real dx = 0.002, g = 9.81;
  const int columns = 40, rows = 3, boxColumns = 10, boxRows = 4;
  auto fluid = testing::fluidBlock2D(columns, rows, dx, Vector::Zero(), 1000, 1e-3);
  auto tank = testing::tankWalls2D(columns, rows + 20, dx);
  const Real left = 15 * dx;
  auto box =
      testing::boxBody(boxColumns, boxRows, 1, dx, Vector(left, (rows + 2) * dx, 0), true, "box");
  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = 10;  // the block lands at 0.3 m/s, the squeezed liquid leaves faster
  settings.gravity = Vector(0, -g, 0);
  Neighbourhood neighbourhood(settings.supportRadius, settings.periodic);
  RigidBodySettings bodySettings;
  bodySettings.name = bodySettings.cloud = "box";
  bodySettings.density = 10000;
  RigidBody body(bodySettings, box, settings.gravity);
  WeaklyCompressibleFlow flow(settings, fluid, {&tank, &box}, neighbourhood);
  neighbourhood.addCloud(box, Neighbourhood::Motion::rigid);
  neighbourhood.requestPairs(box, tank);
  flow.measureLoadOn(box);
  neighbourhood.update();
  flow.start();
  body.setLoadsAndKick(flow.wallLoad(box).force, flow.wallLoad(box).torque, 0, 0);
  double time = 0, smallestStep = 1, largestStep = 0, densityDeviation = 0, deepestBox = 0;
  double deepestLiquid = -1e9;  // behind the floor, or inside the block, in dx
  long steps = 0, contacts = 0;
  std::string limiter;
  while (time < 0.3) {
    const double dt = std::min(flow.stepLimits(0.25).smallest(limiter), body.stableDeltaT(dx));
    smallestStep = std::min(smallestStep, dt);
    largestStep = std::max(largestStep, dt);
    time += dt;
    ++steps;
    flow.kickAndDrift(dt);
    body.kickAndDrift(dt, time);
    neighbourhood.update();
    const BodyContact contact = keepBodyOutOfMolds(
        body, wallSurfaceViews(box, {&tank}, neighbourhood), settings.periodic, dx);
    if (contact.depth > 0) ++contacts;
    flow.keepClearOfWalls();
    const WallLoad& load = flow.wallLoad(box);
    body.takeImpulse(load.clearanceImpulse, load.clearanceAngularImpulse, dt, time);
    flow.computeRatesAndKick(dt);
    body.setLoadsAndKick(load.force, load.torque, dt, time);
    // the block's exact surfaces: its particles' extent grown by half a spacing
    double lowest = 1e9, leftmost = 1e9, rightmost = -1e9, highest = -1e9;
    for (const Vector& x : box.positions()) {
      lowest = std::min(lowest, double(x.y()) - 0.5 * dx);
      highest = std::max(highest, double(x.y()) + 0.5 * dx);
      leftmost = std::min(leftmost, double(x.x()) - 0.5 * dx);
      rightmost = std::max(rightmost, double(x.x()) + 0.5 * dx);
    }
    deepestBox = std::max(deepestBox, -lowest / dx);
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      const Vector& x = fluid.positions()[i];
      double behind = std::max({-double(x.y()), -double(x.x()), double(x.x()) - columns * dx});
      const double inside = std::min({double(x.y()) - lowest, highest - double(x.y()),
                                      double(x.x()) - leftmost, rightmost - double(x.x())});
      behind = std::max(behind, inside);
      deepestLiquid = std::max(deepestLiquid, behind / dx);
      const double dev = std::abs(double(fluid.scalarField(field::rho)[i]) / 1000 - 1);
      densityDeviation = std::max(densityDeviation, dev);
    }
  }
  std::printf(
      "%ld steps (%ld with contact), step %.3g .. %.3g s, block %.3f dx below the floor, "
      "liquid %.3f dx behind a surface, density within %.2f %%, block at rest %.3g m/s\n",
      steps, contacts, smallestStep, largestStep, deepestBox, deepestLiquid, 100 * densityDeviation,
      double(body.velocity().norm()));
  EXPECT_GT(contacts, 0);         // it reached the floor
  EXPECT_LT(deepestBox, 0.05);    // and stayed on it
  EXPECT_LT(deepestLiquid, 0.0);  // no liquid inside anything
  // Not held: the density. The liquid squeezed out from under the block leaves as a sheet one
  // or two particles thick that expands as it thins; a particle that flies off it keeps the
  // density it had (measured: 31 % low), which the solver's health check (20 %) would stop the
  // run for. doc/validation.md §1.7 says more.
  EXPECT_GT(smallestStep, 1e-3 * largestStep);  // the step never collapsed
  EXPECT_LT(body.velocity().norm(), 0.05);      // at rest on the floor
}

}  // namespace
}  // namespace sphcast
