#include "SqueezeFilmCase.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "BodyTestCases.h"
#include "materials/Material.h"
#include "sph/FlowTestCases.h"

namespace sphcast::testing {
namespace {

const Real baseDx = 0.001;  // the spacing at refinement 1
const Real viscosity = 1;   // Pa s, the Newtonian liquid's
const Real density = 1000;
// in mm (spacings at refinement 1): the tank's columns, the plate's face's start above the
// floor, the pool's rows and the slug's columns; the plate is plateLayers thick at any refinement
const int columns = 160, startGap = 8, poolRows = 11, slugColumns = 60, plateLayers = 3;

int plateColumnsOf(Liquid liquid) { return liquid == Liquid::slug ? 140 : 120; }

// The tank, or for a filled gap a floor as wide as the plate (three layers under it).
ParticleCloud wallsOf(Liquid liquid, int tankColumns, int tankRows, int plateColumns,
                      int plateFirst, Real dx) {
  if (liquid != Liquid::gapFilled) return tankWalls2D(tankColumns, tankRows, dx);
  ParticleCloud floor =
      boxBody(plateColumns, 3, 1, dx, Vector(plateFirst * dx, -3 * dx, 0), true, "wall");
  // the floor's face is its top: the end columns' normals up too, as a floor's under a plate
  // of the same width (boxBody points them out of the side)
  auto& normal = floor.vectorField(field::normal);
  auto& depth = floor.scalarField(field::wallDistance);
  for (std::size_t i = 0; i < floor.size(); ++i) {
    normal[i] = Vector::UnitY();
    depth[i] = -floor.positions()[i].y();
  }
  return floor;
}

}  // namespace

const char* nameOf(Liquid liquid) {
  switch (liquid) {
    case Liquid::pool:
      return "pool";
    case Liquid::slug:
      return "slug";
    case Liquid::gapFilled:
      return "gapFilled";
  }
  return "";
}

RigidBodySettings plateSettings() {
  RigidBodySettings settings;
  settings.name = settings.cloud = "plate";
  settings.density = 7850;
  return settings;
}

HerschelBulkleySettings halfPowerLaw(double consistency) {
  HerschelBulkleySettings law;
  law.consistency = Real(consistency);
  law.exponent = Real(0.5);
  law.restViscosity = 100;
  return law;
}

SqueezeFilmCase::SqueezeFilmCase(const RigidBodySettings& bodySettings, double refinementLevel,
                                 Liquid liquidKind, bool incompressible)
    : liquid(liquidKind),
      plateColumns(plateColumnsOf(liquidKind)),
      refinement(refinementLevel),
      dx(baseDx / Real(refinement)),
      fluid(fluidBlock2D(spacings(columns), spacings(poolRows), dx, Vector::Zero(), density,
                         viscosity)),
      tank(wallsOf(liquid, spacings(columns), spacings(poolRows + 8), spacings(plateColumns),
                   first(), dx)),
      plate(boxBody(spacings(plateColumns), plateLayers, 1, dx,
                    Vector(first() * dx, spacings(startGap) * dx, 0), true, "plate")) {
  // the plate's cells hold no liquid, a slug only the gap's middle, a filled gap only the gap
  // (the fields are uniform: the first particle's serve)
  const int slugFirst = (spacings(columns) - spacings(slugColumns)) / 2;
  std::size_t count = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Vector x = fluid.positions()[i];
    const int column = static_cast<int>(std::floor(x.x() / dx));
    const int row = static_cast<int>(std::floor(x.y() / dx));
    const bool underPlate = column >= first() && column < first() + spacings(plateColumns);
    const bool inGap = row < spacings(startGap);
    bool kept = false;
    switch (liquid) {
      case Liquid::pool:
        kept = !underPlate || inGap;
        break;
      case Liquid::slug:
        kept = inGap && column >= slugFirst && column < slugFirst + spacings(slugColumns);
        break;
      case Liquid::gapFilled:
        kept = underPlate && inGap;
        break;
    }
    if (kept) fluid.positions()[count++] = x;
  }
  fluid.resize(count);
  flowSettings.dimension = 2;
  flowSettings.supportRadius = 3 * dx;
  // p_max = 6 mu V a^2 / h^3 = 3,375 Pa at 4 mm when driven at V: 0.8 % of rho c^2 (at the 5 m/s
  // of the first version, 13.5 %: the liquid compressed in the gap instead of flowing out, and
  // the force read 21 % short at 4 dx)
  flowSettings.soundSpeed = 20;
  flowSettings.incompressible = incompressible;
  neighbourhood.emplace(flowSettings.supportRadius, flowSettings.periodic);
  body.emplace(bodySettings, plate, Vector::Zero());
  flow.emplace(flowSettings, fluid, std::vector<const ParticleCloud*>{&tank, &plate},
               *neighbourhood);
  neighbourhood->addCloud(plate, Neighbourhood::Motion::rigid);
  flow->measureLoadOn(plate);
  neighbourhood->update();
  flow->start();
}

int SqueezeFilmCase::spacings(int millimetres) const {
  return static_cast<int>(std::lround(millimetres * refinement));
}

int SqueezeFilmCase::first() const { return (spacings(columns) - spacings(plateColumns)) / 2; }

