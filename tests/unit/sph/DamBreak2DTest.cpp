// The 2D dam break against Martin & Moyce (1952): a water column of width a and height 2a
// collapses onto a dry floor; the surge front Z = x / a against T = t sqrt(2 g / a)
// (doc/validation.md §1.4; cited data in tests/unit/data/damBreak). The dimensionless time
// is the one of Martin & Moyce's Fig. 3 (and of the PySPH digitisation): with it the shallow
// water front speed 2 sqrt(g 2a) is dZ/dT = 2, and the measured slope between T = 2 and 4 is
// 1.7.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "FlowTestCases.h"
#include "particles/FieldNames.h"
#include "post/FluidSampling.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

struct MeasuredFront {
  std::vector<double> time;   // T
  std::vector<double> front;  // Z
};

MeasuredFront frontData(const std::string& name) {
  std::ifstream file(std::string(SPHCAST_TEST_DATA_DIR) + "/damBreak/" + name);
  MeasuredFront data;
  std::string line;
  while (std::getline(file, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream numbers(line);
    double T = 0;
    double Z = 0;
    numbers >> T >> Z;
    data.time.push_back(T);
    data.front.push_back(Z);
  }
  return data;
}
MeasuredFront martinMoyce() { return frontData("martinMoyce1952_n2_a2.25in.dat"); }
// the inviscid front converged: SPHinXsys at a/dx = 80, T <= 2.7 (the file says how)
MeasuredFront convergedInviscidFront() { return frontData("sphinxsysInviscidFront_a80.dat"); }

struct DamBreakResult {
  std::vector<double> time;   // the measured T up to the end of the run
  std::vector<double> front;  // the computed Z there
  std::vector<double> measured;
  double largestError = 0;  // max |Z - Z_measured|
  std::size_t escaped = 0;
  double particleSteps = 0;
  Vector centroid = Vector::Zero();       // of the water at the end
  std::size_t searches = 0, filters = 0;  // pair-list updates
  MeasuredFront everyStep;                // T and Z after every step
  std::uint64_t pressurePasses = 0;       // steps, or dualCriteria's acoustic sub-steps
  std::uint64_t flowSteps = 0;            // steps (incompressible: pressure solves)
  double largestCompression = 0;          // incompressible: the largest a solve left
};

struct Numerics {
  std::string densityScheme = "riemann";
  bool kernelCorrection = false;
  Real deltaSPHViscosity = 0;  // alpha of deltaSPH
  Real neighbourListSkin = FlowSettings().neighbourListSkin;
  bool normalApproach = false;  // wallDissipation normalApproach
  bool dualCriteria = false;    // timeStepping dualCriteria
  Real supportRatio = 3;        // the kernel's support radius in dx
  bool incompressible = false;  // flow { model incompressible; }
};

// Column a = 0.1 m resolved by `columns` particles across; tank 5a long. Runs to T = endT.
DamBreakResult runDamBreak(int columns, double endT, const Numerics& numerics = {}) {
  const Real a = 0.1;
  const Real dx = a / Real(columns);
  const int rows = 2 * columns;
  const int tankColumns = 5 * columns;
  const int wallRows = 3 * columns;
  const Real g = 9.81;
  const Real rho0 = 1000;
  // c = 10 sqrt(g 2a), as PySPH's dam breaks: ten times the shallow-water front speed scale.
  const Real c = 10 * std::sqrt(g * 2 * a);
  auto fluid = testing::fluidBlock2D(columns, rows, dx, Vector::Zero(), rho0, 1e-3);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Real depth = 2 * a - fluid.positions()[i].y();
    fluid.scalarField(field::rho)[i] = rho0 * (1 + g * depth / (c * c));  // hydrostatic start
  }

  auto wall = testing::tankWalls2D(tankColumns, wallRows, dx);

  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = numerics.supportRatio * dx;
  settings.soundSpeed = c;
  settings.gravity = Vector(0, -g, 0);
  settings.densityScheme = numerics.densityScheme;
  settings.kernelCorrection = numerics.kernelCorrection;
  settings.deltaSPHViscosity = numerics.deltaSPHViscosity;
  settings.neighbourListSkin = numerics.neighbourListSkin;
  settings.dualCriteria = numerics.dualCriteria;
  settings.incompressible = numerics.incompressible;
  settings.walls.all.dissipation = numerics.normalApproach
                                       ? WallCondition::Dissipation::normalApproach
                                       : WallCondition::Dissipation::relativeVelocity;
  WeaklyCompressibleFlow flow(settings, fluid, {&wall});

  const MeasuredFront measured = martinMoyce();
  const double timeScale = std::sqrt(a / (2 * g));  // t = T sqrt(a / 2g)
  DamBreakResult result;
  double t = 0;
  std::string limiter;
  auto escaped = [&] {
    std::size_t count = 0;
    for (const Vector& x : fluid.positions()) {
      if (x.x() < 0 || x.x() > 5 * a || x.y() < 0) ++count;
    }
    return count;
  };
  for (std::size_t k = 0; k < measured.time.size() && measured.time[k] <= endT; ++k) {
    const double sampleTime = measured.time[k] * timeScale;
    while (t < sampleTime) {
      const double dt = std::min(flow.stepLimits(0.25).smallest(limiter), sampleTime - t);
      flow.step(dt);
      t += dt;
      result.largestCompression =
          std::max(result.largestCompression, flow.lastPressureSolve().meanCompression);
      result.particleSteps += double(fluid.size());
      result.everyStep.time.push_back(t / timeScale);
      result.everyStep.front.push_back(fluidFront(fluid, Vector(1, 0, 0)) / a);
    }
    const double Z = fluidFront(fluid, Vector(1, 0, 0)) / a;
    result.time.push_back(measured.time[k]);
    result.front.push_back(Z);
    result.measured.push_back(measured.front[k]);
    result.largestError = std::max(result.largestError, std::abs(Z - measured.front[k]));
    result.escaped = escaped();
    if (result.escaped > 0) break;  // a blown-up run: its steps would shrink without end
  }
  for (const Vector& x : fluid.positions()) result.centroid += x / Real(fluid.size());
  // an incompressible step's pressure solve: two passes over the pairs per Jacobi iteration
  result.pressurePasses = numerics.dualCriteria     ? flow.work().acousticSubSteps
                          : numerics.incompressible ? 2 * flow.work().pressureIterations
                                                    : flow.work().flowSteps;
  result.flowSteps = flow.work().flowSteps;
  result.searches = flow.neighbourhood().rebuildCount();
  result.filters = flow.neighbourhood().reuseCount();
  return result;
}

