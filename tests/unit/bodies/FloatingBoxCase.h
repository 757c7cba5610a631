#pragma once

// Archimedes' floating box (doc/validation.md §1.7): the case that ArchimedesTest.cpp checks in
// 2D and floatingBodyStudy (tests/studies) runs in 3D. A box of densityRatio times the liquid's
// density, let go a spacing above a tank of still (viscous: it settles in 0.5 s) liquid, should
// settle at the draft (rho_b / rho_l) x its height and stay where it was put sideways (free to
// translate and to turn). The box's surface is half a spacing beyond its outer particles, as the
// liquid's free surface lies half a spacing above its top particles.

namespace sphcast::testing {

struct Floating {
  double draftError;  // (draft - exact) / dx, over the last 0.2 s, largest
  double drift;       // largest sideways travel of the centre, in dx
  double tilt;        // largest turn, degrees
};

// The tank 120 mm wide (and deep, in 3D) with 48 mm of liquid, the box 32 mm wide (and deep) and
// 16 mm high, at spacing 0.002 x coarsening, its centre offsetColumns spacings off the tank's
// in x, afloat for `seconds`. Up is y in 2D, z in 3D. incompressible: flow { model
// incompressible; } (the bodies kicked and drifted by the step's hooks).
Floating floatBox(int dimension, double densityRatio, double seconds, int coarsening,
                  int offsetColumns = 0, bool incompressible = false);

}  // namespace sphcast::testing
