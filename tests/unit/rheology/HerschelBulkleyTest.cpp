// The Herschel-Bulkley rheology (rheology/HerschelBulkley.h) in steady plane Poiseuille flow
// between no-slip walls, driven by a body force F (pressure gradient G = rho F), against the
// exact profile (Bird, Armstrong & Hassager 1987, Dynamics of Polymeric Liquids vol. 1, §4.2):
// with s the distance from the channel's middle, H its half-width and s0 = tau0 / G the plug's
// half-width,
//   u(s) = n/(n+1) (G/k)^(1/n) [(H - s0)^(1+1/n) - (s - s0)^(1+1/n)]  for s > s0,
//   u(s) = u(s0)                                                    in the plug.
// A power law (tau0 = 0, n = 1/2) and a Bingham plastic (n = 1, s0 = 0.4 H), each at 10, 20 and
// 40 rows across; the viscosity spans three decades (mu0 = 1e3 times the wall's), solved
// implicitly at the acoustic step. Also the law itself and the dictionary's errors.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <omp.h>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "materials/Material.h"
#include "particles/FieldNames.h"
#include "rheology/ElastoViscoplastic.h"
#include "rheology/HerschelBulkley.h"
#include "rheology/RheologyModel.h"
#include "sph/FlowTestCases.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

constexpr double channelWidth = 1e-3, halfWidth = channelWidth / 2;
constexpr double density = 1000, bodyForce = 2e-4;
constexpr double pressureGradient = density * bodyForce;  // G, Pa/m: the wall stress is G H

double exactVelocity(const HerschelBulkleySettings& law, double s) {
  const double plug = law.yieldStress / pressureGradient;
  const double power = 1 + 1 / law.exponent;
  const double scale = law.exponent / (law.exponent + 1) *
                       std::pow(pressureGradient / law.consistency, 1 / law.exponent);
  return scale * (std::pow(halfWidth - plug, power) - std::pow(std::max(s - plug, 0.0), power));
}

struct ChannelRun {
  double error;  // largest |u - u_exact| / u_max over the particles at the end
  double drift;  // change of the mean u over the last tenth of the run, / u_max
  double flux;   // the mean u over the exact profile's at the particles (signed: > 1 too fast)
  double cpuSeconds;
};

// velocities: when given, the fluid's velocities at the end (in the fluid's order); elastic:
// when given, the law is solved as that elasto-viscoplastic stress (rheology/ElastoViscoplastic.h)
// instead of the regularised viscosity, law giving the exact profile.
ChannelRun runChannel(const HerschelBulkleySettings& law, int rows, double endTime,
                      std::vector<Vector>* velocities = nullptr,
                      const ElastoViscoplasticSettings* elastic = nullptr) {
  const Real dx = Real(channelWidth / rows);
  const int columns = 8;  // periodic in x over 8 dx > 2 h
  const double peak = exactVelocity(law, 0);
  auto fluid =
      testing::fluidBlock2D(columns, rows, dx, Vector::Zero(), Real(density), law.restViscosity);
  auto wall = testing::emptyWall();
  testing::addWallCells(
      wall, 0, columns, -3, 0, dx, Vector::Zero(), [](int, int) { return Vector(0, 1, 0); },
      [dx](int, int row) { return (-row - Real(0.5)) * dx; });
  testing::addWallCells(
      wall, 0, columns, rows, rows + 3, dx, Vector::Zero(),
      [](int, int) { return Vector(0, -1, 0); },
      [dx, rows](int, int row) { return (row - rows + Real(0.5)) * dx; });
  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = Real(100 * peak);  // Mach 0.01
  settings.gravity = Vector(Real(bodyForce), 0, 0);
  settings.viscositySolver = ViscositySolver::automatic;
  settings.periodic.setPeriodic(0, 0, columns * dx);
  WeaklyCompressibleFlow flow(settings, fluid, {&wall});
  const Material noTables;
  const RheologyContext context{
      fluid, noTables, flow.neighbourhood(), shearWalls(flow), 2, settings.supportRadius};
  std::unique_ptr<RheologyModel> model;
  if (elastic) {
    model = std::make_unique<ElastoViscoplastic>(context, *elastic);
    flow.addForceModel(*model->force());
  } else {
    model = std::make_unique<HerschelBulkley>(context, law);
  }
  RheologyModel& rheology = *model;

  const auto& u = fluid.vectorField(field::U);
  // the mean velocity (the particles are reordered along the grid every step)
  auto meanVelocity = [&] {
    double sum = 0;
    for (const Vector& v : u) sum += v.x();
    return sum / static_cast<double>(u.size());
  };
  double before = -1;
  const auto start = std::chrono::steady_clock::now();
  double t = 0;
  std::string limiter;
  for (const double until : {0.9 * endTime, endTime}) {
    while (t < until - 1e-12) {
      const double dt = std::min(flow.stepLimits(0.25).smallest(limiter), until - t);
      rheology.update(dt);
      flow.step(dt);
      t += dt;
    }
    if (before < 0) before = meanVelocity();
  }
  ChannelRun run{0, 0, 0,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
  double exactSum = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const double s = std::abs(fluid.positions()[i].y() - halfWidth);
    run.error = std::max(run.error, std::abs(u[i].x() - exactVelocity(law, s)) / peak);
    exactSum += exactVelocity(law, s);
  }
  run.flux = meanVelocity() * static_cast<double>(fluid.size()) / exactSum;
  run.drift = std::abs(meanVelocity() - before) / peak;
  if (velocities) *velocities = u;
  return run;
}