// The computed front against the converged inviscid one at the reference's times up to the end
// of the run, relative: sqrt(mean(((Z - Z_ref) / Z_ref)^2)) and the largest.
struct FrontError {
  double rms = 0;
  double largest = 0;
  std::size_t points = 0;
};
FrontError againstConvergedFront(const DamBreakResult& result) {
  const MeasuredFront reference = convergedInviscidFront();
  const MeasuredFront& computed = result.everyStep;
  FrontError error;
  if (computed.time.size() < 2) return error;
  std::size_t step = 1;
  for (std::size_t k = 0; k < reference.time.size(); ++k) {
    const double T = reference.time[k];
    if (T < computed.time.front() || T > computed.time.back()) continue;
    while (computed.time[step] < T) ++step;
    const double t0 = computed.time[step - 1], t1 = computed.time[step];
    const double z0 = computed.front[step - 1], z1 = computed.front[step];
    const double Z = z0 + (T - t0) / (t1 - t0) * (z1 - z0);
    const double relative = (Z - reference.front[k]) / reference.front[k];
    error.rms += relative * relative;
    error.largest = std::max(error.largest, std::abs(relative));
    ++error.points;
  }
  error.rms = error.points > 0 ? std::sqrt(error.rms / double(error.points)) : 0;
  return error;
}

