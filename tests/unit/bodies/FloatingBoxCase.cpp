// The case of FloatingBoxCase.h.

#include "FloatingBoxCase.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "BodyTestCases.h"
#include "bodies/RigidBody.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "sph/FlowTestCases.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast::testing {
namespace {

const Real liquidDensity = 1000;
const Real g = 9.81;

// A 3D block of liquid on the lattice (cell centres from the origin), at rest.
ParticleCloud fluidBlock3D(int columns, int rows, Real dx, Real viscosity) {
  ParticleCloud fluid("fluid");
  auto& U = fluid.addVectorField(field::U);
  auto& rho = fluid.addScalarField(field::rho);
  auto& mass = fluid.addScalarField(field::mass);
  auto& mu = fluid.addScalarField(field::viscosity);
  auto& rest = fluid.addScalarField(field::restDensity);
  for (int k = 0; k < rows; ++k) {
    for (int j = 0; j < columns; ++j) {
      for (int i = 0; i < columns; ++i) {
        const std::size_t n = fluid.size();
        fluid.resize(n + 1);
        fluid.positions()[n] = dx * Vector(i + Real(0.5), j + Real(0.5), k + Real(0.5));
        U[n] = Vector::Zero();
        rho[n] = rest[n] = liquidDensity;
        mass[n] = liquidDensity * dx * dx * dx;
        mu[n] = viscosity;
      }
    }
  }
  fluid.attributes()["spacing"] = dx;
  return fluid;
}

// A 3D open tank of three wall layers round fluidBlock3D's square (columns x columns), its
// walls `height` cells high: each particle's normal towards the liquid's box and its depth the
// distance to it (exact for a box).
ParticleCloud tankWalls3D(int columns, int height, Real dx) {
  constexpr int layers = 3;
  ParticleCloud wall = emptyWall();
  auto outside = [=](int cell, int count) {
    return cell < 0 ? Real(cell + 0.5) : (cell >= count ? Real(cell - count + 0.5) : Real(0));
  };
  for (int k = -layers; k < height; ++k) {
    for (int j = -layers; j < columns + layers; ++j) {
      for (int i = -layers; i < columns + layers; ++i) {
        const Vector out(outside(i, columns), outside(j, columns), k < 0 ? Real(k + 0.5) : 0);
        if (out.norm() == 0) continue;  // the liquid's column
        const std::size_t n = wall.size();
        wall.resize(n + 1);
        wall.positions()[n] = dx * Vector(i + Real(0.5), j + Real(0.5), k + Real(0.5));
        wall.scalarField(field::volume)[n] = dx * dx * dx;
        wall.vectorField(field::normal)[n] = -out.normalized();
        wall.scalarField(field::wallDistance)[n] = out.norm() * dx;
      }
    }
  }
  return wall;
}

}  // namespace

