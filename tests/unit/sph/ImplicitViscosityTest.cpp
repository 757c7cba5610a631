// The viscous term solved implicitly (sph/ImplicitViscosity.h): start-up of plane Couette flow
// at mush-like viscosities against the series solution, at the acoustic step; momentum kept;
// the same bits on one and two threads.
//
// Couette start-up: fluid at rest between a floor at rest (y = 0) and a lid moving at U from
// t = 0 (y = L), no-slip on both:
//   u(y, t) = U y / L + sum_n 2 U (-1)^n / (n pi) sin(n pi y / L) exp(-n^2 pi^2 nu t / L^2).
#include <gtest/gtest.h>

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "FlowTestCases.h"
#include "particles/FieldNames.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

constexpr double gap = 0.01;       // L, m: a casting's thin section
constexpr double density = 2500;   // kg/m^3, a mush
constexpr double soundSpeed = 50;  // m/s, the paper's
constexpr double lidSpeed = 0.05;  // U, m/s: Mach 0.001
constexpr int columns = 8;         // periodic in x over 8 dx > 2 h

double couetteSeries(double y, double t, double nu) {
  constexpr double pi = std::numbers::pi;
  double u = lidSpeed * y / gap;
  for (int n = 1; n <= 400; ++n) {
    const double decay = std::exp(-n * n * pi * pi * nu * t / (gap * gap));
    if (decay < 1e-300) break;
    u += 2 * lidSpeed * (n % 2 == 0 ? 1 : -1) / (n * pi) * std::sin(n * pi * y / gap) * decay;
  }
  return u;
}

struct CouetteRun {
  double errorEarly = 0;  // max |u - u_exact| / U at the first check
  double errorLate = 0;   // ... at the second
  double tEarly = 0, tLate = 0;
  std::uint64_t steps = 0, implicitSteps = 0, iterations = 0;
  double largestStepOverExplicitLimit = 0;  // dt / (0.125 dx^2 / nu): > 1, the explicit is unstable
  double seconds = 0;
};

// The lid and floor as two wall clouds of three layers each; the lid's U is the lid speed.
CouetteRun runCouette(int rows, double viscosity, ViscositySolver solver,
                      bool dualCriteria = false) {
  const Real dx = static_cast<Real>(gap / rows);
  const double nu = viscosity / density;
  auto fluid =
      testing::fluidBlock2D(columns, rows, dx, Vector::Zero(), Real(density), Real(viscosity));
  auto floor = testing::emptyWall("floor");
  auto lid = testing::emptyWall("lid");
  testing::addWallCells(
      floor, 0, columns, -3, 0, dx, Vector::Zero(), [](int, int) { return Vector(0, 1, 0); },
      [dx](int, int row) { return (-row - Real(0.5)) * dx; });
  testing::addWallCells(
      lid, 0, columns, rows, rows + 3, dx, Vector::Zero(),
      [](int, int) { return Vector(0, -1, 0); },
      [dx, rows](int, int row) { return (row - rows + Real(0.5)) * dx; });
  auto& lidVelocity = lid.addVectorField(field::U);
  for (Vector& u : lidVelocity) u = Vector(Real(lidSpeed), 0, 0);

  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = Real(soundSpeed);
  settings.viscositySolver = solver;
  settings.periodic.setPeriodic(0, 0, columns * dx);
  settings.dualCriteria = dualCriteria;
  WeaklyCompressibleFlow flow(settings, fluid, {&floor, &lid});

  const double diffusionTime = gap * gap / nu;
  const double explicitLimit = 0.125 * double(dx) * double(dx) / nu;
  CouetteRun run;
  // at a tenth and at the whole of the diffusion time, or after 3 and 20 steps where those
  // come sooner (1e6 Pa s: the whole start-up lies within the first acoustic step)
  const double acousticStep = 0.25 * double(dx) / (soundSpeed + lidSpeed);
  run.tEarly = std::max(0.1 * diffusionTime, 3 * acousticStep);
  run.tLate = std::max(diffusionTime, 20 * acousticStep);
  auto largestError = [&](double t) {
    double worst = 0;
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      const double y = fluid.positions()[i].y();
      const double exact = couetteSeries(y, t, nu);
      worst = std::max(worst, std::abs(fluid.vectorField(field::U)[i].x() - exact) / lidSpeed);
    }
    return worst;
  };
  const auto start = std::chrono::steady_clock::now();
  double t = 0;
  std::string limiter;
  for (const double checkAt : {run.tEarly, run.tLate}) {
    while (t < checkAt * (1 - 1e-12)) {
      const double stable = flow.stepLimits(0.25).smallest(limiter);
      const double dt = std::min(stable, checkAt - t);
      run.largestStepOverExplicitLimit =
          std::max(run.largestStepOverExplicitLimit, dt / explicitLimit);
      flow.step(dt);
      t += dt;
      ++run.steps;
    }
    (checkAt == run.tEarly ? run.errorEarly : run.errorLate) = largestError(t);
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.implicitSteps = flow.work().implicitViscousSteps;
  run.iterations = flow.work().viscousIterations;
  return run;
}