void print(int columns, const DamBreakResult& result, const Numerics& numerics = {}) {
  std::printf(
      "dam break 2D, a/dx = %d, densityScheme %s (alpha %g), kernelCorrection %s, "
      "wallDissipation %s, timeStepping %s, support %g dx%s:\n",
      columns, numerics.densityScheme.c_str(), double(numerics.deltaSPHViscosity),
      numerics.kernelCorrection ? "on" : "off",
      numerics.normalApproach ? "normalApproach" : "relativeVelocity",
      numerics.dualCriteria ? "dualCriteria" : "kickDriftKick", double(numerics.supportRatio),
      numerics.incompressible ? ", incompressible" : "");
  for (std::size_t k = 0; k < result.time.size(); ++k) {
    std::printf("    T %.3f  Z %.3f  measured %.3f\n", result.time[k], result.front[k],
                result.measured[k]);
  }
  std::printf("    largest |Z - Z_measured| %.3f, %.3g particle-steps, %zu escaped\n",
              result.largestError, result.particleSteps, result.escaped);
  const FrontError error = againstConvergedFront(result);
  std::printf("    against the converged inviscid front (T <= 2.7): RMS %.2f %%, largest %.2f %%\n",
              100 * error.rms, 100 * error.largest);
}

// The surge speed dZ/dT between T = 2.0 and 3.35 (samples 2 and 4), where the release of the
// column no longer matters, within 12 % of the measured 1.37.
void expectSurgeSpeedWithinTwelvePercent(const DamBreakResult& result) {
  const double measuredSpeed =
      (result.measured[4] - result.measured[2]) / (result.time[4] - result.time[2]);
  const double speed = (result.front[4] - result.front[2]) / (result.time[4] - result.time[2]);
  std::printf("    surge speed dZ/dT %.3f (measured %.3f)\n", speed, measuredSpeed);
  EXPECT_NEAR(speed / measuredSpeed, 1.0, 0.12);
}

TEST(DamBreak2D, SurgeFrontFollowsMartinMoyce) {
  const int columns = 20;
  const auto result = runDamBreak(columns, 3.4);
  print(columns, result);
  ASSERT_EQ(result.time.size(), 5u);  // T = 0.83 .. 3.35
  EXPECT_EQ(result.escaped, 0u);
  // Measured (a/dx = 10, 20, 40): largest |Z - Z_measured| 0.175, 0.184, 0.243. The computed
  // front runs ahead of the measured one early on (by 0.12 a at T = 0.83 here), as inviscid
  // computations of this experiment generally do: the usual explanation is the time the
  // experiment's release of the column took, which is not modelled. A front that does not move
  // misses by 3 a at T = 3.35, one at the ideal shallow-water speed dZ/dT = 2 by 3.5 a.
  // Against the converged inviscid front it is 5.8 % RMS behind: the wall pairs' dissipation
  // acts as a drag on the fluid sliding along the floor (NormalApproachWallsConvergeTheFront).
  EXPECT_LT(result.largestError, 0.25);
  // The surge speed between T = 2.0 and 3.35, where the release no longer matters: measured
  // dZ/dT = 1.37; computed 1.14, 1.28, 1.36 at a/dx = 10, 20, 40 before the Riemann interface
  // left out the hydrostatic jump, 1.27 at a/dx = 20 after.
  expectSurgeSpeedWithinTwelvePercent(result);
}

