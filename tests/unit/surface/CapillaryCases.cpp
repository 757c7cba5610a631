// The cases of CapillaryCases.h: each model's run is a template on the force; the public
// functions pick it from CapillaryOptions::model.

#include "CapillaryCases.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numbers>
#include <type_traits>
#include <vector>

#include <Eigen/Dense>

#include "SurfaceTensionTestCases.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "sph/FlowTestCases.h"
#include "surface/ContinuumSurfaceForce.h"
#include "surface/PairwiseForce.h"

namespace sphcast::testing {
namespace {

bool pairwise(const CapillaryOptions& options) {
  return options.model == SurfaceForceModel::pairwiseForce;
}

template <class Tension>
StaticDropResult staticDropWith(int dimension, int across, double capillaryTimes, double nu,
                                const CapillaryOptions& options) {
  const Real radius = 0.01, sigma = 0.07, rho = 1000;
  const Real dx = 2 * radius / across, h = 3 * dx;
  const Vector reach = Vector::Constant(radius + dx);
  ParticleCloud fluid = options.latticeStart
                            ? latticeFluid(
                                  dimension, dx, -reach, reach,
                                  [&](const Vector& x) { return x.norm() < radius; }, rho, rho * nu)
                            : ringFluid(dimension, dx, across / 2, rho, rho * nu);
  FlowSettings flow;
  flow.dimension = dimension;
  flow.supportRadius = h;
  const double capillarySpeed = std::sqrt(sigma / (rho * radius));
  // the jump compresses the drop by 0.1 %: c^2 = 1000 (d-1) sigma / (rho R), and at least
  // 20 times the capillary speed
  flow.soundSpeed = static_cast<Real>(
      std::max(std::sqrt(1000.0 * (dimension - 1) * sigma / (rho * radius)), 20 * capillarySpeed) *
      options.soundSpeedScale);
  const SurfaceTensionSettings tension = tensionSettings(dimension, h, dx, sigma);
  CapillaryRun<Tension> run(flow, tension, fluid, {});
  const double capillaryTime = std::sqrt(rho * std::pow(radius, 3) / sigma);
  const auto start = std::chrono::steady_clock::now();
  const auto& U0 = fluid.vectorField(field::U);
  double nextReport = 0.5 * capillaryTime;
  while (run.time < capillaryTimes * capillaryTime) {
    run.step(run.stableDeltaT());
    if (options.trace && run.time >= nextReport) {
      nextReport += 0.5 * capillaryTime;
      double largest = 0;
      for (const Vector& u : U0) largest = std::max(largest, static_cast<double>(u.norm()));
      std::cout << "  t/tc " << run.time / capillaryTime << " largest speed "
                << largest / capillarySpeed << std::endl;
    }
  }
  StaticDropResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto& x = fluid.positions();
  const auto& U = fluid.vectorField(field::U);
  const auto& density = fluid.scalarField(field::rho);
  const auto& rest = fluid.scalarField(field::restDensity);
  Vector centre = Vector::Zero(), drift = Vector::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    centre += x[i];
    drift += U[i];
  }
  centre /= static_cast<Real>(x.size());
  drift /= static_cast<Real>(x.size());
  const double volumeRadius = dropRadius(dimension, x.size(), dx);
  double pressure = 0, inner = 0, speedSum = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double speed = (U[i] - drift).norm();
    result.largestSpeed = std::max(result.largestSpeed, speed / capillarySpeed);
    speedSum += speed;
    if ((x[i] - centre).norm() < radius / 2) {
      pressure += flow.soundSpeed * flow.soundSpeed * (density[i] - rest[i]);
      inner += 1;
    }
  }
  result.meanSpeed = speedSum / static_cast<double>(x.size()) / capillarySpeed;
  if constexpr (std::is_same_v<Tension, ContinuumSurfaceForce>) {
    const auto& kappa = fluid.scalarField(field::curvature);
    double kw = 0, w = 0, ps = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (!run.tension.onSurface()[i]) continue;
      kw += kappa[i];
      w += 1;
      ps += flow.soundSpeed * flow.soundSpeed * (density[i] - rest[i]);
    }
    std::cout << "  surface particles " << w << ": mean kappa R/(d-1) "
              << kw / w * volumeRadius / (dimension - 1) << ", mean pressure / Laplace's "
              << ps / w / (sigma * (dimension - 1) / volumeRadius) << std::endl;
  }
  result.pressureRatio = pressure / inner / (sigma * (dimension - 1) / volumeRadius);
  result.closest = 1e9;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (const std::uint32_t j : run.neighbourhood.pairs(fluid, fluid).of(i)) {
      result.closest = std::min(result.closest, static_cast<double>((x[i] - x[j]).norm() / dx));
    }
  }
  result.particles = x.size();
  return result;
}

