// Reynolds' squeeze film (doc/validation.md §1.7): a 2D plate of width 2a approaching the floor
// through a viscous liquid (rho V h / mu = 0.04 at h = 4 dx) feels, per unit depth,
//   F = 8 mu V a^3 / h^3
// (lubrication: q(x) = V x = -(h^3 / 12 mu) dp/dx, p = 6 mu V (a^2 - x^2) / h^3). Driven at V (a
// prescribed rigid body), its load is what the flow measures on its particles; pressed by a
// constant force F instead (a dynamic body on an axis), its gap closes as
//   h(t) = h0 [1 + F h0^2 t / (4 mu a^3)]^(-1/2),
// the 2D form of the disk's h0 [1 + 4 F h0^2 t / (3 pi mu R^4)]^(-1/2). No gravity, so that the
// load is the squeeze alone.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
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

// The plate as a body (density of steel), with the motion's settings still to set.
RigidBodySettings plateSettings() {
  RigidBodySettings settings;
  settings.name = settings.cloud = "plate";
  settings.density = 7850;
  return settings;
}

// The liquid in its tank and the plate above it, its face startGap spacings above the floor, a
// body moving as `body` says, and the flow that loads it.
struct SqueezeCase {
  ParticleCloud fluid, tank, plate;
  FlowSettings flowSettings;
  std::optional<Neighbourhood> neighbourhood;
  std::optional<RigidBody> body;
  std::optional<WeaklyCompressibleFlow> flow;
  double clearanceForce = 0;  // the wall clearance's impulse on the plate over the last step

  explicit SqueezeCase(const RigidBodySettings& bodySettings)
      : fluid(testing::fluidBlock2D(columns, liquidRows, dx, Vector::Zero(), density, viscosity)),
        tank(testing::tankWalls2D(columns, liquidRows + 8, dx)),
        plate(testing::boxBody(plateColumns, plateLayers, 1, dx,
                               Vector(first() * dx, startGap * dx, 0), true, "plate")) {
    // the plate's cells hold no liquid (the fields are uniform: the first particle's serve)
    std::size_t count = 0;
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      const Vector x = fluid.positions()[i];
      const int column = static_cast<int>(std::floor(x.x() / dx));
      const int row = static_cast<int>(std::floor(x.y() / dx));
      if (!(column >= first() && column < first() + plateColumns && row >= startGap)) {
        fluid.positions()[count++] = x;
      }
    }
    fluid.resize(count);
    flowSettings.dimension = 2;
    flowSettings.supportRadius = 3 * dx;
    // p_max = 6 mu V a^2 / h^3 = 3,375 Pa at 4 dx when driven at V: 0.8 % of rho c^2 (at the
    // 5 m/s of the first version, 13.5 %: the liquid compressed in the gap instead of flowing
    // out, and the force read 21 % short at 4 dx)
    flowSettings.soundSpeed = 20;
    neighbourhood.emplace(flowSettings.supportRadius, flowSettings.periodic);
    body.emplace(bodySettings, plate, Vector::Zero());
    flow.emplace(flowSettings, fluid, std::vector<const ParticleCloud*>{&tank, &plate},
                 *neighbourhood);
    neighbourhood->addCloud(plate, Neighbourhood::Motion::rigid);
    flow->measureLoadOn(plate);
    neighbourhood->update();
    flow->start();
  }
  static int first() { return (columns - plateColumns) / 2; }

  // One step of the flow's stable length, as the solver takes it with a body; returns its length.
  double step(double time) {
    std::string limiter;
    const double dt = flow->stepLimits(0.25).smallest(limiter);
    flow->kickAndDrift(dt);
    body->kickAndDrift(dt, time + dt);
    neighbourhood->update();
    flow->keepClearOfWalls();
    const WallLoad& load = flow->wallLoad(plate);
    body->takeImpulse(load.clearanceImpulse, load.clearanceAngularImpulse, dt, time + dt);
    clearanceForce = load.clearanceImpulse.y() / dt;
    flow->computeRatesAndKick(dt);
    body->setLoadsAndKick(load.force, load.torque, dt, time + dt);
    return dt;
  }
  double gap() const { return startGap + body->displacement().y() / dx; }  // in dx
};