// wallDissipation normalApproach: the wall pairs dissipate only the fluid's approach to the
// wall (FlowRates.h, accumulateWallPair), so nothing holds back the fluid sliding along the
// floor but its viscosity (water's, negligible here), and the front converges to the inviscid
// one. Against SPHinXsys at a/dx = 80 (whose own a/dx = 20 front is 2.5 % RMS off it): measured
// RMS 0.62 %, largest 1.55 % (relativeVelocity: 5.8 % RMS behind). Against Martin & Moyce it
// runs further ahead (0.17 a at T = 0.83, 0.50 a at T = 3.35): the experiment's release and
// floor slow its front, which the physics bounds between the measured one and Ritter's ideal
// shallow-water front, Z = 1 + 2 T.
TEST(DamBreak2D, NormalApproachWallsConvergeTheFront) {
  const int columns = 20;
  Numerics numerics;
  numerics.normalApproach = true;
  const auto result = runDamBreak(columns, 3.4, numerics);
  print(columns, result, numerics);
  ASSERT_EQ(result.time.size(), 5u);
  EXPECT_EQ(result.escaped, 0u);
  const FrontError error = againstConvergedFront(result);
  ASSERT_GT(error.points, 200u);
  EXPECT_LT(error.rms, 0.015);
  EXPECT_LT(error.largest, 0.03);
  for (std::size_t k = 0; k < result.time.size(); ++k) {
    EXPECT_GE(result.front[k], result.measured[k]) << "T = " << result.time[k];
    EXPECT_LT(result.front[k], 1 + 2 * result.time[k]) << "T = " << result.time[k];
  }
  // dZ/dT between T = 2.0 and 3.35: 1.47 against the measured 1.37
  expectSurgeSpeedWithinTwelvePercent(result);
}

// timeStepping dualCriteria: advection steps of 0.2 dx / |v|max, each with one search and the
// viscous term, in Verlet sub-steps of the pressure and density at acousticCo 1
// (WeaklyCompressibleFlow::advectionStep), with the tutorial's support h = 2.6 dx. Measured at
// a/dx = 20 against the converged inviscid front: RMS 0.53 %, largest 1.50 % (with h = 3 dx
// 0.59 / 1.48 %), in 842 acoustic sub-steps against kickDriftKick's 2,980 steps at maxCo 0.25
// (0.28 times; its RMS 0.70 %, at 3 dx 0.62 %); 0.58 s (0.71 s at 3 dx), one thread.
TEST(DamBreak2D, DualCriteriaStepsConvergeTheFrontInFewerPasses) {
  const int columns = 20;
  Numerics kickDriftKick;
  kickDriftKick.normalApproach = true;
  kickDriftKick.supportRatio = Real(2.6);  // tutorials/validation/damBreak2D's
  Numerics dual = kickDriftKick;
  dual.dualCriteria = true;
  const auto reference = runDamBreak(columns, 3.4, kickDriftKick);
  const auto result = runDamBreak(columns, 3.4, dual);
  print(columns, result, dual);
  ASSERT_EQ(result.time.size(), 5u);
  EXPECT_EQ(result.escaped, 0u);
  const FrontError error = againstConvergedFront(result);
  const FrontError referenceError = againstConvergedFront(reference);
  std::printf("    %llu acoustic sub-steps against %llu kickDriftKick steps; RMS %.2f %% there\n",
              static_cast<unsigned long long>(result.pressurePasses),
              static_cast<unsigned long long>(reference.pressurePasses), 100 * referenceError.rms);
  ASSERT_GT(error.points, 150u);  // (the front is sampled once per advection step)
  EXPECT_LT(error.rms, 0.015);
  EXPECT_LT(error.largest, 0.03);
  EXPECT_LT(double(result.pressurePasses), 0.4 * double(reference.pressurePasses));
  for (std::size_t k = 0; k < result.time.size(); ++k) {
    EXPECT_GE(result.front[k], result.measured[k]) << "T = " << result.time[k];
    EXPECT_LT(result.front[k], 1 + 2 * result.time[k]) << "T = " << result.time[k];
  }
  expectSurgeSpeedWithinTwelvePercent(result);
}