template <class Tension>
OscillationResult oscillatingDropWith(int dimension, int across, double periods,
                                      const CapillaryOptions& options) {
  const Real radius = 0.01, sigma = 0.07, rho = 1000, nu = 8e-6;
  const Real dx = 2 * radius / across;
  ParticleCloud fluid = ringFluid(dimension, dx, across / 2, rho, rho * nu);
  OscillationResult result;
  result.particles = fluid.size();
  const double R = dropRadius(dimension, fluid.size(), dx);
  const double omega = std::sqrt((dimension == 2 ? 6 : 8) * sigma / (rho * R * R * R));
  result.lambPeriod = 2 * std::numbers::pi / omega;
  result.viscousDecay = (dimension == 2 ? 4 : 5) * nu / (R * R);
  const double a0 = options.amplitude;
  const Real A = static_cast<Real>(a0 * omega);
  FlowSettings flow;
  flow.dimension = dimension;
  flow.supportRadius = 3 * dx;
  // ten times the largest speed, and the jump compresses the drop by 0.1 % at most
  flow.soundSpeed =
      static_cast<Real>(std::max(10 * a0 * omega * R * (dimension == 2 ? 1 : 2),
                                 std::sqrt(1000.0 * (dimension - 1) * sigma / (rho * R))) *
                        options.soundSpeedScale);
  const double c = flow.soundSpeed;
  auto& U = fluid.vectorField(field::U);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Vector& x = fluid.positions()[i];
    fluid.scalarField(field::rho)[i] =
        rho + static_cast<Real>(sigma * (dimension - 1) / R / (c * c));
    U[i] = dimension == 2 ? Vector(A * x[0], -A * x[1], 0)
                          : Vector(-A * x[0], -A * x[1], 2 * A * x[2]);
  }
  CapillaryRun<Tension> run(flow, tensionSettings(dimension, 3 * dx, dx, sigma), fluid, {});
  auto moment = [&] {
    Vector mid = Vector::Zero();
    for (const Vector& x : fluid.positions()) mid += x;
    mid /= static_cast<Real>(fluid.size());
    double sum = 0;
    for (const Vector& xAbsolute : fluid.positions()) {
      const Vector x = xAbsolute - mid;
      sum += dimension == 2 ? x[0] * x[0] - x[1] * x[1]
                            : x[2] * x[2] - 0.5 * (x[0] * x[0] + x[1] * x[1]);
    }
    return sum / static_cast<double>(fluid.size());
  };
  std::vector<double> times{0.0}, moments{moment()};
  const auto start = std::chrono::steady_clock::now();
  while (run.time < periods * result.lambPeriod) {
    run.step(run.stableDeltaT());
    times.push_back(run.time);
    moments.push_back(moment());
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const ModeReading mode = readMode(times, moments);
  if (options.trace) {
    for (const double e : mode.extremes) std::cout << "  extreme " << e / (R * R) << std::endl;
    for (const double t : mode.crossings) {
      std::cout << "  crossing " << t / result.lambPeriod << std::endl;
    }
  }
  result.period = mode.period;
  result.decay = mode.decay;
  return result;
}

