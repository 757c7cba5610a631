// A study, not a check (the model does not reach the angles yet: doc/validation.md §2): a 2D
// drop settling on a flat wall without gravity should reach the contact angle of Young's law,
// cos theta = -Gamma_s / Gamma_g, measured from its height H and area A, which for a circular
// cap give H^2 / A = (1 - cos theta)^2 / (theta - sin theta cos theta). Run by hand:
// SPHCAST_CONTACT_STUDY=<particles across the block> [SPHCAST_CONTACT_TIMES=<capillary times,
// 12>] [SPHCAST_CONTACT_DAMPING=<velocity factor a step, 0.9995>].

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>

#include "SurfaceTensionTestCases.h"
#include "sph/FlowTestCases.h"

namespace sphcast {
namespace {

using testing::CapillaryRun;
using testing::constantTension;
using testing::latticeFluid;

// theta of a circular cap from H^2 / A (bisection: the ratio grows with theta).
double capAngle(double height, double area) {
  const double ratio = height * height / area;
  double low = 1e-3, high = std::numbers::pi;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (low + high);
    const double value =
        std::pow(1 - std::cos(mid), 2) / (mid - std::sin(mid) * std::cos(mid));
    (value < ratio ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

struct SettledDrop {
  double angle = 0;  // degrees
  double steps = 0, seconds = 0;
  double closest = 0;  // nearest pair, in spacings
};

// A block of width x height particles on a wall at y = 0, settled with its velocities damped
// (multiplied by `damping` every step).
SettledDrop settle(double degrees, int width, int height, double capillaryTimes, Real damping) {
  const Real sigma = 0.07, rho = 1000, nu = 1e-5, dx = 5e-4, h = 3 * dx;
  ParticleCloud fluid = latticeFluid(
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
  SurfaceTensionSettings tension;
  tension.dimension = 2;
  tension.supportRadius = h;
  tension.spacing = dx;
  tension.gasTension = constantTension(sigma);
  tension.cosContactAngle = static_cast<Real>(std::cos(degrees * std::numbers::pi / 180));
  const Real factor = SurfaceEnergyTension::calibratedEnergyFactor(2, h, dx, 1);
  flow.soundSpeed = std::sqrt(factor * sigma / (dx * rho * Real(0.01)));
  CapillaryRun run(flow, tension, fluid, {&wall});
  const double area = static_cast<double>(fluid.size()) * dx * dx;
  const double end =
      capillaryTimes * std::sqrt(rho * std::pow(std::sqrt(area), 3) / sigma);
  SettledDrop result;
  const auto start = std::chrono::steady_clock::now();
  while (run.time < end) {
    run.step(run.stableDeltaT());
    for (Vector& u : fluid.vectorField("U")) u *= damping;
    ++result.steps;
  }
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double top = 0;
  for (const Vector& x : fluid.positions()) top = std::max(top, static_cast<double>(x[1]));
  result.angle = capAngle(top + 0.5 * dx, area) * 180 / std::numbers::pi;
  result.closest = 1e9;
  const auto& x = fluid.positions();
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
  for (const double degrees : {60.0, 90.0, 150.0, 180.0}) {
    const Real damping = static_cast<Real>(
        std::getenv("SPHCAST_CONTACT_DAMPING") ? std::atof(std::getenv("SPHCAST_CONTACT_DAMPING"))
                                               : 0.9995);
    const SettledDrop drop = settle(degrees, width, width / 2, times, damping);
    std::cout << "theta " << degrees << ": measured " << drop.angle << " degrees, nearest pair "
              << drop.closest << " dx, " << drop.steps << " steps in " << drop.seconds << " s"
              << std::endl;
  }
}

}  // namespace
}  // namespace sphcast
