// A study, not a check (the model does not reach the angles: doc/validation.md §2): a 2D drop
// settling on a flat wall should reach the contact angle of Young's law,
// cos theta = -Gamma_s / Gamma_g, read from a circle fitted to its surface particles and, for
// comparison, from its height H and area A (a circular cap has H^2 / A = (1 - cos theta)^2 /
// (theta - sin theta cos theta)). Run by hand: SPHCAST_CONTACT_STUDY=<particles across the
// block> [SPHCAST_CONTACT_TIMES=<capillary times, 12>] [SPHCAST_CONTACT_DAMPING=<velocity
// factor a step, 0.99995; 0.9995 held the drops near where they started>]
// [SPHCAST_CONTACT_ANGLES="90 120 150 180"] [SPHCAST_CONTACT_START=<degrees: start from a cap
// of that angle; 0, the block, by default>] [SPHCAST_CONTACT_BOND=<rho g A / sigma, A the
// drop's area: gravity towards the wall, which keeps the drop on it; 0 by default>].

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <sstream>
#include <vector>

#include <Eigen/Dense>

#include "SurfaceTensionTestCases.h"
#include "sph/FlowTestCases.h"

namespace sphcast {
namespace {

using testing::CapillaryRun;
using testing::capillarySoundSpeed;
using testing::latticeFluid;
using testing::tensionSettings;

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

struct SettledDrop {
  double angle = 0;        // degrees, from the fitted circle
  double heightAngle = 0;  // degrees, from the height and area of a circular cap
  double steps = 0, seconds = 0;
  double closest = 0;     // nearest pair, in spacings
  bool detached = false;  // the circle's centre lies higher than its radius
};

// A block of width x height particles on a wall at y = 0, or (startAngle > 0) the lattice
// particles of a circular cap of that angle and the block's area, settled with its velocities
// damped (multiplied by `damping` every step).
SettledDrop settle(double degrees, int width, int height, double capillaryTimes, Real damping,
                   double startAngle) {
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
  ParticleCloud wall = testing::emptyWall();
  const int reach = width;  // the wall runs a drop's width beyond either side
  testing::addWallCells(
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
  if (const char* bond = std::getenv("SPHCAST_CONTACT_BOND")) {
    const double area = static_cast<double>(fluid.size()) * dx * dx;
    flow.gravity = Vector(0, static_cast<Real>(-std::atof(bond) * sigma / (rho * area)), 0);
  }
  CapillaryRun run(flow, tension, fluid, {&wall});
  const double area = static_cast<double>(fluid.size()) * dx * dx;
  const double end = capillaryTimes * std::sqrt(rho * std::pow(std::sqrt(area), 3) / sigma);
  SettledDrop result;
  const auto start = std::chrono::steady_clock::now();
  while (run.time < end) {
    run.step(run.stableDeltaT());
    for (Vector& u : fluid.vectorField("U")) u *= damping;
    ++result.steps;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The cap's circle, fitted (least squares, x^2 + y^2 + D x + E y + F = 0) to the surface
  // particles (surfaceEnergy above a tenth of its largest) more than h from the wall, and moved
  // out by dx / 2 (the surface lies half a spacing beyond the particles' centres): with the
  // wall surface at y = 0, cos theta = -y_centre / R. A centre higher than R is a drop that
  // has left the wall.
  const auto& x = fluid.positions();
  const auto& energy = fluid.scalarField("surfaceEnergy");
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

TEST(ContactAngle, Study) {
  if (!std::getenv("SPHCAST_CONTACT_STUDY")) GTEST_SKIP() << "set SPHCAST_CONTACT_STUDY";
  const int width = std::atoi(std::getenv("SPHCAST_CONTACT_STUDY"));
  const double times =
      std::getenv("SPHCAST_CONTACT_TIMES") ? std::atof(std::getenv("SPHCAST_CONTACT_TIMES")) : 12;
  std::vector<double> angles{90, 120, 150, 180};
  if (const char* list = std::getenv("SPHCAST_CONTACT_ANGLES")) {
    angles.clear();
    std::istringstream in(list);
    for (double a = 0; in >> a;) angles.push_back(a);
  }
  for (const double degrees : angles) {
    const Real damping = static_cast<Real>(std::getenv("SPHCAST_CONTACT_DAMPING")
                                               ? std::atof(std::getenv("SPHCAST_CONTACT_DAMPING"))
                                               : 0.99995);
    const double start =
        std::getenv("SPHCAST_CONTACT_START") ? std::atof(std::getenv("SPHCAST_CONTACT_START")) : 0;
    const SettledDrop drop = settle(degrees, width, width / 2, times, damping, start);
    std::cout << "theta " << degrees << ": measured " << drop.angle << " degrees (fitted circle"
              << (drop.detached ? ", left the wall" : "") << "; from the height "
              << drop.heightAngle << "), nearest pair " << drop.closest << " dx, " << drop.steps
              << " steps in " << drop.seconds << " s" << std::endl;
  }
}

}  // namespace
}  // namespace sphcast