// Steps a sessile drop to `end` (s) as the solver steps it, printing with options.trace
// every `traceEvery` steps its fastest particle, its lowest along the axis `up` and its largest
// curvature (and, with options.traceFastest, the fastest particle's state). Then reads the
// lowest particle and the nearest pair (in spacings) and, by the continuum surface force's
// detection whatever model held the drop, the surface: each outer particle (depth under 0.8 dx)
// moved out along its normal by its depth, where aboveWall(point) is at least h.
template <class Tension, class AboveWall>
SessileResult settleDrop(CapillaryRun<Tension>& run, ParticleCloud& fluid,
                         const SurfaceTensionSettings& tension, const ParticleCloud& wall,
                         double end, int up, long traceEvery, Real h, std::vector<Vector>& surface,
                         AboveWall aboveWall, const CapillaryOptions& options) {
  const Real dx = tension.spacing;
  const auto start = std::chrono::steady_clock::now();
  long steps = 0;
  while (run.time < end) {
    run.step(run.stableDeltaT());
    if (!options.trace || ++steps % traceEvery != 0) continue;
    double fastest = 0, lowest = 1e9, kmax = 0;
    std::size_t f = 0;
    const auto& U = fluid.vectorField(field::U);
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      fastest = std::max(fastest, static_cast<double>(U[i].norm()));
      if (U[i].norm() > U[f].norm()) f = i;
      lowest = std::min(lowest, static_cast<double>(fluid.positions()[i][up] / dx));
      kmax = std::max(kmax, std::abs(static_cast<double>(fluid.scalarField(field::curvature)[i])));
    }
    std::cout << "  t " << run.time << " fastest " << fastest << " lowest " << lowest
              << " dx, largest |kappa| dx " << kmax * dx << std::endl;
    if constexpr (std::is_same_v<Tension, ContinuumSurfaceForce>) {
      if (options.traceFastest) {
        int near = 0;
        for (std::size_t j = 0; j < fluid.size(); ++j) {
          near += (fluid.positions()[j] - fluid.positions()[f]).norm() < h;
        }
        std::cout << "    fastest at " << (fluid.positions()[f] / dx).transpose() << " dx, U "
                  << U[f].transpose() << ", " << near - 1 << " fluid within h, g "
                  << run.tension.colourGradient()[f].transpose() * dx << " /dx, kappa dx "
                  << fluid.scalarField(field::curvature)[f] * dx << ", surface "
                  << int(run.tension.onSurface()[f]) << ", a "
                  << fluid.vectorField(field::acceleration)[f].transpose() << std::endl;
      }
    }
  }
  SessileResult result;
  result.particles = fluid.size();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ContinuumSurfaceForce probe(tension, fluid, {&wall}, run.neighbourhood);
  probe.computeSurface();
  const auto& x = fluid.positions();
  result.lowest = 1e9;
  result.closest = 1e9;
  surface.clear();
  for (std::size_t i = 0; i < x.size(); ++i) {
    result.lowest = std::min(result.lowest, static_cast<double>(x[i][up] / dx));
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      result.closest = std::min(result.closest, static_cast<double>((x[i] - x[j]).norm() / dx));
    }
    if (!probe.onSurface()[i] || probe.depth()[i] > Real(0.8) * dx) continue;
    const Vector point = x[i] + probe.depth()[i] * probe.unitNormal()[i];
    if (aboveWall(point) >= h) surface.push_back(point);
  }
  return result;
}

// The circle (dims 2: in x, y) or sphere (3) through the points in the least-squares sense,
// |x|^2 + a . x + c = 0.
struct FittedSphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0;
};

FittedSphere fitSphere(const std::vector<Vector>& points, int dims) {
  Eigen::MatrixXd a(static_cast<Eigen::Index>(points.size()), dims + 1);
  Eigen::VectorXd b(static_cast<Eigen::Index>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    for (int axis = 0; axis < dims; ++axis) a(row, axis) = double(points[k][axis]);
    a(row, dims) = 1.0;
    b(row) = -double(points[k].squaredNorm());
  }
  const Eigen::VectorXd fit = a.colPivHouseholderQr().solve(b);
  FittedSphere sphere;
  sphere.centre.head(dims) = -0.5 * fit.head(dims);
  sphere.radius = std::sqrt(sphere.centre.squaredNorm() - fit(dims));
  return sphere;
}

