#pragma once

// Drops held by the surface-energy model (surface/SurfaceEnergyTension.h), stepped as the solver
// steps them: the case that OscillatingDropletTest.cpp checks and those that surfaceTensionStudy
// (tests/studies) measures. Each takes its knobs in a setup struct whose defaults are what the
// tests run.
//
// The n = 2 oscillation of a free droplet (no gravity) against Lamb (1932, §275, §355):
//   2D: omega^2 = n (n^2 - 1) sigma / (rho R^3),   3D: omega^2 = n (n - 1)(n + 2) sigma / (rho R^3)
// with the viscous decay of the amplitude, exp(-gamma t),
//   2D: gamma = 2 n (n - 1) nu / R^2,              3D: gamma = (n - 1)(2 n + 1) nu / R^2
// (the dissipation of the potential flow of the mode, valid while gamma << omega).
// The droplet starts round, on the lattice, at the Laplace pressure; its staircase surface
// relaxes with damped velocities first; then it gets the velocity of the mode's potential flow
// (2D: u = A (x, -y); 3D: u = A (-x, -y, 2 z)), and the amplitude is read from the second moments
// of the particle positions, about their mean over the run (a relaxed 3D drop keeps an offset
// as large as the mode, so its moment never crosses zero; doc/validation.md §2). Also the
// static drop's pressure against Laplace's jump, and the contact angle of a drop on a wall.

#include <cstddef>
#include <ostream>
#include <string>

#include "core/Real.h"

namespace sphcast::testing {

struct DropletResult {
  std::size_t particles = 0;
  double radius = 0;
  double lambPeriod = 0, period = 0;  // s
  double lambDecay = 0, decay = 0;    // 1/s
  double steps = 0, seconds = 0;
  double largestDensityDeviation = 0;
  double offset = 0;  // the mean of the n = 2 moment (m^2) over the run, over R
};

struct DropletSetup {
  int dimension = 2;
  int across = 30;          // particles across the diameter
  Real energyFactor = 0;    // R_d (0: calibrated)
  double periods = 2.0;     // how long to run
  double amplitude = 0.05;  // a0 / R
  // the pressure of the surface layer's pull, R_d Gamma / dx, against rho c^2 (sets c)
  double surfaceCompression = 0.01;
  double core = 1;
  double relaxation = 2;        // capillary times sqrt(rho R^3 / sigma) of damped relaxation first
  double hOverDx = 3;           // h / dx
  std::string densityScheme;    // the flow's densityScheme ("": its default)
  bool densityCoupling = true;  // false: the model without its density coupling
  long traceEvery = 0;          // > 0: print the amplitude and energies every that many steps
};

DropletResult oscillatingDroplet(const DropletSetup& setup);

std::ostream& operator<<(std::ostream& out, const DropletResult& r);

// A droplet at rest, round, relaxed under its surface tension: the pressure inside (the mean
// over the inner half of the radius) against Laplace's jump, and the largest velocity left.
// With `slab`, a periodic flat slab instead of the drop: prints its mechanical tension
// (slabTension) at the start and averaged over one capillary time after the relaxation.
struct StaticDropletSetup {
  int dimension = 2;
  int across = 20;            // particles across the diameter (the slab's thickness)
  double relaxation = 4;      // capillary times sqrt(rho R^3 / sigma)
  Real core = 1;              // r0 / dx
  double compression = 0.01;  // R_d Gamma / (rho c^2 dx): sets c
  double hOverDx = 3;
  bool densityCoupling = true;
  bool slab = false;
  double slabPeriod = 0;  // the slab's period along x (and z), in spacings; 0: across + 2
};

struct StaticDropletResult {
  std::size_t particles = 0;
  double radius = 0, laplace = 0, jump = 0, spuriousVelocity = 0, capillaryVelocity = 0;
  double steps = 0, seconds = 0;
  double energyRatio = 0;  // E_s against Gamma times the surface's length (area in 3D)
};

StaticDropletResult staticDroplet(const StaticDropletSetup& setup);

// A 2D drop settling on a flat wall should reach the contact angle of Young's law,
// cos theta = -Gamma_s / Gamma_g, read from a circle fitted to its surface particles and, for
// comparison, from its height H and area A (a circular cap has H^2 / A = (1 - cos theta)^2 /
// (theta - sin theta cos theta)). The model does not reach the angles (doc/validation.md §2.3).
struct SettledDrop {
  double angle = 0;        // degrees, from the fitted circle
  double heightAngle = 0;  // degrees, from the height and area of a circular cap
  double steps = 0, seconds = 0;
  double closest = 0;     // nearest pair, in spacings
  bool detached = false;  // the circle's centre lies higher than its radius
};

struct WallDropSetup {
  double degrees = 90;           // the contact angle set
  int width = 24, height = 12;   // the block's particles (its area the drop's)
  double capillaryTimes = 12;    // of sqrt(rho A^(3/2) / sigma)
  Real damping = Real(0.99995);  // velocity factor a step (0.9995 held the drops where they
                                 // started)
  double startAngle = 0;         // > 0: start as the lattice particles of a cap of that angle
  double bond = 0;               // rho g A / sigma: gravity towards the wall keeps the drop on it
};

// A block of width x height particles on a wall at y = 0, or (startAngle > 0) the lattice
// particles of a circular cap of that angle and the block's area, settled with its velocities
// damped (multiplied by `damping` every step).
SettledDrop settleOnWall(const WallDropSetup& setup);

}  // namespace sphcast::testing
