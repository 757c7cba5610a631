// The two viscous forms on a lattice (h = 3 dx) applied to v = (y (L - y), 0, 0), whose exact
// nu Laplacian(v) is (-2 nu, 0, 0): the measured ratios back the comment in FlowRates.h.
#include <gtest/gtest.h>

#include "FlowTestCases.h"
#include "particles/FieldNames.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {
namespace {

double interiorLaplacianRatio(const std::string& viscousForm) {
  const int rows = 20;
  const int columns = 8;
  const Real width = 1e-3;
  const Real dx = width / rows;
  auto fluid = testing::fluidBlock2D(columns, rows, dx, Vector::Zero(), 1000, 1e-3);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Real y = fluid.positions()[i].y();
    fluid.vectorField(field::U)[i] = Vector(y * (width - y), 0, 0);
  }
  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = 1;
  settings.viscousForm = viscousForm;
  settings.periodic.setPeriodic(0, 0, columns * dx);
  settings.periodic.setPeriodic(1, -width, 3 * width);  // far from any wall: interior only
  WeaklyCompressibleFlow flow(settings, fluid, {});
  // A particle in the middle rows: its neighbourhood is full and the profile is exact there.
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    if (std::abs(fluid.positions()[i].y() - Real(10.5) * dx) < dx / 4) {
      return fluid.vectorField(field::acceleration)[i].x() / (-2 * 1e-6);
    }
  }
  return 0;
}

TEST(ViscousOperator, MorrisFormGivesTheLaplacianOnALattice) {
  EXPECT_NEAR(interiorLaplacianRatio("Morris"), 1.0, 0.01);
}

TEST(ViscousOperator, ClearyFormFallsTwelvePercentShortOnALatticeWithThreeSpacingSupport) {
  EXPECT_NEAR(interiorLaplacianRatio("Cleary"), 0.882, 0.005);
}

}  // namespace
}  // namespace sphcast