// At 1e2, 1e4 and 1e6 Pa s (20 rows) the explicit viscous limit is 3, 320 and 3.2e4 times
// shorter than the acoustic step: with viscositySolver auto every step is acoustic and solved
// implicitly. Backward Euler is first order in time: its error is largest where the step is a
// sizeable part of the diffusion time. Measured at the defaults (tolerance 1e-6, relTol 1e-4;
// max |u - u_exact| / U early, late; CG iterations a step; 1 thread):
//   1e2 Pa s: 10 / 20 / 40 rows 0.0081 / 0.0036 / 0.0024, late 0.0000; 4 / 6 / 7 iterations
//   1e4 Pa s: 0.0021 / 0.0136 / 0.0196 (at 0.6 / 0.3 / 0.15 of L^2 / nu), late 0.0001; 10 / 18 / 26
//   1e6 Pa s: 0.0001 / 0.0001 / 0.0000 (the start-up lies within the first step); 10 / 18 / 29
// With relTol 1e-3 the 1e4 Pa s start-up is 0.043 off at 40 rows (16 iterations); with the
// tolerance alone (1e-6 of m v) 0.0026 (39 iterations).
// The iterations grow as the rows across (the Laplacian's condition number).
TEST(ImplicitViscosity, CouetteStartUpAtTheAcousticStepFollowsTheSeries) {
  for (const double viscosity : {1e2, 1e4, 1e6}) {
    for (const int rows : {10, 20, 40}) {
      const CouetteRun run = runCouette(rows, viscosity, ViscositySolver::automatic);
      std::printf(
          "Couette, mu %.0e Pa s, %2d rows: max |u - u_exact| / U %.4f at t = %.3g s, %.4f at "
          "%.3g s; %llu steps (dt up to %.0f explicit limits), %.1f CG iterations a step, "
          "%.3f s\n",
          viscosity, rows, run.errorEarly, run.tEarly, run.errorLate, run.tLate,
          static_cast<unsigned long long>(run.steps), run.largestStepOverExplicitLimit,
          double(run.iterations) / double(std::max<std::uint64_t>(run.implicitSteps, 1)),
          run.seconds);
      // every step but the shortened last ones before the checks
      EXPECT_GE(run.implicitSteps + 2, run.steps) << viscosity;
      EXPECT_GT(run.largestStepOverExplicitLimit, 1.0) << viscosity;
      EXPECT_LT(run.errorEarly, 0.02) << viscosity << ", " << rows << " rows";
      EXPECT_LT(run.errorLate, 0.02) << viscosity << ", " << rows << " rows";
    }
  }
}

// timeStepping dualCriteria: the viscosity solved implicitly in every acoustic sub-step, after
// its kick, as after kick-drift-kick's second kick. 20 rows, measured max |u - u_exact| / U
// early, late: 1e2 Pa s 0.0087, 0.0000 (kickDriftKick's 0.0036, 0.0000); 1e4 Pa s 0.0723,
// 0.0001 (0.0136, 0.0001): there the early check, 3 kick-drift-kick steps in, lies within the
// first sub-step (acousticCo 1 against maxCo 0.25), and backward Euler over it is first order.
// One solve over each whole advection step instead (2 or 3 steps here) gave 0.130, 0.018 and
// 0.131, 0.009.
TEST(ImplicitViscosity, CouetteStartUpInAdvectionStepsFollowsTheSeries) {
  for (const double viscosity : {1e2, 1e4}) {
    const CouetteRun run = runCouette(20, viscosity, ViscositySolver::automatic, true);
    std::printf(
        "Couette, dualCriteria, mu %.0e Pa s, 20 rows: max |u - u_exact| / U %.4f at t = %.3g "
        "s, %.4f at %.3g s; %llu steps, %llu sub-steps solved implicitly\n",
        viscosity, run.errorEarly, run.tEarly, run.errorLate, run.tLate,
        static_cast<unsigned long long>(run.steps),
        static_cast<unsigned long long>(run.implicitSteps));
    EXPECT_GT(run.implicitSteps, run.steps) << viscosity;
    EXPECT_LT(run.errorEarly, viscosity < 1e3 ? 0.02 : 0.1) << viscosity;
    EXPECT_LT(run.errorLate, 0.02) << viscosity;
  }
}