// flow { model incompressible; }: steps of 0.4 dx / |v|max, each with one search and the
// pressure solved for rho_s (IncompressiblePressure.h), against the converged inviscid front.
// Measured at a/dx = 10 / 20 / 40: RMS 3.74 / 1.63 / 0.60 %, largest 6.33 / 2.88 / 1.15 %, in
// 97 / 186 / 413 steps (0.04 / 0.31 / 2.8 s on one thread; the weakly compressible
// kickDriftKick at 20: 0.62 % in 2,980 steps, 1.55 s). Halving or quartering the step leaves it
// (2.10 and 2.19 % at 20), a tolerance of 0.01 % too (1.89 %): the error is the resolution's, a
// free surface of summed densities. So the weakly compressible bounds are asked at 40, and the
// front must converge from 20.
TEST(DamBreak2D, IncompressibleSolveConvergesTheFront) {
  Numerics numerics;
  numerics.normalApproach = true;
  numerics.incompressible = true;
  FrontError previous;
  for (const int columns : {20, 40}) {
    const auto result = runDamBreak(columns, 3.4, numerics);
    print(columns, result, numerics);
    const FrontError error = againstConvergedFront(result);
    std::printf(
        "    %llu steps, %llu pair passes of the pressure; mean compression at most %.3g %%\n",
        static_cast<unsigned long long>(result.flowSteps),
        static_cast<unsigned long long>(result.pressurePasses), 100 * result.largestCompression);
    ASSERT_EQ(result.time.size(), 5u);
    EXPECT_EQ(result.escaped, 0u);
    EXPECT_LE(result.largestCompression, 1e-3);
    for (std::size_t k = 0; k < result.time.size(); ++k) {
      EXPECT_GE(result.front[k], result.measured[k]) << "T = " << result.time[k];
      EXPECT_LT(result.front[k], 1 + 2 * result.time[k]) << "T = " << result.time[k];
    }
    expectSurgeSpeedWithinTwelvePercent(result);
    if (columns == 40) {
      EXPECT_LT(error.rms, 0.015);
      EXPECT_LT(error.largest, 0.03);
      EXPECT_LT(error.rms, 0.6 * previous.rms);  // converging
    }
    previous = error;
  }
}

// Pair lists reused over steps (a skin of 0.1 h and 0.3 h) against a search at every step: the
// same pairs, so the same run up to the order of the sums. Measured to T = 2.0 (861 steps at
// a/dx = 10; 95 and 32 searches): the fronts agree to 1.3e-15 a, the centroids to 2.9e-16 a.
// With the rebuild test three times too lax (pairs missed now and then) the 0.3 h run is off by
// 4e-6 a.
TEST(DamBreak2D, ReusedPairListsChangeNothingBeyondRoundOff) {
  const int columns = 10;
  Numerics searchEveryStep;
  searchEveryStep.neighbourListSkin = 0;
  const auto reference = runDamBreak(columns, 2.0, searchEveryStep);
  for (const Real skin : {Real(0.1), Real(0.3)}) {
    Numerics reused;
    reused.neighbourListSkin = skin;
    const auto result = runDamBreak(columns, 2.0, reused);
    ASSERT_EQ(result.front.size(), reference.front.size());
    double frontDifference = 0;
    for (std::size_t k = 0; k < result.front.size(); ++k) {
      frontDifference = std::max(frontDifference, std::abs(result.front[k] - reference.front[k]));
    }
    const double centroidDifference = (result.centroid - reference.centroid).norm() / 0.1;
    std::printf(
        "skin %.1f h: %zu searches, %zu filters; fronts within %.3g a, centroids within "
        "%.3g a\n",
        double(skin), result.searches, result.filters, frontDifference, centroidDifference);
    EXPECT_GT(result.filters, 2 * result.searches);
    EXPECT_LT(frontDifference, 1e-9);
    EXPECT_LT(centroidDifference, 1e-9);
  }
}

TEST(DamBreak2D, DeltaSPHSurgeFrontFollowsMartinMoyce) {
  const int columns = 20;
  const Numerics deltaSPH{"deltaSPH", false, Real(0.02)};  // delta 0.1, alpha 0.02
  const auto result = runDamBreak(columns, 3.4, deltaSPH);
  print(columns, result, deltaSPH);
  ASSERT_EQ(result.time.size(), 5u);
  EXPECT_EQ(result.escaped, 0u);
  // Measured (a/dx = 10, 20, 40): largest |Z - Z_measured| 0.179, 0.222, 0.259 (riemann: 0.175,
  // 0.184, 0.243), ahead of the measured front early on as the riemann runs are. Before deltaSPH
  // stepped by Stormer-Verlet and kept the fluid's tension in wall pairs, this run lost
  // particles out of the tank by T = 0.83 (alpha 0.05: none lost, but 0.85 a ahead).
  EXPECT_LT(result.largestError, 0.25);
  // Surge speed between T = 2.0 and 3.35: computed dZ/dT 1.309, 1.324, 1.362 at a/dx = 10, 20,
  // 40 against the measured 1.37 (before: 1.67 with alpha 0.05).
  expectSurgeSpeedWithinTwelvePercent(result);
}

