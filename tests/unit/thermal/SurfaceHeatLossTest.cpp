// The exposed area A_i (11) and the heat lost through it to the air (15) and by radiation
// (16), against geometry and the lumped ODEs (doc/validation.md §3): a body whose Biot number
// is far below 0.1 cools as a whole, rho c V dT/dt = -omega A (T - T_a) or
// -beta sigma A (T^4 - T_a^4), so its mean temperature checks the sum of A_i.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <numbers>
#include <random>

#include "ThermalTestCases.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "sph/ExposedArea.h"

namespace sphcast::testing {
namespace {

const char* const copper =  // a conductor: Bi = omega L / kappa ~ 1e-4 for a 10 mm cube
    "copper { density 8900; conductivity 400; specificHeat 385; emissivity 0.8; }";

// A cube of n^3 particles of side L = 10 mm (dx = L / n), h = 3 dx.
ThermalRun cube(int n, double T) {
  const Real dx = Real(0.01) / n;
  ThermalRun run(3, 3 * dx, dx, materials(copper));
  run.add(latticeBlock("copper", Vector(0, 0, 0), n, n, n, dx, 3, Real(T)), "copper");
  return run;
}

// A ball of radius R = 5 mm cut from the lattice, dx = 2 R / n.
ThermalRun ball(int n, double T) {
  const Real R = Real(0.005), dx = 2 * R / n;
  ThermalRun run(3, 3 * dx, dx, materials(copper));
  ParticleCloud cloud = latticeBlock("copper", Vector::Constant(-R), n, n, n, dx, 3, Real(T));
  keepWhere(cloud, [R](const Vector& x) { return x.norm() < R; });
  run.add(std::move(cloud), "copper");
  return run;
}

double totalArea(const ThermalRun& run) {
  double sum = 0;
  for (const Real area : run.clouds.front().scalarField(field::exposedArea)) sum += area;
  return sum;
}

double meanTemperature(const ParticleCloud& cloud) {
  double sum = 0;
  for (const Real T : cloud.scalarField(field::T)) sum += T;
  return sum / double(cloud.size());
}

// The sum of A_i over the body against its area, for the form heatTransfer's exposedArea names.
double areaError(int n, bool isBall, const std::string& form) {
  ThermalRun run = isBall ? ball(n, 400) : cube(n, 400);
  run.start("clouds (copper); exposedArea " + form +
            "; atmosphere { T 300; coefficients ((copper 10)); }");
  double area = 6 * 0.01 * 0.01;
  if (isBall) {
    // the ball's volume on the lattice differs from 4/3 pi R^3: the area of the sphere of the
    // same volume
    const double volume = double(run.clouds.front().size()) * std::pow(0.01 / n, 3);
    area = 4 * std::numbers::pi * std::pow(3 * volume / (4 * std::numbers::pi), 2.0 / 3.0);
  }
  return totalArea(run) / area - 1;
}

TEST(SurfaceHeatLossTest, ExposedAreaOfACubeAndABallConvergesToTheirArea) {
  // R_A is calibrated on a flat face; edges, corners and curvature are what these measure
  double previousCube = 1, previousBall = 1;
  for (const int n : {10, 20, 40}) {
    const double cubeError = areaError(n, false, "gradient");
    const double ballError = areaError(n, true, "gradient");
    RecordProperty("cube_" + std::to_string(n), std::to_string(cubeError));
    RecordProperty("ball_" + std::to_string(n), std::to_string(ballError));
    // eq. (11) of the paper, for the record (doc/physics.md §5.4)
    RecordProperty("cube_granularity_" + std::to_string(n),
                   std::to_string(areaError(n, false, "granularity")));
    RecordProperty("ball_granularity_" + std::to_string(n),
                   std::to_string(areaError(n, true, "granularity")));
    // A flat face counts its area exactly (the calibration); the gradient of s is smoothed
    // over h = 3 dx, which rounds the 12 edges: a deficit of about 2 d / L for a rounding d of
    // the edge, bounded here by d = 1.5 dx (half the support radius). The ball's lattice steps
    // are smoothed away too.
    EXPECT_LT(std::abs(cubeError), 3.0 / n) << "cube, " << n << " particles across";
    EXPECT_LT(std::abs(ballError), 2.0 / n) << "ball, " << n << " particles across";
    EXPECT_LT(std::abs(cubeError), previousCube);
    EXPECT_LT(std::abs(ballError), previousBall);
    previousCube = std::abs(cubeError);
    previousBall = std::abs(ballError);
  }
}

// Flowing metal is disordered: the cube with every particle moved by up to +-0.15 dx per
// coordinate (fixed seed). Without the interior gate (ExposedArea.h) every interior particle
// carried about 0.1 dx^2 of false area: -18.0 / +7.2 / +44.1 % at 10 / 20 / 40 across, 1.2 / 11 /
// 28 % of it deeper than h (measured with the gate taken out), growing with the volume.
TEST(SurfaceHeatLossTest, ExposedAreaOfADisorderedCubeStaysAtItsSurface) {
  for (const int n : {10, 20, 40}) {
    const Real dx = Real(0.01) / n;
    ThermalRun run(3, 3 * dx, dx, materials(copper));
    ParticleCloud cloud = latticeBlock("copper", Vector(0, 0, 0), n, n, n, dx, 3, Real(400));
    std::mt19937 random(12345);
    std::uniform_real_distribution<double> jitter(-0.15, 0.15);
    for (Vector& x : cloud.positions()) {
      for (int a = 0; a < 3; ++a) x[a] += Real(jitter(random)) * dx;
    }
    run.add(std::move(cloud), "copper");
    run.start("clouds (copper); atmosphere { T 300; coefficients ((copper 10)); }");
    const ParticleCloud& body = run.clouds.front();
    double total = 0, interior = 0;
    for (std::size_t i = 0; i < body.size(); ++i) {
      const Vector& x = body.positions()[i];
      const Real area = body.scalarField(field::exposedArea)[i];
      total += area;
      // deeper than h from every face: no area belongs there
      if ((x.array() > 3 * dx).all() && (x.array() < Real(0.01) - 3 * dx).all()) interior += area;
    }
    const double error = total / (6 * 0.01 * 0.01) - 1;
    RecordProperty("jittered_cube_" + std::to_string(n), std::to_string(error));
    std::printf("jittered cube, %d across: sum A_i %+.2f %% of 6 L^2, %.3f %% of it inside\n", n,
                100 * error, 100 * interior / total);
    // the lattice cube's bound (its edges rounded over h) with the disorder's own noise at the
    // surface; the interior's false area would have put it at +44 % at 40 across
    EXPECT_LT(std::abs(error), 3.0 / n) << n << " across";
    EXPECT_LT(interior / total, 0.005) << n << " across";
  }
}

// The gate's ramp starts above the flat lattice face's deepest layer with area, whose smoothed
// fullness an independent prototype put at 0.892 (h = 3 dx, 3D).
TEST(SurfaceHeatLossTest, InteriorGateLetsEveryLayerOfAFlatFaceThrough) {
  const Real dx = Real(1e-3);
  EXPECT_NEAR(ExposedArea::deepestAreaLayerFullness(3, 3 * dx, dx), 0.892, 0.001);
}

// A wall keeps the rows that nothing changed (ExposedArea.h): after a metal particle above it
// changed its volume, a corner of the metal moved, and the metal left, its areas are those a
// new ExposedArea computes on the same state, bit for bit, and the rows the metal reached did
// change.
TEST(SurfaceHeatLossTest, ExposedAreaOfAWallKeepsOnlyTheRowsNothingChanged) {
  const Real dx = Real(1e-3);
  ParticleCloud wall = latticeBlock("wall", Vector(0, 0, 0), 16, 16, 4, dx, 3, Real(400));
  ParticleCloud metal =
      latticeBlock("metal", Vector(4 * dx, 4 * dx, 4 * dx), 6, 6, 3, dx, 3, Real(900));
  auto& mass = metal.addScalarField(field::mass);
  auto& rho = metal.addScalarField(field::rho);
  std::fill(mass.begin(), mass.end(), Real(2.5e-6));
  std::fill(rho.begin(), rho.end(), Real(2500));
  const PeriodicBox open;
  Neighbourhood neighbourhood(3 * dx, open, Real(0.9) * dx);  // a skin: lists filtered, kept
  neighbourhood.addCloud(wall, Neighbourhood::Motion::fixed);
  // rigid: its lists are left alone where it did not move (a moving cloud's are filtered at
  // every update), so that a change of volume alone reaches the rows through their neighbours
  neighbourhood.addCloud(metal, Neighbourhood::Motion::rigid);
  auto areaOn = [&]() {
    return std::make_unique<ExposedArea>(ExposedAreaForm::gradient, 3, 3 * dx, dx,
                                         std::vector<ParticleCloud*>{&wall},
                                         std::vector<const ParticleCloud*>{&wall, &metal},
                                         neighbourhood, std::vector<const ParticleCloud*>{&wall});
  };
  const auto kept = areaOn();
  neighbourhood.update(CloudOrder::keep);
  kept->compute();
  std::vector<Real> before = wall.scalarField(field::exposedArea);
  // each change of the metal, then the kept object's areas against a new object's
  const std::vector<std::function<void()>> changes{
      [] {},  // nothing moved
      [&] {   // a particle's density changed, nothing moved: the lists stay as they are
        metal.scalarField(field::rho)[40] = Real(2450);
      },
      [&] {  // a corner of the metal shifted along x, within the skin: the lists filtered
        for (std::size_t i = 0; i < 10; ++i) metal.positions()[i][0] += Real(0.2) * dx;
      },
      [&] {  // the metal lifted out of the wall's reach
        for (Vector& x : metal.positions()) x[2] += 10 * dx;
      }};
  for (std::size_t k = 0; k < changes.size(); ++k) {
    changes[k]();
    neighbourhood.update(CloudOrder::keep);
    kept->compute();
    const std::vector<Real> keptArea = wall.scalarField(field::exposedArea);
    const std::vector<Real> keptGranularity = wall.scalarField(field::granularity);
    areaOn()->compute();
    const auto& fresh = wall.scalarField(field::exposedArea);
    const auto& freshGranularity = wall.scalarField(field::granularity);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < wall.size(); ++i) {
      ASSERT_EQ(keptArea[i], fresh[i]) << "change " << k << ", wall particle " << i;
      ASSERT_EQ(keptGranularity[i], freshGranularity[i]) << "change " << k << ", particle " << i;
      if (fresh[i] != before[i]) ++changed;
    }
    if (k == 0) {
      EXPECT_EQ(changed, 0u);
    } else {
      EXPECT_GT(changed, k == 1 ? 5u : 50u) << "change " << k << ": no area changed";
      EXPECT_LT(changed, wall.size() / 2) << "change " << k;
    }
    before = fresh;
  }
}

// A plate periodic in x and y (8 x 8 particles), `layers` thick in z: two flat faces of area
// 2 (8 dx)^2 per period, no edges. A made-up conductor (kappa 50 W/m/K) keeps the Biot number
// small with few steps (the diffusion limit is 0.1 dx^2 rho c / kappa).
constexpr int period = 8;
const char* const conductor =
    "conductor { density 8900; conductivity 50; specificHeat 385; emissivity 0.8; }"
    "other { density 8900; conductivity 50; specificHeat 385; }";

ThermalRun periodicPlates(Real dx) {
  ThermalRun run(3, 3 * dx, dx, materials(conductor));
  run.periodic.setPeriodic(0, 0, period * dx);
  run.periodic.setPeriodic(1, 0, period * dx);
  return run;
}

TEST(SurfaceHeatLossTest, LumpedPlateCoolsByNewtonsLaw) {
  const Real dx = Real(1.25e-3);
  const int layers = 8;  // L = 10 mm
  ThermalRun run = periodicPlates(dx);
  run.add(latticeBlock("conductor", Vector(0, 0, 0), period, period, layers, dx, 3, 400),
          "conductor");
  const double omega = 250;  // W/m^2/K; Bi = omega (L/2) / kappa = 0.025
  run.start(
      "clouds (conductor); conduction on; atmosphere { T 300; coefficients ((conductor 250)); }");
  const double L = layers * dx, rhoC = 8900.0 * 385.0;
  const double tau = rhoC * L / (2 * omega);  // two faces
  run.advanceTo(tau);
  const double exact = 300 + 100 * std::exp(-1.0);
  const double error = std::abs(meanTemperature(run.clouds.front()) - exact) / (exact - 300);
  RecordProperty("steps", std::to_string(run.steps));
  RecordProperty("error", std::to_string(error));
  // the lumped ODE itself is off by about Bi/3 = 0.8 % at this Biot number
  EXPECT_LT(error, 0.02) << "T " << meanTemperature(run.clouds.front()) << " K against " << exact;
  // the books: the heat that left equals the internal energy the plate lost
  const auto& attributes = run.clouds.front().attributes();
  const double lost = attributes.at("heatLost.atmosphere");
  const double change =
      run.internalEnergy(run.clouds.front()) - attributes.at("internalEnergyAtStart");
  EXPECT_NEAR(lost + change, 0, 1e-10 * lost);
}

TEST(SurfaceHeatLossTest, LumpedPlateCoolsByRadiation) {
  const Real dx = Real(1.25e-3);
  const int layers = 8;
  ThermalRun run = periodicPlates(dx);
  run.add(latticeBlock("conductor", Vector(0, 0, 0), period, period, layers, dx, 3, 1000),
          "conductor");
  run.start("clouds (conductor); conduction on; radiation { T 300; }");
  const double L = layers * dx, rhoCL = 8900.0 * 385.0 * L;
  const double beta = 0.8, sigma = 5.670374419e-8;
  // rho c L dT/dt = -2 beta sigma (T^4 - T_a^4), by RK4 with 10^4 steps
  auto rate = [&](double T) {
    return -2 * beta * sigma * (std::pow(T, 4) - std::pow(300.0, 4)) / rhoCL;
  };
  const double end = 60;
  double T = 1000;
  const int steps = 10000;
  const double dt = end / steps;
  for (int s = 0; s < steps; ++s) {
    const double k1 = rate(T), k2 = rate(T + 0.5 * dt * k1), k3 = rate(T + 0.5 * dt * k2),
                 k4 = rate(T + dt * k3);
    T += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  run.advanceTo(end);
  const double error = std::abs(meanTemperature(run.clouds.front()) - T) / (1000 - T);
  RecordProperty("error", std::to_string(error));
  ASSERT_LT(T, 930) << "the test must cool the plate to mean anything";
  EXPECT_LT(error, 0.02) << "T " << meanTemperature(run.clouds.front()) << " K against " << T;
}

// Two plates touching along a flat face, their materials joined by a contact coefficient: the
// difference of their mean temperatures decays as exp(-omega (2 / (rho c L)) t) per unit area
// (each plate lumped: Bi = omega L / kappa = 0.03 with L = 6 mm, which puts the lumped ODE
// about Bi/3 = 1 % off).
TEST(SurfaceHeatLossTest, MoldContactPassesOmegaATimesTheDifference) {
  const Real dx = Real(1e-3);
  const int layers = 6;
  ThermalRun run = periodicPlates(dx);
  run.add(latticeBlock("hot", Vector(0, 0, 0), period, period, layers, dx, 3, 500), "conductor");
  run.add(latticeBlock("cold", Vector(0, 0, -layers * dx), period, period, layers, dx, 3, 300),
          "other");
  const double omega = 250;
  run.start(
      "clouds (hot cold); conduction on; moldContact { coefficients ((conductor other 250)); }");
  const double rhoCL = 8900.0 * 385.0 * layers * dx;
  const double tau = rhoCL / (2 * omega);
  run.advanceTo(tau);
  const double difference = meanTemperature(run.clouds[0]) - meanTemperature(run.clouds[1]);
  const double exact = 200 * std::exp(-1.0);
  const double error = std::abs(difference - exact) / exact;
  RecordProperty("steps", std::to_string(run.steps));
  RecordProperty("error", std::to_string(error));
  EXPECT_LT(error, 0.02) << "difference " << difference << " K against " << exact;
}

}  // namespace
}  // namespace sphcast::testing