std::vector<GapForce> squeezePlate(const std::vector<double>& gaps) {
  const double travel = (startGap - 2.5) * dx;
  RigidBodySettings settings = plateSettings();
  settings.displacement = {{0.0, Vector::Zero()},
                           {travel / speed, Vector(0, -static_cast<Real>(travel), 0)}};
  SqueezeCase squeeze(settings);
  const double a = plateColumns * dx / 2;
  std::vector<GapForce> result;
  struct Window {
    double force = 0, gap = 0, weight = 0;  // time integrals while the gap is in the window
  };
  std::vector<Window> windows(gaps.size());
  double time = 0;
  while (time < travel / speed) {
    const double dt = squeeze.step(time);
    time += dt;
    const double gap = squeeze.gap();
    const double force = squeeze.flow->wallLoad(squeeze.plate).force.y() + squeeze.clearanceForce;
    for (std::size_t g = 0; g < gaps.size(); ++g) {
      if (std::abs(gap - gaps[g]) > 0.25) continue;
      windows[g].force += dt * force;
      windows[g].gap += dt * gap;
      windows[g].weight += dt;
    }
  }
  for (std::size_t g = 0; g < gaps.size(); ++g) {
    const double gap = windows[g].gap / windows[g].weight;
    const double h = gap * dx;
    const double reynolds = 8 * viscosity * speed * a * a * a / (h * h * h);
    result.push_back({gap, windows[g].force / windows[g].weight / reynolds});
  }
  return result;
}

// a = 60 dx: the lubrication limit (h/a = 0.1 at 6 dx). Measured (doc/validation.md §1.7), at
// c = 20 m/s: the force over Reynolds' is 1.116 / 1.041 / 0.987 / 0.872 at h = 6 / 5 / 4 / 3 dx:
// above it where h/a is largest (the flow round the plate's edges, which lubrication leaves out:
// at a = 20 dx it adds 10-40 %), short where the gap has few spacings. The test holds 5 and 4 dx
// to 10 %, 6 dx to 15 % (its edge term), and the order.
TEST(SqueezeFilm, ForceOnAnApproachingPlateIsReynoldsWhereTheGapIsResolved) {
  const std::vector<GapForce> forces = squeezePlate({6, 5, 4, 3});
  for (const GapForce& force : forces) {
    std::printf("gap %.3f dx: F / (8 mu V a^3 / h^3) = %.4f\n", force.gap, force.ratio);
  }
  ASSERT_EQ(forces.size(), 4u);
  EXPECT_NEAR(forces[0].ratio, 1.0, 0.15) << "at a gap of 6 dx";
  EXPECT_NEAR(forces[1].ratio, 1.0, 0.1) << "at a gap of 5 dx";
  EXPECT_NEAR(forces[2].ratio, 1.0, 0.1) << "at a gap of 4 dx";
  EXPECT_GT(forces[0].ratio, forces[1].ratio);
  EXPECT_GT(forces[1].ratio, forces[2].ratio);
  EXPECT_GT(forces[2].ratio, forces[3].ratio);
}

// The plate pressed by a constant force per unit depth (80 N/m: V = 0.01 m/s at h = 6 dx by
// Reynolds), a dynamic body on the y axis, from 8 dx: the time its gap takes to close from 6 dx
// to 5 and to 4 dx against h(t) above. Measured (doc/validation.md §1.7): 6 -> 5 dx in 1.048 and
// 6 -> 4 dx in 1.023 of Reynolds' time (the force's edge excess of the prescribed test slows the
// plate, its thin-gap deficit speeds it). The test holds both within 10 %.
TEST(SqueezeFilm, GapUnderAConstantLoadClosesAsReynolds) {
  const double a = plateColumns * dx / 2, load = 80;
  RigidBodySettings settings = plateSettings();
  settings.translation = RigidBodySettings::Translation::axis;
  settings.axis = Vector::UnitY();
  settings.rotationLocked = true;
  settings.appliedForce = Vector(0, -load, 0);
  SqueezeCase squeeze(settings);
  // the times the gap passes 6, 5 and 4 dx (interpolated within the step)
  const std::vector<double> marks{6, 5, 4};
  std::vector<double> passed(marks.size(), -1);
  double time = 0, gap = startGap;
  while (passed.back() < 0 && time < 5) {
    const double dt = squeeze.step(time);
    const double newGap = squeeze.gap();
    for (std::size_t m = 0; m < marks.size(); ++m) {
      if (passed[m] < 0 && newGap <= marks[m]) {
        passed[m] = time + dt * (gap - marks[m]) / (gap - newGap);
      }
    }
    gap = newGap;
    time += dt;
  }
  ASSERT_GT(passed.back(), 0) << "the gap did not close to 4 dx in 5 s: " << gap << " dx";
  const double h0 = marks[0] * dx;
  for (std::size_t m = 1; m < marks.size(); ++m) {
    const double h = marks[m] * dx;
    const double reynolds = 4 * viscosity * a * a * a / (load * h0 * h0) * (h0 * h0 / (h * h) - 1);
    const double ratio = (passed[m] - passed[0]) / reynolds;
    std::printf("gap 6 -> %g dx in %.4f s, Reynolds %.4f s: %.4f\n", marks[m],
                passed[m] - passed[0], reynolds, ratio);
    RecordProperty("timeRatio6to" + std::to_string(static_cast<int>(marks[m])),
                   std::to_string(ratio));
    EXPECT_NEAR(ratio, 1.0, 0.1) << "6 -> " << marks[m] << " dx";
  }
}

}  // namespace
}  // namespace sphcast
