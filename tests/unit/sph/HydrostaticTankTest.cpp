// A 2D water column in a tank (doc/validation.md §1.2: p = rho g (H - z), fluid stays at rest).
// Coarse CI version: 20 x 20 particles, t sqrt(g/H) = 20; the long run (>= 100) is a tutorial.
#include <gtest/gtest.h>

#include <cmath>

#include "FlowTestCases.h"
#include "particles/FieldNames.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

struct TankResult {
  double pressureError;   // RMS of p - rho0 g (H - y), over rho0 g H
  double pressureOffset;  // mean of p - rho0 g (H - y), over rho0 g H
  double largestSpeed;    // over sqrt(g H)
  double largestDrift;    // largest displacement, over dx
  std::size_t escaped;    // particles outside the tank
};

TankResult runTank(const std::string& scheme, double dimensionlessTime,
                   bool kernelCorrection = false, Real deltaSPHViscosity = 0,
                   bool dualCriteria = false, bool incompressible = false) {
  const int columns = 20;
  const int rows = 20;
  const Real dx = 0.002;
  const Real height = rows * dx;
  const Real width = columns * dx;
  const Real g = 9.81;
  const Real rho0 = 1000;
  const Real c = 10;  // ~16 sqrt(g H): density varies by 0.4 %
  auto fluid = testing::fluidBlock2D(columns, rows, dx, Vector::Zero(), rho0, 1e-3);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    // Start in hydrostatic balance: rho = rho0 (1 + g (H - y) / c^2).
    fluid.scalarField(field::rho)[i] =
        rho0 * (1 + g * (height - fluid.positions()[i].y()) / (c * c));
  }
  const auto start = fluid.positions();
  auto id = fluid.addIdField("id");
  for (std::size_t i = 0; i < id.size(); ++i) id[i] = static_cast<std::int64_t>(i);
  fluid.idField("id") = id;

  auto wall = testing::emptyWall();
  const int layers = 3;
  // The normal and depth of a wall cell: towards the fluid, distance behind the nearest face
  // (behind a corner, the distance to the corner).
  auto outside = [=](int column, int row) {
    const Real ox =
        column < 0 ? Real(column + 0.5) : (column >= columns ? Real(column - columns + 0.5) : 0);
    const Real oy = row < 0 ? Real(row + 0.5) : 0;
    return Vector(ox, oy, 0);
  };
  auto normal = [=](int column, int row) { return Vector(-outside(column, row)); };
  auto depth = [=](int column, int row) { return outside(column, row).norm() * dx; };
  testing::addWallCells(wall, -layers, columns + layers, -layers, 0, dx, Vector::Zero(), normal,
                        depth);
  testing::addWallCells(wall, -layers, 0, 0, rows + 10, dx, Vector::Zero(), normal, depth);
  testing::addWallCells(wall, columns, columns + layers, 0, rows + 10, dx, Vector::Zero(), normal,
                        depth);

  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = c;
  settings.gravity = Vector(0, -g, 0);
  settings.densityScheme = scheme;
  settings.kernelCorrection = kernelCorrection;
  settings.deltaSPHViscosity = deltaSPHViscosity;
  settings.dualCriteria = dualCriteria;
  settings.incompressible = incompressible;
  WeaklyCompressibleFlow flow(settings, fluid, {&wall});

  const double endTime = dimensionlessTime / std::sqrt(g / height);
  std::string limiter;
  for (double t = 0; t < endTime;) {
    const double dt = flow.stepLimits(0.25).smallest(limiter);
    flow.step(dt);
    t += dt;
  }

  TankResult result{};
  double squares = 0;
  double sum = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Vector& x = fluid.positions()[i];
    const double exact = rho0 * g * (height - x.y());
    squares += std::pow(fluid.scalarField(field::p)[i] - exact, 2);
    sum += fluid.scalarField(field::p)[i] - exact;
    result.largestSpeed = std::max(
        result.largestSpeed, double(fluid.vectorField(field::U)[i].norm()) / std::sqrt(g * height));
    const auto original = static_cast<std::size_t>(fluid.idField("id")[i]);
    result.largestDrift = std::max(result.largestDrift, double((x - start[original]).norm()) / dx);
    if (x.x() < 0 || x.x() > width || x.y() < 0) ++result.escaped;
  }
  result.pressureError = std::sqrt(squares / double(fluid.size())) / (rho0 * g * height);
  result.pressureOffset = sum / double(fluid.size()) / (rho0 * g * height);
  return result;
}

void print(const char* run, const TankResult& result) {
  std::printf(
      "hydrostatic tank 2D, 20x20, %s: pressure RMS error %.4f rho g H (mean %.4f), "
      "largest speed %.4f sqrt(gH), largest drift %.3f dx, %zu escaped\n",
      run, result.pressureError, result.pressureOffset, result.largestSpeed, result.largestDrift,
      result.escaped);
}

TEST(HydrostaticTank, RiemannSchemeKeepsTheColumnAtRestWithHydrostaticPressure) {
  const auto result = runTank("riemann", 20);
  print("t sqrt(g/H) = 20", result);
  // Measured at this coarse resolution: RMS pressure error 0.0052 rho g H, largest speed
  // 0.0085 sqrt(gH), largest drift 0.82 dx. Before the Riemann interface left out the
  // hydrostatic part of the pressure jump (RiemannSolver.h, restingJump) the same run gave
  // 0.047, 0.0076 and 2.0 dx; with the wall pressure mirrored per pair instead of Adami's
  // extrapolation 0.077, 0.062 and 18 dx: the bounds below separate all three.
  EXPECT_EQ(result.escaped, 0u);
  EXPECT_LT(result.pressureError, 0.01);
  EXPECT_LT(result.largestSpeed, 0.015);
  EXPECT_LT(result.largestDrift, 1.5);
}

