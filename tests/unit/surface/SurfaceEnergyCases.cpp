// The cases of SurfaceEnergyCases.h.

#include "SurfaceEnergyCases.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

#include <Eigen/Dense>

#include "SurfaceTensionTestCases.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "sph/FlowTestCases.h"
#include "surface/SurfaceEnergyTension.h"

namespace sphcast::testing {
namespace {

// The mechanical tension of a periodic slab (along x): the work of stretching it along x per unit
// of new surface, positions and box scaled by 1 + e, densities by 1 / (1 + e) (continuity),
//   sigma = (dE_s/de - sum_i p_i V_i) / (2 L)
// (two surfaces; the equation of state's work is -p dV). Central differences in e.
double slabTension(const ParticleCloud& fluid, const SurfaceTensionSettings& settings, Real lower,
                   Real length) {
  const Real area = settings.dimension == 2 ? length : length * length;
  auto energyAt = [&](Real e) {
    ParticleCloud copy = fluid;
    for (Vector& x : copy.positions()) x[0] = lower + (x[0] - lower) * (1 + e);
    for (Real& r : copy.scalarField(field::rho)) r /= 1 + e;
    PeriodicBox box;
    box.setPeriodic(0, lower, length * (1 + e));
    if (settings.dimension == 3) box.setPeriodic(2, lower, length);
    Neighbourhood neighbourhood(settings.supportRadius, box);
    neighbourhood.addCloud(copy, Neighbourhood::Motion::moving);
    SurfaceEnergyTension tension(settings, copy, {}, neighbourhood);
    neighbourhood.update();
    return tension.energy();
  };
  const Real e = Real(1e-5);
  const double slope = (energyAt(e) - energyAt(-e)) / (2 * e);
  double work = 0;
  const auto& p = fluid.scalarField(field::p);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    work += p[i] * fluid.scalarField(field::mass)[i] / fluid.scalarField(field::rho)[i];
  }
  return (slope - work) / (2 * area);
}

// theta of a circular cap from H^2 / A (bisection: the ratio grows with theta).
double capAngle(double height, double area) {
  const double ratio = height * height / area;
  double low = 1e-3, high = std::numbers::pi;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (low + high);
    const double value = std::pow(1 - std::cos(mid), 2) / (mid - std::sin(mid) * std::cos(mid));
    (value < ratio ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace

DropletResult oscillatingDroplet(const DropletSetup& setup) {
  const int d = setup.dimension;
  const Real radius = 0.01, sigma = 0.07, rho = 1000, nu = 8e-6;
  const Real dx = 2 * radius / setup.across;
  const Real h = static_cast<Real>(setup.hOverDx) * dx;
  const int n = 2;
  const double omegaLamb =
      d == 2 ? std::sqrt(n * (n * n - 1) * sigma / (rho * std::pow(radius, 3)))
             : std::sqrt(n * (n - 1) * (n + 2) * sigma / (rho * std::pow(radius, 3)));
  ParticleCloud fluid = latticeFluid(
      d, dx, Vector::Constant(-radius - dx), Vector::Constant(radius + dx),
      [&](const Vector& x) { return x.norm() < radius; }, rho, rho * nu);
  DropletResult result;
  result.particles = fluid.size();
  // the radius of the droplet the particles make (their area or volume)
  result.radius = dropRadius(d, fluid.size(), dx);
  const double R = result.radius;
  result.lambPeriod = 2 * std::numbers::pi /
                      (d == 2 ? std::sqrt(n * (n * n - 1) * sigma / (rho * R * R * R))
                              : std::sqrt(n * (n - 1) * (n + 2) * sigma / (rho * R * R * R)));
  result.lambDecay = d == 2 ? 2 * n * (n - 1) * nu / (R * R) : (n - 1) * (2 * n + 1) * nu / (R * R);
  // The speed of sound: ten times the largest speed, and stiff enough against the surface
  // layer's pull. The energy falls as the surface particles crowd (s_i rises towards 1), so
  // the layer is pressed by about R_d Gamma / dx, a pressure far above Laplace's sigma / R,
  // that only the equation of state resists.
  const Real speed = setup.amplitude * radius * omegaLamb * (d == 2 ? 1 : 2);
  const Real laplace = (d - 1) * sigma / radius;
  const Real factor = setup.energyFactor > 0 ? setup.energyFactor
                                             : SurfaceEnergyTension::calibratedEnergyFactor(
                                                   d, h, dx, static_cast<Real>(setup.core));
  const Real c = std::max(
      10 * speed,
      capillarySoundSpeed(factor, sigma, dx, rho, static_cast<Real>(setup.surfaceCompression)));
  FlowSettings flow;
  flow.dimension = d;
  flow.supportRadius = h;
  flow.soundSpeed = c;
  if (!setup.densityScheme.empty()) flow.densityScheme = setup.densityScheme;
  SurfaceTensionSettings tension = tensionSettings(d, h, dx, sigma);
  tension.densityCoupling = setup.densityCoupling;
  tension.energyFactor = setup.energyFactor;
  tension.coreRadius = static_cast<Real>(setup.core);
  const Real A = setup.amplitude * omegaLamb;  // a0 omega / R
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    fluid.scalarField(field::rho)[i] = rho + laplace / (c * c);
  }
  CapillaryRun run(flow, tension, fluid, {});
  // The lattice's staircase surface relaxes first, its energy (a large multiple of the mode's)
  // taken out by damping the velocities, over `relaxation` capillary times.
  auto& U = fluid.vectorField(field::U);
  const double relaxEnd = setup.relaxation * std::sqrt(rho * std::pow(radius, 3) / sigma);
  while (run.time < relaxEnd) {
    run.step(run.stableDeltaT());
    for (Vector& u : U) u *= Real(0.99);
  }
  Vector centre = Vector::Zero();
  for (const Vector& x : fluid.positions()) centre += x;
  centre /= static_cast<Real>(fluid.size());
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Vector x = fluid.positions()[i] - centre;
    U[i] = d == 2 ? Vector(A * x[0], -A * x[1], 0) : Vector(-A * x[0], -A * x[1], 2 * A * x[2]);
  }
  run.time = 0;
  // the mode's amplitude, up to a constant factor
  auto amplitude = [&] {
    double sum = 0;
    Vector mid = Vector::Zero();
    for (const Vector& x : fluid.positions()) mid += x;
    mid /= static_cast<Real>(fluid.size());
    for (const Vector& xAbsolute : fluid.positions()) {
      const Vector x = xAbsolute - mid;
      sum += d == 2 ? x[0] * x[0] - x[1] * x[1] : x[2] * x[2] - 0.5 * (x[0] * x[0] + x[1] * x[1]);
    }
    return sum / static_cast<double>(fluid.size());
  };
  // the moment's history; a relaxed drop is not quite round (in 3D its moment keeps an offset
  // of the order of the mode's amplitude), so the period and decay are read about its mean
  std::vector<double> times{0.0}, moments{amplitude()};
  const double end = setup.periods * result.lambPeriod;
  const auto clockStart = std::chrono::steady_clock::now();
  while (run.time < end) {
    const double dt = run.stableDeltaT();
    const double t0 = run.time;
    run.step(dt);
    ++result.steps;
    const double now = amplitude();
    const long trace = setup.traceEvery;
    if (trace > 0 && static_cast<long>(result.steps) % trace == 0) {
      double kinetic = 0;
      for (const Vector& u : fluid.vectorField(field::U)) kinetic += 0.5 * u.squaredNorm();
      double closest = 1e9;
      const auto& xs = fluid.positions();
      for (std::size_t i = 0; i < xs.size(); ++i) {
        for (std::size_t j = i + 1; j < xs.size(); ++j) {
          closest = std::min(closest, static_cast<double>((xs[i] - xs[j]).norm()));
        }
      }
      std::cout << "t " << run.time << " a " << now / R << " sum u^2/2 " << kinetic << " E_s "
                << run.tension.energy() << " nearest pair/dx " << closest / dx << std::endl;
    }
    times.push_back(t0 + dt);
    moments.push_back(now);
    for (const Real r : fluid.scalarField(field::rho)) {
      result.largestDensityDeviation =
          std::max(result.largestDensityDeviation, std::abs(r / rho - 1));
    }
  }
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clockStart).count();
  const ModeReading mode = readMode(times, moments);
  result.offset = mode.mean / R;
  result.period = mode.period;
  result.decay = mode.decay;
  return result;
}