// The run to T = 3.4 at a/dx = 10, 20 and 40 with `numerics`, printed with its passes and time.
void printThreeResolutions(const Numerics& numerics) {
  for (const int columns : {10, 20, 40}) {
    const auto start = std::chrono::steady_clock::now();
    const auto result = runDamBreak(columns, 3.4, numerics);
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    print(columns, result, numerics);
    std::printf("    %llu pressure passes, %zu searches, %.2f s\n",
                static_cast<unsigned long long>(result.pressurePasses), result.searches,
                seconds.count());
  }
}

// Three resolutions, for the issue note (minutes on one thread): run with
// --gtest_also_run_disabled_tests --gtest_filter='*Resolutions*'.
TEST(DamBreak2D, DISABLED_SurgeFrontAtThreeResolutions) {
  // Measured, largest |Z - Z_measured| at a/dx = 10, 20, 40: riemann 0.175, 0.184, 0.243;
  // riemann with kernelCorrection 0.200, 0.181, 0.216; no particle past a wall face in any of
  // them (before walls only pushed, one particle sliding down the wall behind the column ended
  // 0.1-0.2 dx inside it at a/dx = 40, and at 20 with kernelCorrection). deltaSPH (delta 0.1)
  // with alpha = 0.02: 0.179, 0.222, 0.259, none out; with alpha 0.01 at a/dx = 20: 0.294, and
  // with alpha = 0 (the default of deltaSPHCoeffs) 0.541 (dZ/dT 1.50): stable, but the thin
  // front tip runs ahead without the artificial viscosity.
  Numerics normalApproach;
  normalApproach.normalApproach = true;
  Numerics deltaSPHNormalApproach{"deltaSPH", false, Real(0.02)};
  deltaSPHNormalApproach.normalApproach = true;
  Numerics dualCriteria = normalApproach;
  dualCriteria.dualCriteria = true;
  Numerics incompressible = normalApproach;
  incompressible.incompressible = true;
  for (const Numerics& numerics : {Numerics{"riemann", false, 0}, Numerics{"riemann", true, 0},
                                   Numerics{"deltaSPH", false, Real(0.02)}, normalApproach,
                                   deltaSPHNormalApproach, dualCriteria, incompressible}) {
    printThreeResolutions(numerics);
  }
}

// The incompressible solve at three resolutions (seconds): run with
// --gtest_also_run_disabled_tests --gtest_filter='*IncompressibleAtThreeResolutions*'.
TEST(DamBreak2D, DISABLED_IncompressibleAtThreeResolutions) {
  Numerics incompressible;
  incompressible.normalApproach = true;
  incompressible.incompressible = true;
  printThreeResolutions(incompressible);
}

// The kernel's support against cost with dualCriteria steps (SPHinXsys's support is 2.6 dx), for
// the benchmarks: run with --gtest_also_run_disabled_tests --gtest_filter='*SupportRadius*'.
// Measured (one thread, 2026-12-07), RMS from the a/dx 80 front at a/dx 10 / 20 / 40:
// 3 dx: 2.30 / 0.59 / 0.81 % in 0.10 / 0.71 / 5.68 s;
// 2.6 dx: 2.18 / 0.53 / 0.75 % in 0.08 / 0.58 / 4.56 s.
TEST(DamBreak2D, DISABLED_SupportRadiusAgainstCost) {
  for (const Real ratio : {Real(3), Real(2.6)}) {
    Numerics dualCriteria;
    dualCriteria.normalApproach = true;
    dualCriteria.dualCriteria = true;
    dualCriteria.supportRatio = ratio;
    printThreeResolutions(dualCriteria);
  }
}

}  // namespace
}  // namespace sphcast