// timeStepping dualCriteria (acousticCo 1): the column at rest takes advection steps of the body
// force's limit, 0.25 sqrt(dx / g), each of some 18 acoustic sub-steps with one search and one
// viscous pass. Measured: RMS pressure error 0.0052 rho g H, largest speed 0.0087 sqrt(gH),
// drift 0.81 dx (kickDriftKick at maxCo 0.25: 0.0052, 0.0085, 0.82 dx) in 2.7 s against 7.2 s
// (one thread): the same bounds.
TEST(HydrostaticTank, DualCriteriaStepsKeepTheColumnAtRest) {
  const auto result = runTank("riemann", 20, false, 0, true);
  print("t sqrt(g/H) = 20, dualCriteria", result);
  EXPECT_EQ(result.escaped, 0u);
  EXPECT_LT(result.pressureError, 0.01);
  EXPECT_LT(result.largestSpeed, 0.015);
  EXPECT_LT(result.largestDrift, 1.5);
}

// flow { model incompressible; }: the pressure solved for rho_s (IncompressiblePressure.h), in
// steps of the body force's limit (the column is at rest: no flow speed sets one). Measured:
// RMS pressure error 0.0110 rho g H, largest speed 0.0080 sqrt(gH), drift 0.37 dx, 2.0 s on one
// thread (kickDriftKick: 0.0052, 0.0085, 0.82 dx, 6 s). With the walls' pressure 0 in the
// pressure force (Akinci's) the wall columns carried twice rho g (H - y) (RMS 0.34); mirrored
// (p_b = p_i, also in a_ii) the column went unstable (speed 0.45); without the lattice's kernel
// sum 0.0125; a tolerance of 0.01 % instead of 0.1 %: 0.0138 in 5.4 s; 1 %: 0.0285, drift 1.8 dx.
// The bound on the pressure is 0.015, not the weakly compressible 0.01: the free surface's rows,
// whose summed densities are short, carry twice its error; it separates the variants above
// (0.34 and 0.45 in speed) from this one.
TEST(HydrostaticTank, IncompressibleSolveKeepsTheColumnAtRest) {
  const auto result = runTank("riemann", 20, false, 0, false, true);
  print("t sqrt(g/H) = 20, incompressible", result);
  EXPECT_EQ(result.escaped, 0u);
  EXPECT_LT(result.pressureError, 0.015);
  EXPECT_LT(result.largestSpeed, 0.015);
  EXPECT_LT(result.largestDrift, 1.5);
}

TEST(HydrostaticTank, KernelCorrectionKeepsTheColumnInTheTank) {
  const auto result = runTank("riemann", 20, true);
  print("t sqrt(g/H) = 20, kernelCorrection on", result);
  // Measured: RMS pressure error 0.0167 rho g H, largest speed 0.061 sqrt(gH), drift 5.2 dx,
  // each worse than without the correction (0.0052, 0.0085, 0.82). The fallback blends the
  // correction out at the free surface only; one or two spacings below it the corrected
  // pressure gradient of the symmetric pair form is not balanced by gravity as well as the
  // plain one, so the upper layers circulate slowly. Bounds: stable and in the tank, not good.
  EXPECT_EQ(result.escaped, 0u);
  EXPECT_LT(result.pressureError, 0.025);
  EXPECT_LT(result.largestSpeed, 0.08);
  EXPECT_LT(result.largestDrift, 7.0);
}

TEST(HydrostaticTank, DeltaSPHKeepsTheColumnAtRestWithHydrostaticPressure) {
  const auto result = runTank("deltaSPH", 20, false, Real(0.02));  // delta 0.1, alpha 0.02
  print("t sqrt(g/H) = 20, deltaSPH", result);
  // Measured: RMS pressure error 0.0056 rho g H (mean 0.0037), largest speed 0.0006 sqrt(gH),
  // drift 0.42 dx; at t sqrt(g/H) = 100: 0.0081, 0.0008, 0.46 dx. Before deltaSPH stepped by
  // Stormer-Verlet (WeaklyCompressibleFlow::stepStormerVerlet) the density oscillated with
  // growing amplitude from the free-surface corners and the run blew up by t sqrt(g/H) = 1.6.
  EXPECT_EQ(result.escaped, 0u);
  EXPECT_LT(result.pressureError, 0.01);
  EXPECT_LT(result.largestSpeed, 0.015);
  EXPECT_LT(result.largestDrift, 1.5);
}

// The criterion: a long run, t sqrt(g/H) = 100 (about a minute on one thread).
TEST(HydrostaticTank, StaysHydrostaticOverALongRun) {
  const auto result = runTank("riemann", 100);
  print("t sqrt(g/H) = 100", result);
  // Measured: RMS pressure error 0.0075 rho g H, nearly all of it a uniform offset (mean
  // 0.0074), largest speed 0.012 sqrt(gH), drift 0.96 dx. Before the Riemann interface left
  // out the hydrostatic jump the same run gave 0.39 rho g H and 9.0 dx; with kernelCorrection
  // on it gives 0.027 rho g H, 0.090 sqrt(gH) and 22.6 dx (no particle escapes either way).
  EXPECT_EQ(result.escaped, 0u);
  EXPECT_LT(result.pressureError, 0.015);
  EXPECT_LT(result.largestSpeed, 0.025);
  EXPECT_LT(result.largestDrift, 1.5);
}

}  // namespace
}  // namespace sphcast
