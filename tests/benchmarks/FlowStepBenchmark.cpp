// One kick-drift-kick step of the weakly compressible flow (neighbour lists, reorder, Riemann
// interface, Morris viscosity, gravity) on a 3D periodic block of fluid with h = 3 dx
// (~107 neighbours), at 1e4..1e6 particles. The fluid streams at 1 m/s (a casting's speed) with
// the acoustic step (maxCo 0.25), so that, as in a real run, some particles change cell every
// step and the cloud is reordered. Reports particle-steps/s (items) and pair interactions/s
// (counter "pairs").
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "particles/FieldNames.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace {

namespace field = sphcast::field;

using sphcast::Real;
using sphcast::Vector;

sphcast::ParticleCloud periodicBlock(int perSide, Real dx, Real viscosity) {
  sphcast::ParticleCloud fluid("fluid");
  fluid.resize(static_cast<std::size_t>(perSide) * perSide * perSide);
  auto& U = fluid.addVectorField(field::U);
  auto& rho = fluid.addScalarField(field::rho);
  auto& mass = fluid.addScalarField(field::mass);
  auto& mu = fluid.addScalarField(field::viscosity);
  auto& rest = fluid.addScalarField(field::restDensity);
  std::size_t i = 0;
  for (int k = 0; k < perSide; ++k) {
    for (int j = 0; j < perSide; ++j) {
      for (int l = 0; l < perSide; ++l, ++i) {
        fluid.positions()[i] =
            Vector((l + Real(0.5)) * dx, (j + Real(0.5)) * dx, (k + Real(0.5)) * dx);
        U[i] = Vector(1 + Real(0.01) * std::sin(Real(0.1) * Real(i)), 0, 0);
        rho[i] = rest[i] = 2400;
        mass[i] = 2400 * dx * dx * dx;
        mu[i] = viscosity;
      }
    }
  }
  fluid.attributes()["spacing"] = double(dx);
  return fluid;
}

// One step of the scheme named by densityScheme, with or without the kernel correction (which
// adds a pass over every pair for the correction matrices; deltaSPH adds that pass for its
// renormalised density gradient and two terms per pair).
void FlowStep(benchmark::State& state, const char* densityScheme, bool kernelCorrection,
              Real neighbourListSkin = sphcast::FlowSettings().neighbourListSkin,
              Real viscosity = Real(1.28e-3),
              sphcast::ViscositySolver solver = sphcast::ViscositySolver::automatic) {
  const int perSide = static_cast<int>(std::lround(std::cbrt(double(state.range(0)))));
  const Real dx = Real(1.25e-3);
  auto fluid = periodicBlock(perSide, dx, viscosity);
  sphcast::FlowSettings settings;
  settings.dimension = 3;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = 50;
  settings.gravity = Vector(0, 0, Real(-9.81));
  settings.densityScheme = densityScheme;
  settings.kernelCorrection = kernelCorrection;
  settings.neighbourListSkin = neighbourListSkin;
  settings.viscositySolver = solver;
  for (int axis = 0; axis < 3; ++axis) settings.periodic.setPeriodic(axis, 0, perSide * dx);
  sphcast::WeaklyCompressibleFlow flow(settings, fluid, {});
  std::string limiter;
  // the acoustic step: an explicit step of a mush this long is unstable, but costs the same
  const double deltaT = flow.stepLimits(0.25).acoustic;
  for (auto _ : state) flow.step(deltaT);
  state.SetItemsProcessed(state.iterations() * static_cast<long>(fluid.size()));
  state.counters["pairs"] = benchmark::Counter(
      double(flow.fluidPairCount()) * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["particles"] = double(fluid.size());
  if (flow.work().implicitViscousSteps > 0) {
    state.counters["iterations"] =
        double(flow.work().viscousIterations) / double(flow.work().implicitViscousSteps);
  }
}
// 1e4 to 1e6 by half decades: the cost against N (costAgainstParticles plots it)
BENCHMARK_CAPTURE(FlowStep, riemann, "riemann", false)
    ->Arg(10'000)
    ->Arg(30'000)
    ->Arg(100'000)
    ->Arg(300'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// the pair lists searched at every step (no skin), as before issue #25
BENCHMARK_CAPTURE(FlowStep, riemannSearchEveryStep, "riemann", false, Real(0))
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(FlowStep, riemannCorrected, "riemann", true)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(FlowStep, deltaSPH, "deltaSPH", false)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// A mush of 1e4 Pa s at the acoustic step (320 explicit viscous limits): the step with the
// viscosity in the rates (what an explicit step costs; it would be unstable) against the step
// with the implicit solve (counter "iterations": the conjugate gradient's per step).
BENCHMARK_CAPTURE(FlowStep, mush1e4Explicit, "riemann", false,
                  sphcast::FlowSettings().neighbourListSkin, Real(1e4),
                  sphcast::ViscositySolver::explicitForm)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(FlowStep, mush1e4Implicit, "riemann", false,
                  sphcast::FlowSettings().neighbourListSkin, Real(1e4),
                  sphcast::ViscositySolver::implicitForm)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
