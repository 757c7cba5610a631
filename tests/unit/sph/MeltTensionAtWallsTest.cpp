// A melt in tension in a closed box stays at rest: a uniform pressure exerts no force (-grad p =
// 0), whatever its sign. The melt's tension has a floor (cavitationPressure); its wall pairs
// carry the tension its fluid pairs do (FlowRates.h, accumulateWallPair). Before they did, a
// particle in tension beside a wall was pulled off it by its own fluid pairs, and crossDitchPress
// at c = 50 m/s stirred at up to 1 m/s (doc/physics.md §10.4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "FlowTestCases.h"
#include "particles/FieldNames.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

struct TensionResult {
  double firstAcceleration;                // the largest |dv/dt| of the first step, m/s^2
  double largestSpeed;                     // m/s
  double largestDrift;                     // over dx
  double lowestPressure, highestPressure;  // Pa
};

// 2D: 20 x 10 melt particles in a closed box of three wall layers, no gravity, the density
// 0.1 % below rho_s (p = c^2 (rho - rho_s) = -6,000 Pa at c = 50, held at the floor), run for
// `duration` seconds at maxCo 0.25.
TensionResult runTensileBox(Real floor, double duration) {
  const int columns = 20, rows = 10, layers = 3;
  const Real dx = 0.003, restDensity = 2400, c = 50;
  auto fluid = testing::fluidBlock2D(columns, rows, dx, Vector::Zero(), restDensity, 1e-3);
  for (auto& rho : fluid.scalarField(field::rho)) rho = restDensity * Real(0.999);
  const auto start = fluid.positions();
  auto id = fluid.addIdField("id");  // the flow reorders the particles
  for (std::size_t i = 0; i < id.size(); ++i) id[i] = static_cast<std::int64_t>(i);
  fluid.idField("id") = id;

  // A wall cell's normal towards the melt and its depth behind the nearest face (behind a
  // corner, the distance to the corner).
  auto outside = [=](int column, int row) {
    const Real ox =
        column < 0 ? Real(column + 0.5) : (column >= columns ? Real(column - columns + 0.5) : 0);
    const Real oy = row < 0 ? Real(row + 0.5) : (row >= rows ? Real(row - rows + 0.5) : 0);
    return Vector(ox, oy, 0);
  };
  auto normal = [=](int column, int row) { return Vector(-outside(column, row)); };
  auto depth = [=](int column, int row) { return outside(column, row).norm() * dx; };
  auto wall = testing::emptyWall();
  testing::addWallCells(wall, -layers, columns + layers, -layers, 0, dx, Vector::Zero(), normal,
                        depth);
  testing::addWallCells(wall, -layers, columns + layers, rows, rows + layers, dx, Vector::Zero(),
                        normal, depth);
  testing::addWallCells(wall, -layers, 0, 0, rows, dx, Vector::Zero(), normal, depth);
  testing::addWallCells(wall, columns, columns + layers, 0, rows, dx, Vector::Zero(), normal,
                        depth);

  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = c;
  settings.gravity = Vector::Zero();
  settings.densityScheme = "riemann";
  settings.cavitationPressure = floor;
  WeaklyCompressibleFlow flow(settings, fluid, {&wall});

  std::string limiter;
  double firstAcceleration = 0;
  for (double t = 0; t < duration;) {
    const double dt = flow.stepLimits(0.25).smallest(limiter);
    flow.step(dt);
    if (t == 0) {
      for (const Vector& a : fluid.vectorField(field::acceleration)) {
        firstAcceleration = std::max(firstAcceleration, double(a.norm()));
      }
    }
    t += dt;
  }
  TensionResult result{firstAcceleration, 0, 0, 1e300, -1e300};
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    result.largestSpeed =
        std::max(result.largestSpeed, double(fluid.vectorField(field::U)[i].norm()));
    result.largestDrift = std::max(
        result.largestDrift,
        double((fluid.positions()[i] - start[static_cast<std::size_t>(fluid.idField("id")[i])])
                   .norm() /
               dx));
    result.lowestPressure = std::min(result.lowestPressure, double(fluid.scalarField(field::p)[i]));
    result.highestPressure =
        std::max(result.highestPressure, double(fluid.scalarField(field::p)[i]));
  }
  std::printf(
      "melt in tension in a closed box (floor %g Pa): first step's largest acceleration %.3g "
      "m/s^2; after %g s largest speed %.3g m/s, drift %.3g dx, p %.0f .. %.0f Pa\n",
      double(floor), result.firstAcceleration, duration, result.largestSpeed, result.largestDrift,
      result.lowestPressure, result.highestPressure);
  return result;
}

// The pull a wall used to leave: |p| / (rho dx), 694 m/s^2 at -5,000 Pa. The bounds are 1 %
// of it for the first step's acceleration, and ten times the speed and drift measured.
TEST(MeltTensionAtWalls, AMeltInTensionInAClosedBoxStaysAtRest) {
  // Measured: first step 0.615 m/s^2 (the box's corners); after 0.005 s (333 steps) 0.0033
  // m/s, drift 0.0024 dx, p -5,000 .. -4,936 Pa. With the wall pairs clamped to p >= 0
  // (before): 615 m/s^2, 0.244 m/s, 0.27 dx, p -5,000 .. +3,416 Pa (the walls' rows pulled
  // off them, the middle compressed).
  const auto result = runTensileBox(-5000, 0.005);
  EXPECT_LT(result.firstAcceleration, 6.9);
  EXPECT_LT(result.largestSpeed, 0.033);
  EXPECT_LT(result.largestDrift, 0.024);
  EXPECT_LT(result.highestPressure, 0);
}

TEST(MeltTensionAtWalls, ATensionAboveALowerFloorIsCarriedToo) {
  // The floor at -20,000 Pa (crossDitchPress at c = 50 stirred at 1.7 m/s there before,
  // doc/physics.md §10.4), the melt at -6,000 Pa, above it. Measured: 0.738 m/s^2, 0.0028
  // m/s, 0.0017 dx; before: 738 m/s^2, 0.495 m/s, 1.19 dx.
  const auto result = runTensileBox(-20000, 0.005);
  EXPECT_LT(result.firstAcceleration, 8.3);
  EXPECT_LT(result.largestSpeed, 0.028);
  EXPECT_LT(result.largestDrift, 0.017);
}

}  // namespace
}  // namespace sphcast
