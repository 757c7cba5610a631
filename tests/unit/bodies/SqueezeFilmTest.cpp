// Reynolds' squeeze film (doc/validation.md §1.7): a 2D plate of width 2a driven towards the
// floor at V through a viscous liquid (rho V h / mu = 0.04 at h = 4 dx) feels, per unit depth,
//   F = 8 mu V a^3 / h^3
// (lubrication: q(x) = V x = -(h^3 / 12 mu) dp/dx, p = 6 mu V (a^2 - x^2) / h^3). The plate is a
// prescribed rigid body; its load is what the flow measures on its particles. No gravity, so
// that the load is the squeeze alone.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "BodyTestCases.h"
#include "bodies/RigidBody.h"
#include "particles/Neighbourhood.h"
#include "sph/FlowTestCases.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

const Real dx = 0.001;
const Real viscosity = 1;  // Pa s
const Real density = 1000;
const double speed = 0.01;  // m/s, the plate's approach
const int columns = 160, plateColumns = 120, plateLayers = 3, startGap = 8, liquidRows = 11;

struct GapForce {
  double gap;    // mean gap over the window, in dx
  double ratio;  // mean SPH force over Reynolds' at that gap
};

std::vector<GapForce> squeezePlate(const std::vector<double>& gaps) {
  const int first = (columns - plateColumns) / 2;
  ParticleCloud fluid =
      testing::fluidBlock2D(columns, liquidRows, dx, Vector::Zero(), density, viscosity);
  {  // the plate's cells hold no liquid (the fields are uniform: the first particle's serve)
    std::size_t count = 0;
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      const Vector x = fluid.positions()[i];
      const int column = static_cast<int>(std::floor(x.x() / dx));
      const int row = static_cast<int>(std::floor(x.y() / dx));
      if (!(column >= first && column < first + plateColumns && row >= startGap)) {
        fluid.positions()[count++] = x;
      }
    }
    fluid.resize(count);
  }
  auto tank = testing::tankWalls2D(columns, liquidRows + 8, dx);
  auto plate = testing::boxBody(plateColumns, plateLayers, 1, dx,
                                Vector(first * dx, startGap * dx, 0), true, "plate");
  const double travel = (startGap - 2.5) * dx;
  RigidBodySettings settings;
  settings.name = settings.cloud = "plate";
  settings.density = 7850;
  settings.displacement = {{0.0, Vector::Zero()},
                           {travel / speed, Vector(0, -static_cast<Real>(travel), 0)}};
  FlowSettings flowSettings;
  flowSettings.dimension = 2;
  flowSettings.supportRadius = 3 * dx;
  flowSettings.soundSpeed = 5;  // p_max = 6 mu V a^2 / h^3 = 940 Pa at 3 dx: 0.4 % of rho c^2
  Neighbourhood neighbourhood(flowSettings.supportRadius, flowSettings.periodic);
  RigidBody body(settings, plate, Vector::Zero());
  WeaklyCompressibleFlow flow(flowSettings, fluid, {&tank, &plate}, neighbourhood);
  neighbourhood.addCloud(plate, Neighbourhood::Motion::rigid);
  flow.measureLoadOn(plate);
  neighbourhood.update();
  flow.start();
  const double a = plateColumns * dx / 2;
  std::vector<GapForce> result;
  std::vector<double> sumForce(gaps.size(), 0), sumGap(gaps.size(), 0), weight(gaps.size(), 0);
  double time = 0;
  std::string limiter;
  while (time < travel / speed) {
    const double dt = flow.stepLimits(0.25).smallest(limiter);
    time += dt;
    flow.kickAndDrift(dt);
    body.kickAndDrift(dt, time);
    neighbourhood.update();
    flow.keepClearOfWalls();
    const WallLoad& load = flow.wallLoad(plate);
    const double clearance = load.clearanceImpulse.y() / dt;
    flow.computeRatesAndKick(dt);
    body.setLoadsAndKick(load.force, load.torque, dt, time);
    const double gap = startGap + body.displacement().y() / dx;  // in dx
    for (std::size_t g = 0; g < gaps.size(); ++g) {
      if (std::abs(gap - gaps[g]) > 0.25) continue;
      sumForce[g] += dt * (load.force.y() + clearance);
      sumGap[g] += dt * gap;
      weight[g] += dt;
    }
  }
  for (std::size_t g = 0; g < gaps.size(); ++g) {
    const double gap = sumGap[g] / weight[g];
    const double h = gap * dx;
    const double reynolds = 8 * viscosity * speed * a * a * a / (h * h * h);
    result.push_back({gap, sumForce[g] / weight[g] / reynolds});
  }
  return result;
}

// a = 60 dx: the lubrication limit (h/a = 0.1 at 6 dx). Measured (doc/validation.md §1.7): the
// force over Reynolds' is 1.004 / 0.895 / 0.790 / 0.620 at h = 6 / 5 / 4 / 3 dx: the gap's
// flow is too easy when it is a few spacings across. The test holds the resolved gap to 10 % and
// the thinner ones to an error that grows as the gap loses spacings (a resolution error).
TEST(SqueezeFilm, ForceOnAnApproachingPlateIsReynoldsWhereTheGapIsResolved) {
  const std::vector<GapForce> forces = squeezePlate({6, 5, 4, 3});
  for (const GapForce& force : forces) {
    std::printf("gap %.3f dx: F / (8 mu V a^3 / h^3) = %.4f\n", force.gap, force.ratio);
  }
  ASSERT_EQ(forces.size(), 4u);
  EXPECT_NEAR(forces[0].ratio, 1.0, 0.1) << "at a gap of 6 dx";
  EXPECT_GT(forces[1].ratio, forces[2].ratio);
  EXPECT_GT(forces[2].ratio, forces[3].ratio);
}

}  // namespace
}  // namespace sphcast
