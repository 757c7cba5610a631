// A drop at rest under its surface tension for 10^5 steps (2D, 20 particles across, no gravity,
// the default settings): it keeps its particles apart (no pair closer than half a spacing: the
// paper's kernel clumps pairs within 0.03 s, SurfaceEnergyTension.h), its size (no particle
// farther than R + 2 dx from the centre: none escapes the surface), its density (within 1 %)
// and stays finite.

#include <gtest/gtest.h>

#include <cmath>

#include "SurfaceTensionTestCases.h"
#include "particles/FieldNames.h"

namespace sphcast {
namespace {

TEST(DropletStability, AtRestForAHundredThousandSteps) {
  const Real radius = 0.01, sigma = 0.07, rho = 1000, nu = 1e-5;
  const int across = 20;
  const Real dx = 2 * radius / across, h = 3 * dx;
  ParticleCloud fluid = testing::latticeFluid(
      2, dx, Vector::Constant(-radius - dx), Vector::Constant(radius + dx),
      [&](const Vector& x) { return x.norm() < radius; }, rho, rho * nu);
  FlowSettings flow;
  flow.dimension = 2;
  flow.supportRadius = h;
  const SurfaceTensionSettings tension = testing::tensionSettings(2, h, dx, sigma);
  // c from R_d Gamma / (rho c^2 dx) = 1 %, as the tutorials choose it
  flow.soundSpeed = testing::capillarySoundSpeed(
      SurfaceEnergyTension::calibratedEnergyFactor(2, h, dx, 1), sigma, dx, rho, Real(0.01));
  testing::CapillaryRun run(flow, tension, fluid, {});
  const auto& x = fluid.positions();
  double closest = 1e9, farthest = 0, densityDeviation = 0;
  for (long step = 1; step <= 100000; ++step) {
    run.step(run.stableDeltaT());
    if (step % 1000 != 0) continue;
    Vector centre = Vector::Zero();
    for (const Vector& xi : x) centre += xi;
    centre /= static_cast<Real>(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      ASSERT_TRUE(x[i].allFinite()) << "step " << step;
      farthest = std::max(farthest, static_cast<double>((x[i] - centre).norm()));
      densityDeviation =
          std::max(densityDeviation, std::abs(fluid.scalarField(field::rho)[i] / rho - 1.0));
      for (const std::uint32_t j : run.neighbourhood.pairs(fluid, fluid).of(i)) {
        closest = std::min(closest, static_cast<double>((x[i] - x[j]).norm()));
      }
    }
  }
  std::cout << "after " << run.time << " s ("
            << run.time / std::sqrt(rho * std::pow(radius, 3) / sigma)
            << " capillary times): nearest pair " << closest / dx << " dx, farthest "
            << farthest / radius << " R, largest density deviation " << 100 * densityDeviation
            << " %" << std::endl;
  EXPECT_GT(closest, 0.5 * dx);
  EXPECT_LT(farthest, radius + 2 * dx);
  EXPECT_LT(densityDeviation, 0.01);
}

}  // namespace
}  // namespace sphcast