template <class Tension>
SessileResult sessileDropWith(double degrees, int layers, double capillaryTimes, double bond,
                              double cylinder, const CapillaryOptions& options) {
  const Real sigma = 0.07, rho = 1000, nu = 1e-4, dx = 5e-4, h = 3 * dx;
  const Real capRadius = layers * dx;
  const Real cylinderRadius = static_cast<Real>(cylinder) * capRadius;
  const Vector cylinderCentre(0, -cylinderRadius, 0);
  // on a cylinder the drop is built of rings round it a spacing apart (lattice rows would leave
  // gaps of up to a spacing and more against its surface)
  std::vector<Vector> rings;
  for (int ring = 0; cylinder > 0 && ring < 2 * layers; ++ring) {
    const Real radius = cylinderRadius + (ring + Real(0.5)) * dx;
    const int count = static_cast<int>(std::round(2 * std::numbers::pi * radius / dx));
    for (int k = 0; k < count; ++k) {
      const Real angle = 2 * std::numbers::pi * (k + Real(0.5) * (ring % 2)) / count;
      const Vector x = cylinderCentre + radius * Vector(std::sin(angle), std::cos(angle), 0);
      if (x.norm() < capRadius) rings.push_back(x);
    }
  }
  // options.startDegrees: on a flat wall, the lattice particles of a cap of that angle and the
  // half disk's area instead
  Real startRadius = capRadius;
  Vector startCentre = Vector::Zero();
  if (options.startDegrees > 0) {
    const double theta0 = options.startDegrees * std::numbers::pi / 180;
    const double area = 0.5 * std::numbers::pi * capRadius * capRadius;
    startRadius =
        static_cast<Real>(std::sqrt(area / (theta0 - std::sin(theta0) * std::cos(theta0))));
    startCentre[1] = static_cast<Real>(-startRadius * std::cos(theta0));
  }
  ParticleCloud fluid =
      cylinder > 0 ? fluidAtRest(2, dx, rings, rho, rho * nu)
                   : latticeFluid(
                         2, dx, Vector(-startRadius - dx, 0, 0),
                         Vector(startRadius + dx, startCentre[1] + startRadius + dx, 0),
                         [&](const Vector& x) { return (x - startCentre).norm() < startRadius; },
                         rho, rho * nu);
  ParticleCloud wall = emptyWall();
  const int reach = 4 * layers;
  if (cylinder > 0) {
    for (int ring = 0; ring < 3; ++ring) {
      const Real radius = cylinderRadius - (ring + Real(0.5)) * dx;
      const int count = static_cast<int>(std::round(2 * std::numbers::pi * radius / dx));
      for (int k = 0; k < count; ++k) {
        const Real angle = 2 * std::numbers::pi * (k + Real(0.5) * (ring % 2)) / count;
        const Vector normal(std::sin(angle), std::cos(angle), 0);
        const std::size_t index = wall.size();
        wall.resize(index + 1);
        wall.positions()[index] = cylinderCentre + radius * normal;
        wall.scalarField(field::volume)[index] = dx * dx;
        wall.vectorField(field::normal)[index] = normal;
        wall.scalarField(field::wallDistance)[index] = (ring + Real(0.5)) * dx;
      }
    }
  } else {
    addWallCells(
        wall, -reach, reach, -3, 0, dx, Vector::Zero(), [](int, int) { return Vector(0, 1, 0); },
        [dx](int, int row) { return (-row - Real(0.5)) * dx; });
  }
  const double area = static_cast<double>(fluid.size()) * dx * dx;
  FlowSettings flow;
  if (options.slipWalls) flow.walls.all.velocity = WallCondition::Velocity::slip;
  flow.dimension = 2;
  flow.supportRadius = h;
  flow.gravity = Vector(0, static_cast<Real>(-bond * sigma / (rho * area)), 0);
  const double radius = std::sqrt(2 * area / std::numbers::pi);
  flow.soundSpeed = static_cast<Real>(std::sqrt(1000.0 * sigma / (rho * radius)));
  SurfaceTensionSettings tension = tensionSettings(2, h, dx, sigma);
  tension.cosContactAngle = static_cast<Real>(std::cos(degrees * std::numbers::pi / 180));
  CapillaryRun<Tension> run(flow, tension, fluid, {&wall});
  const double end = capillaryTimes * std::sqrt(rho * std::pow(area, 1.5) / sigma);
  std::vector<Vector> surface;
  SessileResult result = settleDrop(
      run, fluid, tension, wall, end, 1, 200, h, surface,
      [&](const Vector& point) {
        return cylinder > 0 ? (point - cylinderCentre).norm() - cylinderRadius : point[1];
      },
      options);
  const auto& x = fluid.positions();
  {
    double top = -1e9, bottom = 1e9;
    for (const Vector& p : x) {
      top = std::max(top, static_cast<double>(p[1]));
      bottom = std::min(bottom, static_cast<double>(p[1]));
    }
    const double height = top - bottom + dx, ratio = height * height / area;
    double low = 1e-3, high = std::numbers::pi;  // H^2 / A of a cap grows with theta
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (low + high);
      const double value = std::pow(1 - std::cos(mid), 2) / (mid - std::sin(mid) * std::cos(mid));
      (value < ratio ? low : high) = mid;
    }
    result.heightAngle = 0.5 * (low + high) * 180 / std::numbers::pi;
  }
  const FittedSphere fit = fitSphere(surface, 2);
  const Eigen::Vector2d centre = fit.centre.head<2>();
  const double fitted = fit.radius;
  double cosine = -centre(1) / fitted;
  if (cylinder > 0) {
    const double rc = cylinderRadius;
    const double apart = (centre - Eigen::Vector2d(0, -rc)).norm();
    cosine = (fitted * fitted + rc * rc - apart * apart) / (2 * fitted * rc);
  }
  result.angle = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / std::numbers::pi;
  return result;
}