// Within 5 % of u_max at 20 and 40 rows across, 10 % at 10 rows (the Bingham plug is then 8 dx
// wide, its edges a kernel support from the walls' sheared layers), the 40 rows' error below the
// 10 rows'.
// Measured (max |u - u_exact| / u_max): power law 0.036 / 0.0088 / 0.016, Bingham 0.055 / 0.046
// / 0.036 (before the shear rate took the walls' no-slip: 0.131 / 0.030 / 0.0085 and 0.207 /
// 0.034 / 0.030). The power law's rise from 20 to 40 rows is the whole channel moving 1.6 % too
// fast while its wall shear rate is within 1.6 %; not yet traced: probably the flow's viscous
// wall term, which reads the shear as (v_i - v_wall) / d_i and so misses the profile's
// curvature (first order in dx), with the shear rate's own opposite error hiding it at 20 rows.
// The Bingham error is the kernel's smoothing of the shear rate across the yield surface, which
// yields a layer about 4 dx into the plug.
void expectProfiles(const char* name, const HerschelBulkleySettings& law, double endTime) {
  std::vector<ChannelRun> runs;
  for (const int rows : {10, 20, 40}) {
    runs.push_back(runChannel(law, rows, endTime));
    std::printf(
        "%s, %2d rows: max |u - u_exact| / u_max %.4f, flux over the exact %.4f (mean u still "
        "moving %.1e), %.2f s CPU\n",
        name, rows, runs.back().error, runs.back().flux, runs.back().drift, runs.back().cpuSeconds);
  }
  EXPECT_LT(runs[0].error, 0.10) << name << " at 10 rows";
  EXPECT_LT(runs[1].error, 0.05) << name << " at 20 rows";
  EXPECT_LT(runs[2].error, 0.05) << name << " at 40 rows";
  EXPECT_LT(runs[2].error, runs[0].error) << name << ": no convergence";
  for (const ChannelRun& run : runs) EXPECT_LT(run.drift, 5e-3) << name << ": not steady";
}

HerschelBulkleySettings binghamPlastic() {
  HerschelBulkleySettings bingham;
  bingham.yieldStress = Real(0.4 * pressureGradient * halfWidth);  // s0 = 0.4 H
  bingham.consistency = Real(1e-3);
  bingham.exponent = 1;
  bingham.restViscosity = 1;  // 1e3 times the plastic viscosity
  return bingham;
}

TEST(HerschelBulkley, PowerLawChannelFollowsTheExactProfile) {
  HerschelBulkleySettings powerLaw;
  powerLaw.consistency = Real(2.5e-4);  // u_max 2.7e-5 m/s, wall shear rate 0.16 1/s
  powerLaw.exponent = Real(0.5);
  powerLaw.restViscosity = 1;  // 1.5e3 times the wall's 6.3e-4 Pa s
  expectProfiles("power law n = 0.5", powerLaw, 5.0);
}

TEST(HerschelBulkley, BinghamChannelCarriesAPlug) {
  expectProfiles("Bingham s0 = 0.4 H", binghamPlastic(), 2.0);
}