// The pair terms cancel: in a periodic box without walls the fluid's momentum is what it was,
// and its kinetic energy only falls.
TEST(ImplicitViscosity, KeepsMomentumAndDissipates) {
  const int side = 12;
  const Real dx = Real(1e-3);
  auto fluid = testing::fluidBlock2D(side, side, dx, Vector::Zero(), Real(density), Real(1e3));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> speed(-0.1, 0.1);
  for (Vector& u : fluid.vectorField(field::U))
    u = Vector(Real(speed(random)), Real(speed(random)), 0);
  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = Real(soundSpeed);
  settings.viscositySolver = ViscositySolver::implicitForm;
  settings.implicitViscosity.tolerance = Real(1e-10);
  settings.periodic.setPeriodic(0, 0, side * dx);
  settings.periodic.setPeriodic(1, 0, side * dx);
  WeaklyCompressibleFlow flow(settings, fluid, {});
  auto totals = [&] {
    Vector momentum = Vector::Zero();
    double energy = 0;
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      const Real m = fluid.scalarField(field::mass)[i];
      const Vector& u = fluid.vectorField(field::U)[i];
      momentum += m * u;
      energy += 0.5 * double(m) * double(u.squaredNorm());
    }
    return std::make_pair(momentum, energy);
  };
  const auto [momentum0, energy0] = totals();
  const double scale = double(fluid.scalarField(field::mass)[0]) * 0.1 * double(fluid.size());
  double energy = energy0;
  for (int step = 0; step < 5; ++step) {
    flow.step(1e-5);
    const auto [momentum, energyNow] = totals();
    EXPECT_LT(double((momentum - momentum0).norm()), 1e-9 * scale) << "step " << step;
    EXPECT_LT(energyNow, energy) << "step " << step;
    energy = energyNow;
  }
  EXPECT_LT(energy, 0.5 * energy0);  // 1e3 Pa s damps the noise within a few steps
}

TEST(ImplicitViscosity, SameBitsOnOneAndTwoThreads) {
  auto velocities = [](int threads) {
    omp_set_num_threads(threads);
    const Real dx = Real(gap / 20);
    auto fluid = testing::fluidBlock2D(columns, 20, dx, Vector::Zero(), Real(density), Real(1e4));
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      fluid.vectorField(field::U)[i] = Vector(Real(0.01) * std::sin(Real(i)), 0, 0);
    }
    auto floor = testing::emptyWall("floor");
    testing::addWallCells(
        floor, 0, columns, -3, 0, dx, Vector::Zero(), [](int, int) { return Vector(0, 1, 0); },
        [dx](int, int row) { return (-row - Real(0.5)) * dx; });
    FlowSettings settings;
    settings.dimension = 2;
    settings.supportRadius = 3 * dx;
    settings.soundSpeed = Real(soundSpeed);
    settings.gravity = Vector(0, Real(-9.81), 0);
    settings.viscositySolver = ViscositySolver::implicitForm;
    settings.periodic.setPeriodic(0, 0, columns * dx);
    WeaklyCompressibleFlow flow(settings, fluid, {&floor});
    for (int step = 0; step < 3; ++step) flow.step(1e-6);
    return fluid.vectorField(field::U);
  };
  const auto one = velocities(1);
  const auto two = velocities(2);
  omp_set_num_threads(1);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i][0], two[i][0]) << i;
    EXPECT_EQ(one[i][1], two[i][1]) << i;
  }
}

}  // namespace
}  // namespace sphcast