std::ostream& operator<<(std::ostream& out, const DropletResult& r) {
  return out << r.particles << " particles, R " << r.radius << " m: period " << r.period
             << " s against Lamb's " << r.lambPeriod << " s ("
             << 100 * (r.period / r.lambPeriod - 1) << " %), decay " << r.decay << " /s against "
             << r.lambDecay << " /s, largest density deviation " << 100 * r.largestDensityDeviation
             << " %, mean n = 2 moment / R " << r.offset << " m, " << r.steps << " steps in "
             << r.seconds << " s";
}

StaticDropletResult staticDroplet(const StaticDropletSetup& setup) {
  const int d = setup.dimension, across = setup.across;
  const double relaxation = setup.relaxation, compression = setup.compression;
  const Real core = setup.core;
  const Real radius = 0.01, sigma = 0.07, rho = 1000, nu = 1e-4;
  const Real dx = 2 * radius / across;
  const Real h = static_cast<Real>(setup.hOverDx) * dx;
  const bool slab = setup.slab;
  // the slab's period along x (and z): setup.slabPeriod spacings, or across + 2
  const Real lower = -radius - dx;
  const Real period =
      setup.slabPeriod > 0 ? static_cast<Real>(setup.slabPeriod) * dx : 2 * radius + 2 * dx;
  Vector upper = Vector::Constant(radius + dx);
  if (slab) {
    upper[0] = lower + period;
    if (d == 3) upper[2] = lower + period;
  }
  ParticleCloud fluid = latticeFluid(
      d, dx, Vector::Constant(lower), upper,
      [&](const Vector& x) { return slab ? std::abs(x[1]) < radius : x.norm() < radius; }, rho,
      rho * nu);
  StaticDropletResult result;
  result.particles = fluid.size();
  result.radius = dropRadius(d, fluid.size(), dx);
  result.laplace = (d - 1) * sigma / result.radius;
  result.capillaryVelocity = sigma / (rho * nu);
  const Real factor = SurfaceEnergyTension::calibratedEnergyFactor(d, h, dx, core);
  const Real c = capillarySoundSpeed(factor, sigma, dx, rho, static_cast<Real>(compression));
  FlowSettings flow;
  flow.dimension = d;
  flow.supportRadius = h;
  flow.soundSpeed = c;
  if (slab) {
    flow.periodic.setPeriodic(0, lower, period);
    if (d == 3) flow.periodic.setPeriodic(2, lower, period);
  }
  SurfaceTensionSettings tension = tensionSettings(d, h, dx, sigma);
  tension.densityCoupling = setup.densityCoupling;
  tension.coreRadius = core;
  for (Real& r : fluid.scalarField(field::rho))
    r = rho + static_cast<Real>(result.laplace) / (c * c);
  CapillaryRun run(flow, tension, fluid, {});
  if (slab) {
    std::cout << "lattice slab: mechanical tension / sigma "
              << slabTension(fluid, tension, lower, period) / sigma << std::endl;
  }
  const double end = relaxation * std::sqrt(rho * std::pow(radius, 3) / sigma);
  const auto clockStart = std::chrono::steady_clock::now();
  while (run.time < end) {
    run.step(run.stableDeltaT());
    ++result.steps;
  }
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clockStart).count();
  Vector centre = Vector::Zero();
  for (const Vector& x : fluid.positions()) centre += x;
  centre /= static_cast<Real>(fluid.size());
  double pressure = 0;
  int inner = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Vector offset = fluid.positions()[i] - centre;
    if ((slab ? std::abs(offset[1]) : offset.norm()) < 0.5 * result.radius) {
      pressure += fluid.scalarField(field::p)[i];
      ++inner;
    }
    result.spuriousVelocity = std::max(result.spuriousVelocity,
                                       static_cast<double>(fluid.vectorField(field::U)[i].norm()));
  }
  result.jump = pressure / inner;
  if (slab) {
    // the mean over one more capillary time (the pressures carry acoustic noise)
    const double sampleEnd = run.time + std::sqrt(rho * std::pow(radius, 3) / sigma);
    double sum = 0, squares = 0;
    int samples = 0;
    for (long step = 0; run.time < sampleEnd; ++step) {
      run.step(run.stableDeltaT());
      if (step % 100 == 0) {
        const double t = slabTension(fluid, tension, lower, period) / sigma;
        sum += t;
        squares += t * t;
        ++samples;
      }
    }
    const double mean = sum / samples;
    std::cout << "relaxed slab: mechanical tension / sigma " << mean << " +- "
              << std::sqrt(std::max(0.0, squares / samples - mean * mean)) << " (" << samples
              << " samples)" << std::endl;
  }
  const double surface = slab ? (d == 2 ? 2 * period : 2 * period * period)
                              : (d == 2 ? 2 * std::numbers::pi * result.radius
                                        : 4 * std::numbers::pi * result.radius * result.radius);
  if (surface > 0) result.energyRatio = run.tension.energy() / (sigma * surface);
  return result;
}