double SqueezeFilmCase::step(double time) {
  std::string limiter;
  double dt = std::min(flow->stepLimits(0.25).smallest(limiter), body->stableDeltaT(dx));
  if (lastDeltaT > 0) dt = std::min(dt, 1.2 * lastDeltaT);  // as the solver's time control
  lastDeltaT = dt;
  const WallLoad& load = flow->wallLoad(plate);
  if (flowSettings.incompressible) {  // the step with the plate in its solve, then the search
    if (rheology) rheology->update(dt);
    WeaklyCompressibleFlow::SubStepHooks hooks;
    hooks.kick = [&](double step, double) {
      body->setLoadsAndKick(load.force, load.torque, step, time + dt);
    };
    hooks.drift = [&](double step, double) { body->kickAndDrift(step, time + dt); };
    hooks.predict = [&](const ParticleCloud& wall, const Vector& force, const Vector& torque,
                        double step, std::vector<Vector>& velocity) {
      if (&wall != &plate) return false;
      body->predictParticleVelocities(force, torque, step, time + dt, velocity);
      return true;
    };
    flow->advectionStep(dt, hooks);
    neighbourhood->update();
    flow->keepClearOfWalls();
    body->takeImpulse(load.clearanceImpulse, load.clearanceAngularImpulse, dt, time + dt);
    clearanceForce = load.clearanceImpulse.y() / dt;
    return dt;
  }
  flow->kickAndDrift(dt);
  body->kickAndDrift(dt, time + dt);
  neighbourhood->update();
  flow->keepClearOfWalls();
  body->takeImpulse(load.clearanceImpulse, load.clearanceAngularImpulse, dt, time + dt);
  clearanceForce = load.clearanceImpulse.y() / dt;
  if (rheology) rheology->update(dt);
  flow->computeRatesAndKick(dt);
  body->setLoadsAndKick(load.force, load.torque, dt, time + dt);
  return dt;
}

double SqueezeFilmCase::gap() const { return spacings(startGap) * dx + body->displacement().y(); }

double SqueezeFilmCase::halfWidth() const { return plateColumns * baseDx / 2; }

namespace {

// int_to^from dh / V(h) by Simpson's rule (2,000 intervals: exact to 1e-9 here).
double lubricationTime(double load, double consistency, double n,
                       const std::function<double(double)>& halfWidth, double from, double to) {
  const double shape = std::pow((2 * n + 1) / (2 * n), n);
  auto inverseSpeed = [&](double h) {
    return std::pow(2 * consistency * shape * std::pow(halfWidth(h), n + 2) /
                        (load * (n + 2) * std::pow(h / 2, 2 * n + 1)),
                    1 / n);
  };
  const int intervals = 2000;
  const double step = (from - to) / intervals;
  double sum = inverseSpeed(to) + inverseSpeed(from);
  for (int k = 1; k < intervals; ++k) sum += (k % 2 ? 4 : 2) * inverseSpeed(to + k * step);
  return sum * step / 3;
}

}  // namespace

ClosingTimes closingTimes(Liquid liquid, double load, double refinement,
                          const std::optional<HerschelBulkleySettings>& law, bool incompressible) {
  RigidBodySettings settings = plateSettings();
  settings.translation = RigidBodySettings::Translation::axis;
  settings.axis = Vector::UnitY();
  settings.rotationLocked = true;
  settings.appliedForce = {{0.0, Vector(0, -static_cast<Real>(load), 0)}};
  const auto start = std::chrono::steady_clock::now();
  SqueezeFilmCase squeeze(settings, refinement, liquid, incompressible);
  const Material noTables;
  if (law) {
    squeeze.rheology = std::make_unique<HerschelBulkley>(
        RheologyContext{squeeze.fluid, noTables, *squeeze.neighbourhood, shearWalls(*squeeze.flow),
                        2, squeeze.flowSettings.supportRadius},
        *law);
  }
  const double consistency = law ? law->consistency : viscosity;
  const double exponent = law ? law->exponent : 1;
  const double a = plateColumnsOf(Liquid::pool) * baseDx / 2;
  const double area = static_cast<double>(squeeze.fluid.size()) * squeeze.dx * squeeze.dx;
  const std::function<double(double)> halfWidth = [&](double h) {
    return liquid == Liquid::slug ? area / (2 * h) : a;
  };
  // the times the gap passes 6, 5 and 4 mm (interpolated within the step)
  const std::vector<double> marks{6e-3, 5e-3, 4e-3};
  std::vector<double> passed(marks.size(), -1);
  double time = 0, gap = squeeze.gap();
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
  auto lubrication = [&](double h) {
    return lubricationTime(load, consistency, exponent, halfWidth, marks[0], h);
  };
  ClosingTimes times{
      (passed[1] - passed[0]) / lubrication(marks[1]),
      (passed[2] - passed[0]) / lubrication(marks[2]), lubrication(marks[2]),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
  if (passed.back() < 0) {
    std::printf("the gap did not close to 4 mm in 5 s: %.3f mm\n", gap * 1e3);
    times.to5 = times.to4 = std::nan("");
  }
  std::printf(
      "%s, n = %g, dx = %.3f mm (%zu liquid particles): 6 -> 5 mm in %.4f and 6 -> 4 mm in %.4f "
      "of lubrication's time (%.4f s to 4 mm), %.1f s\n",
      nameOf(liquid), exponent, 1e3 * squeeze.dx, squeeze.fluid.size(), times.to5, times.to4,
      times.lubricationTo4, times.seconds);
  return times;
}

}  // namespace sphcast::testing