template <class Tension>
SessileResult sessileDrop3DWith(double degrees, int layers, double capillaryTimes, double bond,
                                const CapillaryOptions& options) {
  const Real sigma = 0.07, rho = 1000, nu = 1e-4, dx = 5e-4, h = 3 * dx;
  const Real ballRadius = layers * dx;
  ParticleCloud fluid = latticeFluid(
      3, dx, Vector(-ballRadius - dx, -ballRadius - dx, 0),
      Vector(ballRadius + dx, ballRadius + dx, ballRadius + dx),
      [&](const Vector& x) { return x.norm() < ballRadius; }, rho, rho * nu);
  ParticleCloud wall = floorInZ(3 * layers, dx);
  const double volume = static_cast<double>(fluid.size()) * dx * dx * dx;
  FlowSettings flow;
  if (options.slipWalls) flow.walls.all.velocity = WallCondition::Velocity::slip;
  flow.dimension = 3;
  flow.supportRadius = h;
  flow.gravity =
      Vector(0, 0, static_cast<Real>(-bond * sigma / (rho * std::cbrt(volume * volume))));
  const double radius = std::cbrt(3 * volume / (4 * std::numbers::pi));
  flow.soundSpeed = static_cast<Real>(std::sqrt(1000.0 * sigma / (rho * radius)));
  SurfaceTensionSettings tension = tensionSettings(3, h, dx, sigma);
  tension.cosContactAngle = static_cast<Real>(std::cos(degrees * std::numbers::pi / 180));
  CapillaryRun<Tension> run(flow, tension, fluid, {&wall});
  const double end = capillaryTimes * std::sqrt(rho * volume / sigma);
  std::vector<Vector> surface;
  SessileResult result = settleDrop(
      run, fluid, tension, wall, end, 2, 100, h, surface,
      [](const Vector& point) { return point[2]; }, options);
  const FittedSphere fit = fitSphere(surface, 3);
  result.angle =
      std::acos(std::clamp(-fit.centre(2) / fit.radius, -1.0, 1.0)) * 180 / std::numbers::pi;
  return result;
}

}  // namespace