SettledDrop settleOnWall(const WallDropSetup& setup) {
  const double degrees = setup.degrees, capillaryTimes = setup.capillaryTimes;
  const double startAngle = setup.startAngle;
  const int width = setup.width, height = setup.height;
  const Real damping = setup.damping;
  const Real sigma = 0.07, rho = 1000, nu = 1e-5, dx = 5e-4, h = 3 * dx;
  const double blockArea = double(width) * height * dx * dx;
  const double theta0 = startAngle * std::numbers::pi / 180;
  const double capRadius =
      startAngle > 0 ? std::sqrt(blockArea / (theta0 - std::sin(theta0) * std::cos(theta0))) : 0;
  const Vector capCentre(0, static_cast<Real>(-capRadius * std::cos(theta0)), 0);
  ParticleCloud fluid =
      startAngle > 0
          ? latticeFluid(
                2, dx, Vector(static_cast<Real>(-capRadius) - dx, 0, 0),
                Vector(static_cast<Real>(capRadius) + dx, capCentre[1] + Real(capRadius) + dx, 0),
                [&](const Vector& x) { return (x - capCentre).norm() < capRadius; }, rho, rho * nu)
          : latticeFluid(
                2, dx, Vector(-width * dx / 2, 0, 0), Vector(width * dx / 2, height * dx, 0),
                [](const Vector&) { return true; }, rho, rho * nu);
  ParticleCloud wall = emptyWall();
  const int reach = width;  // the wall runs a drop's width beyond either side
  addWallCells(
      wall, -reach, reach, -3, 0, dx, Vector::Zero(), [](int, int) { return Vector(0, 1, 0); },
      [dx](int, int row) { return (-row - Real(0.5)) * dx; });
  FlowSettings flow;
  flow.dimension = 2;
  flow.supportRadius = h;
  SurfaceTensionSettings tension = tensionSettings(2, h, dx, sigma);
  tension.cosContactAngle = static_cast<Real>(std::cos(degrees * std::numbers::pi / 180));
  const Real factor = SurfaceEnergyTension::calibratedEnergyFactor(2, h, dx, 1);
  flow.soundSpeed = capillarySoundSpeed(factor, sigma, dx, rho, Real(0.01));
  // gravity of Bond number rho g A / sigma (A: the drop's area), which keeps a drop on the wall
  if (setup.bond != 0) {
    const double area = static_cast<double>(fluid.size()) * dx * dx;
    flow.gravity = Vector(0, static_cast<Real>(-setup.bond * sigma / (rho * area)), 0);
  }
  CapillaryRun run(flow, tension, fluid, {&wall});
  const double area = static_cast<double>(fluid.size()) * dx * dx;
  const double end = capillaryTimes * std::sqrt(rho * std::pow(std::sqrt(area), 3) / sigma);
  SettledDrop result;
  const auto start = std::chrono::steady_clock::now();
  while (run.time < end) {
    run.step(run.stableDeltaT());
    for (Vector& u : fluid.vectorField(field::U)) u *= damping;
    ++result.steps;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The cap's circle, fitted (least squares, x^2 + y^2 + D x + E y + F = 0) to the surface
  // particles (surfaceEnergy above a tenth of its largest) more than h from the wall, and moved
  // out by dx / 2 (the surface lies half a spacing beyond the particles' centres): with the
  // wall surface at y = 0, cos theta = -y_centre / R. A centre higher than R is a drop that
  // has left the wall.
  const auto& x = fluid.positions();
  const auto& energy = fluid.scalarField(field::surfaceEnergy);
  const Real largest = *std::max_element(energy.begin(), energy.end());
  Eigen::MatrixXd a(0, 3);
  Eigen::VectorXd b(0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (energy[i] < Real(0.1) * largest || x[i][1] < h) continue;
    a.conservativeResize(a.rows() + 1, Eigen::NoChange);
    b.conservativeResize(b.rows() + 1);
    a.row(a.rows() - 1) << double(x[i][0]), double(x[i][1]), 1.0;
    b(b.rows() - 1) = -double(x[i].squaredNorm());
  }
  const Eigen::Vector3d fit = a.colPivHouseholderQr().solve(b);
  const double centreY = -0.5 * fit(1);
  const double radius =
      std::sqrt(0.25 * fit(0) * fit(0) + 0.25 * fit(1) * fit(1) - fit(2)) + 0.5 * dx;
  result.detached = centreY > radius;
  result.angle = std::acos(std::clamp(-centreY / radius, -1.0, 1.0)) * 180 / std::numbers::pi;
  double top = 0;
  for (const Vector& xi : x) top = std::max(top, static_cast<double>(xi[1]));
  result.heightAngle = capAngle(top + 0.5 * dx, area) * 180 / std::numbers::pi;
  result.closest = 1e9;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      result.closest = std::min(result.closest, static_cast<double>((x[i] - x[j]).norm() / dx));
    }
  }
  return result;
}

}  // namespace sphcast::testing
