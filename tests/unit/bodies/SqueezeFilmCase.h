#pragma once

// The squeeze film of doc/validation.md §1.7, which SqueezeFilmTest.cpp checks and
// squeezeFlowStudy (tests/studies) runs where the unit tests cannot afford it: a 2D plate
// (a rigid body, steel) over a liquid on a floor, its face 8 mm above the floor, no gravity, so
// that its load is the squeeze alone. At refinement r the spacing is 1 mm / r, the geometry the
// same.
//
// Lubrication (Engmann, Servais & Burbidge 2005, J. Non-Newt. Fluid Mech. 132:1, in plane
// strain): for a liquid tau = k gammaDot^n in a gap h of half-width R, a pressure gradient G
// drives q = 2 n/(2n+1) (G/k)^(1/n) (h/2)^((2n+1)/n) per unit depth; with q(x) = V x,
//   F = 2 k C V^n R^(n+2) / ((n+2) (h/2)^(2n+1)),  C = ((2n+1)/(2n))^n,
// per unit depth, and under a constant F the gap closes at
//   V(h) = [F (n+2) (h/2)^(2n+1) / (2 k C R^(n+2))]^(1/n).
// n = 1 is Reynolds' F = 8 mu V R^3 / h^3. R is the plate's half-width a over a pool and in a
// filled gap, or A / 2h for a slug of area A per unit depth spreading under a wider plate.

#include <functional>
#include <memory>
#include <optional>

#include "bodies/RigidBody.h"
#include "particles/Neighbourhood.h"
#include "rheology/HerschelBulkley.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast::testing {

// A pool filling the tank (160 mm) to the plate's top round a plate 120 mm wide (a = 60 mm
// fixed); a slug 60 x 8 mm filling the gap's middle under a plate 140 mm wide; or the gap
// filled (a constant-area squeeze, as a squeeze-flow rheometer runs it): liquid only between
// the plate and a floor exactly as wide (120 mm, a = 60 mm fixed), squeezed out past both edges
// into empty space, so that the pressure at the edges is the free surface's, lubrication's p(a)
// = 0. Over the pool the liquid leaving the gap has to push the pool aside, which lubrication
// leaves out.
enum class Liquid { pool, slug, gapFilled };

const char* nameOf(Liquid liquid);

struct SqueezeFilmCase {
  // the plate's motion (a prescribed displacement or a dynamic body on the y axis), settings
  // still to add to plateSettings()
  // (incompressible: flow { model incompressible; }, the plate coupled within its solve)
  SqueezeFilmCase(const RigidBodySettings& bodySettings, double refinement, Liquid liquid,
                  bool incompressible = false);

  // One step of the flow's stable length, as the solver takes it with a body; returns its length.
  double step(double time);
  double gap() const;  // m
  // the plate's half-width
  double halfWidth() const;

  Liquid liquid;
  int plateColumns;  // at refinement 1
  double refinement;
  Real dx;
  ParticleCloud fluid, tank, plate;
  FlowSettings flowSettings;
  std::optional<Neighbourhood> neighbourhood;
  std::optional<RigidBody> body;
  std::optional<WeaklyCompressibleFlow> flow;
  std::unique_ptr<RheologyModel> rheology;  // when set, the liquid's viscosity law
  double clearanceForce = 0;  // the wall clearance's impulse on the plate over the last step
  double lastDeltaT = 0;      // the step grows by 1.2 at most, as the solver's

 private:
  int spacings(int millimetres) const;  // a length given in mm, in spacings, rounded
  int first() const;                    // the plate's first column
};

// The plate as a body (density of steel), with the motion's settings still to set.
RigidBodySettings plateSettings();

// A shear-thinning liquid: a power law tau = k gammaDot^(1/2), capped at mu0 = 100 Pa s where
// the shear rate vanishes on the gap's middle line, solved implicitly.
HerschelBulkleySettings halfPowerLaw(double consistency);

// The times the plate, pressed by `load` N/m, takes to close its gap from 6 mm to 5 and to 4 mm
// (from 8 mm), over lubrication's (above, integrated over the gap); law: the liquid's, or none
// for a Newtonian liquid of 1 Pa s.
struct ClosingTimes {
  double to5, to4;        // SPH over lubrication
  double lubricationTo4;  // s
  double seconds;         // the whole run's, wall-clock
};
ClosingTimes closingTimes(Liquid liquid, double load, double refinement,
                          const std::optional<HerschelBulkleySettings>& law = std::nullopt,
                          bool incompressible = false);

}  // namespace sphcast::testing
