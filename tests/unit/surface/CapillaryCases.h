#pragma once

// Drops held by the continuum surface force (surface/ContinuumSurfaceForce.h) or the pairwise
// force (surface/PairwiseForce.h), stepped as the solver steps them: the cases that
// ContinuumSurfaceForceTest.cpp checks and that surfaceTensionStudy (tests/studies) measures.
// The studies' knobs come in CapillaryOptions, whose defaults are what the tests run.

#include <cstddef>
#include <ostream>

namespace sphcast::testing {

// The force that holds the drops (named as in physicsModels).
enum class SurfaceForceModel { continuumSurfaceForce, pairwiseForce };

struct CapillaryOptions {
  // static, oscillating and sessile drops (the gap is always the continuum surface force's)
  SurfaceForceModel model = SurfaceForceModel::continuumSurfaceForce;
  bool latticeStart = false;   // static drop: lattice particles instead of rings
  double soundSpeedScale = 1;  // static and oscillating drops: a factor on the speed of sound
  double amplitude = 0.05;     // oscillating drop: a0, the mode's amplitude over R
  bool slipWalls = false;      // sessile drops and the gap: wallSlip slip instead of no-slip
  bool gapMeniscus = false;    // the gap: Young-Laplace's curvature in a sub-kernel gap
  double startDegrees = 0;     // 2D sessile drop on a flat wall: start as a cap of this angle
                               // and the half disk's area (0: the half disk)
  bool trace = false;          // print as it runs
  bool traceFastest = false;   // sessile drops, with trace: the fastest particle's state too
};

// A drop at rest, stepped as the solver steps it: the pressure inside (the mean over the
// particles within R/2 of the centre) against Laplace's and the largest speed against the
// capillary speed sqrt(sigma / (rho R)), after `capillaryTimes` of sqrt(rho R^3 / sigma).
struct StaticDropResult {
  double pressureRatio = 0, largestSpeed = 0, meanSpeed = 0, seconds = 0;
  double closest = 0;  // the nearest pair, in spacings
  std::size_t particles = 0;
};

StaticDropResult staticDrop(int dimension, int across, double capillaryTimes, double nu,
                            const CapillaryOptions& options = {});

// The n = 2 oscillation of a free drop of rings (no gravity), water-like (rho 1000 kg/m^3,
// sigma 0.07 N/m, nu 8e-6 m^2/s, R = 1 cm: Ohnesorge 0.01), started at Laplace's pressure with
// the mode's potential flow (2D: u = A (x, -y); 3D: u = A (-x, -y, 2 z)), A = a0 omega (a0 =
// options.amplitude, 0.05: the surface moves 0.05 R in 2D, 0.1 R in 3D); the
// period from the zero crossings of the second moment about its mean, against Lamb (1932):
//   2D: omega^2 = 6 sigma / (rho R^3),   3D: omega^2 = 8 sigma / (rho R^3),
// and the amplitude's decay rate from its successive extremes, against the viscous one
//   2D: 4 nu / R^2,   3D: 5 nu / R^2.
struct OscillationResult {
  std::size_t particles = 0;
  double period = 0, lambPeriod = 0, decay = 0, viscousDecay = 0, seconds = 0;
};

OscillationResult oscillatingDrop(int dimension, int across, double periods,
                                  const CapillaryOptions& options = {});

std::ostream& operator<<(std::ostream& out, const OscillationResult& r);

// The curvature the continuum surface force reads on the n = 2 mode, without dynamics: a drop of
// rings (R/dx = across / 2) displaced by the mode's potential flow to r = R (1 + epsilon P),
// P = cos(2 phi) in 2D, P2(cos theta) in 3D, then kappa = kappa_0 + kappa_P P fitted over its
// surface particles: kappa_0 against (d - 1) / R and kappa_P against the exact 3 epsilon / R (2D)
// or 4 epsilon / R (3D). The mode's stiffness, and Lamb's omega^2, go as kappa_P.
struct ModeCurvatureResult {
  std::size_t particles = 0;
  double meanCurvature = 0, modeCurvature = 0;
};

ModeCurvatureResult modeCurvature(int dimension, int across, double epsilon);

std::ostream& operator<<(std::ostream& out, const ModeCurvatureResult& r);

// A 2D drop on a flat wall (its surface y = 0, three layers below) held by a little gravity
// (Bond number rho g A / sigma = 0.2, A the drop's area: the cap stays nearly circular),
// started as the lattice particles of a half disk of radius `layers` dx (a 90-degree cap) and
// settled over `capillaryTimes` of sqrt(rho A^(3/2) / sigma) by viscosity (nu 1e-4: the
// equilibrium does not depend on it). The angle from a circle fitted (least squares) to the
// surface, each outer particle (depth under 0.8 dx) moved out along its normal by its depth,
// above h from the wall: cos theta = -y_centre / R. The surface is read by the continuum
// surface force's detection whatever model held the drop.
struct SessileResult {
  double angle = 0, seconds = 0, lowest = 0, closest = 0;
  double heightAngle = 0;  // 2D: theta of the circular cap of the drop's height and area
  std::size_t particles = 0;
};

// With `cylinder` > 0 the wall is a cylinder (a circle in 2D) of that many times the cap's
// radius, its top at y = 0 (three rings of particles a spacing apart), and the drop the particles
// of rings round it a spacing apart within the cap's radius of the top; the angle then from the
// fitted circle and the cylinder's, cos theta = (R^2 + R_c^2 - D^2) / (2 R R_c), D between
// their centres.
SessileResult sessileDrop(double degrees, int layers, double capillaryTimes, double bond,
                          double cylinder = 0, const CapillaryOptions& options = {});

// The same in 3D: the lattice particles of a half ball of radius `layers` dx on a floor
// (floorInZ), Bond rho g V^(2/3) / sigma, capillary times of sqrt(rho V / sigma); the angle from a
// sphere fitted to the surface more than h above the floor, cos theta = -z_centre / R.
SessileResult sessileDrop3D(double degrees, int layers, double capillaryTimes, double bond,
                            const CapillaryOptions& options = {});

// A non-wetting liquid over a gap (2D): a pool 40 dx wide and 10 dx deep in a box of walls,
// over a slot `gap` dx wide and 12 dx deep in its floor, all walls at `degrees`; gravity sets
// the pressure at the slot's mouth, rho g H, to `ratio` times the capillary entry pressure
// 2 sigma |cos theta| / w (Young-Laplace: the meniscus across a slot of width w has the radius
// w / (2 |cos theta|)). Below 1 the liquid should stay out of the slot, above 1 fill it. Read
// after `capillaryTimes` of sqrt(rho w^3 / sigma): the slot's filled fraction and the deepest
// particle.
struct GapResult {
  double filled = 0, deepest = 0, seconds = 0;
  std::size_t particles = 0;
};

GapResult gapEntry(int gap, double ratio, double capillaryTimes, double degrees,
                   const CapillaryOptions& options = {});

}  // namespace sphcast::testing
