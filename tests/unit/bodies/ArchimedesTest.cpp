// Archimedes (doc/validation.md §1.7): a box of density 0.5 and 0.7 of the liquid's, let go a
// spacing above a tank of still (viscous: it settles in 0.5 s) liquid, settles at the draft
// (rho_b / rho_l) x its height, within 0.5 dx, and stays where it was put sideways (free to
// translate and to turn): in 2D over 1.5 s, and off-centre over 10 s (the case: FloatingBoxCase.h).
// The 3D box is floatingBodyStudy's (tests/studies/FloatingBodyStudy.cpp), run by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "FloatingBoxCase.h"

namespace sphcast {
namespace {

using testing::floatBox;
using testing::Floating;

// At dx = 4 mm (the box 8 x 4 particles; 2 x 7 s on 1 thread). Measured at 2 mm (16 x 8): the
// draft 0.21 dx (0.5) and 0.17 dx (0.7) short, no drift, no tilt (doc/validation.md §1.7).
TEST(Archimedes, BoxesFloatAtTheirDraft) {
  for (const double ratio : {0.5, 0.7}) {
    const Floating box = floatBox(2, ratio, 1.5, 2);
    std::printf("density ratio %.1f: draft error %.3f dx, drift %.3f dx, tilt %.3f degrees\n",
                ratio, box.draftError, box.drift, box.tilt);
    EXPECT_LT(std::abs(box.draftError), 0.5) << "density ratio " << ratio;
    EXPECT_LT(box.drift, 2.0) << "density ratio " << ratio;
  }
}

// flow { model incompressible; }: the box coupled to the pressure solve (its velocity at the
// step's end predicted from the pressure's load at every iteration). Measured: the draft
// 0.28 dx (0.5) and 0.22 dx (0.7) off over the last 0.2 s, no drift (2 s on one thread). Kicked
// by the solve's loads only after it (explicit coupling), the light box
// never settled: its load swung between 0 and 2.8 times its weight, the draft 0.81 dx off at 3 s
// (the liquid it moves weighs more than it: the added-mass instability).
TEST(Archimedes, BoxesFloatAtTheirDraftOnAnIncompressibleLiquid) {
  for (const double ratio : {0.5, 0.7}) {
    const Floating box = floatBox(2, ratio, 1.5, 2, 0, true);
    std::printf("incompressible, density ratio %.1f: draft error %.3f dx, drift %.3f dx, tilt "
                "%.3f degrees\n",
                ratio, box.draftError, box.drift, box.tilt);
    EXPECT_LT(std::abs(box.draftError), 0.5) << "density ratio " << ratio;
    EXPECT_LT(box.drift, 2.0) << "density ratio " << ratio;
  }
}

// Ten seconds afloat, let go 4 spacings off the tank's centre (nothing pulls it back or
// pushes it on: any drift is the method's), at dx = 4 mm: within 2 dx sideways, at its draft.
// Measured: 1.30 dx of drift at most, 3.6 degrees of tilt, the draft 0.07 dx high (38 s).
TEST(Archimedes, FloatsInPlaceForTenSecondsOffCentre) {
  const Floating box = floatBox(2, 0.5, 10, 2, 4);
  std::printf("10 s off-centre: draft error %.3f dx, drift %.3f dx, tilt %.3f degrees\n",
              box.draftError, box.drift, box.tilt);
  EXPECT_LT(std::abs(box.draftError), 0.5);
  EXPECT_LT(box.drift, 2.0);
}

}  // namespace
}  // namespace sphcast