StaticDropResult staticDrop(int dimension, int across, double capillaryTimes, double nu,
                            const CapillaryOptions& options) {
  return pairwise(options)
             ? staticDropWith<PairwiseForce>(dimension, across, capillaryTimes, nu, options)
             : staticDropWith<ContinuumSurfaceForce>(dimension, across, capillaryTimes, nu,
                                                     options);
}

OscillationResult oscillatingDrop(int dimension, int across, double periods,
                                  const CapillaryOptions& options) {
  return pairwise(options)
             ? oscillatingDropWith<PairwiseForce>(dimension, across, periods, options)
             : oscillatingDropWith<ContinuumSurfaceForce>(dimension, across, periods, options);
}

std::ostream& operator<<(std::ostream& out, const OscillationResult& r) {
  return out << r.particles << " particles: period / Lamb's " << r.period / r.lambPeriod
             << ", decay / the viscous " << r.decay / r.viscousDecay << ", " << r.seconds << " s";
}

ModeCurvatureResult modeCurvature(int dimension, int across, double epsilon) {
  const Real dx = 0.001, rho = 1000, sigma = 0.07;
  ParticleCloud fluid = ringFluid(dimension, dx, across / 2, rho, 1e-3);
  ModeCurvatureResult result;
  result.particles = fluid.size();
  const double R = dropRadius(dimension, fluid.size(), dx);
  // the mode's shape at a point's direction: 2D cos(2 phi), 3D P2(cos theta)
  auto mode = [&](const Vector& x) {
    if (dimension == 2) return std::cos(2 * std::atan2(double(x[1]), double(x[0])));
    const double c = x[2] / x.norm();
    return 0.5 * (3 * c * c - 1);
  };
  // the mode's potential flow as a displacement (divergence-free: the particles keep their
  // volumes): the surface r = R (1 + epsilon mode)
  const Real e = static_cast<Real>(epsilon);
  for (Vector& x : fluid.positions()) {
    x += dimension == 2 ? Vector(e * x[0], -e * x[1], 0)
                        : Vector(-e / 2 * x[0], -e / 2 * x[1], e * x[2]);
  }
  FlowSettings flow;
  flow.dimension = dimension;
  flow.supportRadius = 3 * dx;
  flow.soundSpeed = 5;
  CapillaryRun<ContinuumSurfaceForce> run(flow, tensionSettings(dimension, 3 * dx, dx, sigma),
                                          fluid, {});
  run.tension.addAcceleration();
  // kappa = kappa_0 + kappa_mode * mode, least squares over the surface particles
  const auto& kappa = fluid.scalarField(field::curvature);
  Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
  Eigen::Vector2d right = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    if (!run.tension.onSurface()[i]) continue;
    const Eigen::Vector2d row(1, mode(fluid.positions()[i]));
    normal += row * row.transpose();
    right += row * static_cast<double>(kappa[i]);
  }
  const Eigen::Vector2d fit = normal.ldlt().solve(right);
  result.meanCurvature = fit[0] * R / (dimension - 1);
  // r = R (1 + epsilon mode): kappa_mode = (n - 1)(n + 2) epsilon / R in 3D (n = 2: 4),
  // (n^2 - 1) epsilon / R in 2D (3)
  result.modeCurvature = fit[1] / ((dimension == 2 ? 3 : 4) * epsilon / R);
  return result;
}

std::ostream& operator<<(std::ostream& out, const ModeCurvatureResult& r) {
  return out << r.particles << " particles: mean curvature R / (d - 1) " << r.meanCurvature
             << ", the mode's curvature / the exact " << r.modeCurvature;
}

SessileResult sessileDrop(double degrees, int layers, double capillaryTimes, double bond,
                          double cylinder, const CapillaryOptions& options) {
  return pairwise(options) ? sessileDropWith<PairwiseForce>(degrees, layers, capillaryTimes, bond,
                                                            cylinder, options)
                           : sessileDropWith<ContinuumSurfaceForce>(degrees, layers, capillaryTimes,
                                                                    bond, cylinder, options);
}