// The same Bingham plastic as an elastic solid below tau0 (Saramito's law): its plug is rigid,
// not a creeping regularised fluid, and the steady profile is the same exact one; k is shared
// between the plastic consistency (90 %) and etaS (10 %, which damps the plug's elastic
// waves), G = 1000 tau0 (the plug strained 0.1 %, the stress's relaxation time k / G 25 ms).
TEST(HerschelBulkley, ElastoViscoplasticBinghamChannelCarriesARigidPlug) {
  const HerschelBulkleySettings law = binghamPlastic();
  ElastoViscoplasticSettings elastic;
  elastic.yieldStress = law.yieldStress;
  elastic.consistency = Real(0.9) * law.consistency;
  elastic.solventViscosity = Real(0.1) * law.consistency;
  elastic.shearModulus = 1000 * law.yieldStress;
  std::vector<ChannelRun> runs;
  for (const int rows : {10, 20, 40}) {
    runs.push_back(runChannel(law, rows, 2.0, nullptr, &elastic));
    std::printf(
        "elasto-viscoplastic Bingham, %2d rows: max |u - u_exact| / u_max %.4f, flux over the "
        "exact %.4f (mean u still moving %.1e), %.2f s CPU\n",
        rows, runs.back().error, runs.back().flux, runs.back().drift, runs.back().cpuSeconds);
  }
  // Measured 0.227 / 0.058 / 0.016 (the regularised viscosity's 0.055 / 0.046 / 0.036): second
  // order from 20 rows on. At 10 rows the sheared layers are one spacing thick, and a wall
  // particle carries the fluid particle's own stress (zero gradient, first order), where the
  // viscous term extrapolates the velocity.
  EXPECT_LT(runs[0].error, 0.30);
  EXPECT_LT(runs[1].error, 0.08);
  EXPECT_LT(runs[2].error, 0.03);
  EXPECT_LT(runs[2].error, 0.5 * runs[1].error) << "not converging";
  for (const ChannelRun& run : runs) EXPECT_LT(run.drift, 5e-3) << "not steady";
}

// The shear rates and the viscosity (per particle, no sums across threads): the same bits on
// one and two threads, through the implicit solve.
TEST(HerschelBulkley, SameBitsOnOneAndTwoThreads) {
  std::vector<Vector> one, two;
  omp_set_num_threads(1);
  runChannel(binghamPlastic(), 20, 0.2, &one);
  omp_set_num_threads(2);
  runChannel(binghamPlastic(), 20, 0.2, &two);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << "particle " << i;
}

TEST(HerschelBulkley, TheLawBetweenItsLimits) {
  HerschelBulkleySettings law;
  law.yieldStress = 10;
  law.consistency = 2;
  law.exponent = Real(0.5);
  law.restViscosity = 1e4;
  ParticleCloud fluid = testing::fluidBlock2D(1, 1, 1, Vector::Zero(), 1000, 1);
  Neighbourhood neighbourhood(3, PeriodicBox());
  const Material noTables;
  const HerschelBulkley model(RheologyContext{fluid, noTables, neighbourhood, {}, 2, 3}, law);
  EXPECT_EQ(model.viscosity(0), 1e4);     // at rest: mu0
  EXPECT_EQ(model.viscosity(1e-4), 1e4);  // below tau0 / mu0 = 1e-3 1/s: the cap
  EXPECT_NEAR(model.viscosity(100), (10 + 2 * 10) / 100.0, 1e-6);
}

TEST(HerschelBulkley, ItsDictionaryIsChecked) {
  ParticleCloud fluid = testing::fluidBlock2D(1, 1, 1, Vector::Zero(), 1000, 1);
  Neighbourhood neighbourhood(3, PeriodicBox());
  const Material noTables;
  const RheologyContext context{fluid, noTables, neighbourhood, {}, 2, 3};
  auto build = [&](const std::string& text) {
    return rheologyModels().build("herschelBulkley", context,
                                  Dictionary::parse(text, "constant/physicsModels"));
  };
  const auto model = build(
      "model herschelBulkley; herschelBulkleyCoeffs { tau0 5; k 0.1; n 0.4; "
      "mu0 1e3; }");
  EXPECT_NE(model->description().find("tau0 = 5 Pa"), std::string::npos);
  auto expectError = [&](const std::string& text, const std::string& message) {
    try {
      build(text);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find("physicsModels:1"), std::string::npos)
          << error.what();
    }
  };
  expectError("model herschelBulkley;", "needs herschelBulkleyCoeffs");
  expectError("model herschelBulkley; herschelBulkleyCoeffs { tau0 5; k 0.1; n 0.4; }", "mu0");
  expectError("model herschelBulkley; herschelBulkleyCoeffs { tau0 5; k 0.1; n 0; mu0 1; }",
              "'n' must be positive");
  expectError("model herschelBulkley; herschelBulkleyCoeffs { tau0 -1; k 0.1; n 1; mu0 1; }",
              "'tau0' must be zero or positive");
  expectError("model herschelBulkley; herschelBulkleyCoeffs { tau0 0; k 0; n 1; mu0 1; }",
              "both zero");
  expectError("model herschelBulkley; herschelBulkleyCoeffs { tau0 0; k 1; n 1; mu0 1; nu0 1; }",
              "nu0");
}

}  // namespace
}  // namespace sphcast