Floating floatBox(int dimension, double densityRatio, double seconds, int coarsening,
                  int offsetColumns, bool incompressible) {
  const Real dx = Real(0.002) * coarsening;
  const int columns = 60 / coarsening, rows = 24 / coarsening;
  const int boxColumns = 16 / coarsening, boxRows = 8 / coarsening;
  const int up = dimension - 1;
  const double boxHeight = boxRows * dx;
  const double draft = densityRatio * boxHeight;  // exact
  const int firstColumn = (columns - boxColumns) / 2 + offsetColumns;
  // let go with its bottom surface a spacing above the liquid (rows dx): it floats where the
  // liquid's level has risen by what it displaces, rows dx + draft w / W
  const double bottom = (rows + 1) * dx;
  const Real c = 10;
  ParticleCloud fluid = dimension == 2
                            ? fluidBlock2D(columns, rows, dx, Vector::Zero(), liquidDensity, 0.5)
                            : fluidBlock3D(columns, rows, dx, 0.5);
  for (std::size_t i = 0; i < fluid.size(); ++i) {  // hydrostatic start
    fluid.scalarField(field::rho)[i] =
        liquidDensity * (1 + g * (rows * dx - fluid.positions()[i][up]) / (c * c));
  }
  ParticleCloud tank =
      dimension == 2 ? tankWalls2D(columns, rows + 20, dx) : tankWalls3D(columns, rows + 20, dx);
  const int centred = (columns - boxColumns) / 2;
  const Vector lower = dimension == 2
                           ? Vector(firstColumn * dx, static_cast<Real>(bottom), 0)
                           : Vector(firstColumn * dx, centred * dx, static_cast<Real>(bottom));
  ParticleCloud box = dimension == 2
                          ? boxBody(boxColumns, boxRows, 1, dx, lower, true, "box")
                          : boxBody(boxColumns, boxColumns, boxRows, dx, lower, false, "box");
  FlowSettings settings;
  settings.dimension = dimension;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = c;
  settings.gravity = -g * Vector::Unit(up);
  settings.incompressible = incompressible;
  Neighbourhood neighbourhood(settings.supportRadius, settings.periodic);
  RigidBodySettings bodySettings;
  bodySettings.name = bodySettings.cloud = "box";
  bodySettings.density = densityRatio * liquidDensity;
  RigidBody body(bodySettings, box, settings.gravity);
  const Vector start = body.centre();
  WeaklyCompressibleFlow flow(settings, fluid, {&tank, &box}, neighbourhood);
  neighbourhood.addCloud(box, Neighbourhood::Motion::rigid);
  flow.measureLoadOn(box);
  neighbourhood.update();
  flow.start();
  body.setLoadsAndKick(flow.wallLoad(box).force, flow.wallLoad(box).torque, 0, 0);
  Floating result{0, 0, 0};
  double time = 0;
  std::string limiter;
  const double width = columns * dx;
  while (time < seconds) {
    const double dt = std::min(flow.stepLimits(0.25).smallest(limiter), body.stableDeltaT(dx));
    time += dt;
    const WallLoad& load = flow.wallLoad(box);
    if (incompressible) {  // the step, then the search
      WeaklyCompressibleFlow::SubStepHooks hooks;
      hooks.kick = [&](double step, double) {
        body.setLoadsAndKick(load.force, load.torque, step, time);
      };
      hooks.drift = [&](double step, double) { body.kickAndDrift(step, time); };
      hooks.predict = [&](const ParticleCloud& wall, const Vector& force, const Vector& torque,
                          double step, std::vector<Vector>& velocity) {
        if (&wall != &box) return false;
        body.predictParticleVelocities(force, torque, step, time, velocity);
        return true;
      };
      flow.advectionStep(dt, hooks);
      neighbourhood.update();
      flow.keepClearOfWalls();
      body.takeImpulse(load.clearanceImpulse, load.clearanceAngularImpulse, dt, time);
    } else {
      flow.kickAndDrift(dt);
      body.kickAndDrift(dt, time);
      neighbourhood.update();
      flow.keepClearOfWalls();
      body.takeImpulse(load.clearanceImpulse, load.clearanceAngularImpulse, dt, time);
      flow.computeRatesAndKick(dt);
      body.setLoadsAndKick(load.force, load.torque, dt, time);
    }
    Vector sideways = body.centre() - start;
    sideways[up] = 0;
    result.drift = std::max(result.drift, double(sideways.norm()) / dx);
    const double angle = 2 * std::asin(std::min(1.0, double(body.orientation().vec().norm())));
    result.tilt = std::max(result.tilt, angle * 180 / std::acos(-1.0));
    if (time > seconds - 0.2) {
      // the free surface far from the box: its top particles within 4 to 24 mm of a side
      double top = 0;
      for (const Vector& x : fluid.positions()) {
        double fromSide = std::min(double(x.x()), width - x.x());
        if (dimension == 3) fromSide = std::min({fromSide, double(x.y()), width - x.y()});
        if (fromSide > 0.004 && fromSide < 0.024) top = std::max(top, double(x[up]));
      }
      const double surface = top + 0.5 * dx;
      double lowest = 1e9;
      for (const Vector& x : box.positions()) lowest = std::min(lowest, double(x[up]));
      const double boxBottom = lowest - 0.5 * dx;
      const double error = (surface - boxBottom - draft) / dx;
      if (std::abs(error) > std::abs(result.draftError)) result.draftError = error;
    }
  }
  return result;
}

}  // namespace sphcast::testing