SessileResult sessileDrop3D(double degrees, int layers, double capillaryTimes, double bond,
                            const CapillaryOptions& options) {
  return pairwise(options)
             ? sessileDrop3DWith<PairwiseForce>(degrees, layers, capillaryTimes, bond, options)
             : sessileDrop3DWith<ContinuumSurfaceForce>(degrees, layers, capillaryTimes, bond,
                                                        options);
}

GapResult gapEntry(int gap, double ratio, double capillaryTimes, double degrees,
                   const CapillaryOptions& options) {
  const Real sigma = 0.07, rho = 1000, nu = 1e-4, dx = 5e-4, h = 3 * dx;
  const int width = 40, depth = 12, pool = 10, box = 24;
  const Real halfWidth = width * dx / 2, halfGap = gap * dx / 2;
  // the fluid's domain: the box above the floor and the slot below it
  auto nearestInDomain = [&](const Vector& x) {
    auto clampTo = [&](Real lowX, Real highX, Real lowY, Real highY) {
      return Vector(std::clamp(x[0], lowX, highX), std::clamp(x[1], lowY, highY), 0);
    };
    const Vector inBox = clampTo(-halfWidth, halfWidth, 0, box * dx);
    const Vector inSlot = clampTo(-halfGap, halfGap, -depth * dx, 0);
    return (inBox - x).norm() < (inSlot - x).norm() ? inBox : inSlot;
  };
  ParticleCloud wall = emptyWall();
  for (int j = -depth - 3; j < box; ++j) {
    for (int i = -width / 2 - 3; i < width / 2 + 3; ++i) {
      const Vector x((i + Real(0.5)) * dx, (j + Real(0.5)) * dx, 0);
      const Vector nearest = nearestInDomain(x);
      const Real distance = (nearest - x).norm();
      if (!(distance > 0) || distance > 3 * dx) continue;  // in the domain, or deeper than 3 dx
      const std::size_t k = wall.size();
      wall.resize(k + 1);
      wall.positions()[k] = x;
      wall.scalarField(field::volume)[k] = dx * dx;
      wall.vectorField(field::normal)[k] = (nearest - x) / distance;
      wall.scalarField(field::wallDistance)[k] = distance;
    }
  }
  ParticleCloud fluid = latticeFluid(
      2, dx, Vector(-halfWidth, 0, 0), Vector(halfWidth, pool * dx, 0),
      [](const Vector&) { return true; }, rho, rho * nu);
  const double cosine = std::cos(degrees * std::numbers::pi / 180);
  const double entry = 2 * sigma * std::abs(cosine) / (gap * dx);
  FlowSettings flow;
  flow.dimension = 2;
  flow.supportRadius = h;
  if (options.slipWalls) flow.walls.all.velocity = WallCondition::Velocity::slip;
  const double g = ratio * entry / (rho * pool * dx);
  flow.gravity = Vector(0, static_cast<Real>(-g), 0);
  flow.soundSpeed = static_cast<Real>(
      std::max(10 * std::sqrt(2 * g * pool * dx), std::sqrt(1000.0 * entry / rho)));
  SurfaceTensionSettings tension = tensionSettings(2, h, dx, sigma);
  tension.cosContactAngle = static_cast<Real>(cosine);
  tension.gapMeniscus = options.gapMeniscus;
  CapillaryRun<ContinuumSurfaceForce> run(flow, tension, fluid, {&wall});
  const double end = capillaryTimes * std::sqrt(rho * std::pow(gap * dx, 3) / sigma);
  const auto start = std::chrono::steady_clock::now();
  while (run.time < end) run.step(run.stableDeltaT());
  GapResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.particles = fluid.size();
  std::size_t inside = 0;
  for (const Vector& x : fluid.positions()) {
    result.deepest = std::min(result.deepest, static_cast<double>(x[1] / dx));
    inside += x[1] < 0 && std::abs(x[0]) < halfGap;
  }
  result.filled = static_cast<double>(inside) / (gap * depth);
  return result;
}

}  // namespace sphcast::testing
