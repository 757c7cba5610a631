// The heat transfer of a casting step, 3D, h = 3 dx (~110 neighbours): an AC4CH-like block in
// an iron cup (conduction in both, contact between them, air and radiation on the exposed
// faces), at 1e4..1e5 metal particles.
//   HeatStep/<paths>: one step of the energy equation alone (halfKick, rates, halfKick),
//     particles at rest, as the solver steps a thermal-only case (the exposed area, computed
//     once, does not change).
//   FlowAndHeatStep: the solver's step order (CastingSolver::evolve) for a flow of the block
//     (periodic, streaming as in flowStepBenchmark) with conduction in it: what heat adds to
//     the flow's step, against FlowStep/riemann of flowStepBenchmark.
// Reports particle-steps/s (items: every particle that carries heat).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/dictionary/Dictionary.h"
#include "materials/MaterialLibrary.h"
#include "particles/FieldNames.h"
#include "sph/ExposedArea.h"
#include "sph/WeaklyCompressibleFlow.h"
#include "thermal/EnergyEquation.h"

namespace {

namespace field = sphcast::field;

using sphcast::Real;
using sphcast::Vector;

const char* const properties =
    "metal { density 2400; conductivity table ((830 175) (889 83)); emissivity 0.1;"
    "        internalEnergy table ((803 7.89e5) (830.44 8.44e5) (888.64 1.33e6) (973 1.431e6)); }"
    "iron { density 7874; conductivity 26; emissivity 0.3;"
    "       specificHeat table ((773.15 640) (973.15 800)); }";

sphcast::ParticleCloud block(const std::string& name, const Vector& lower, int nx, int ny, int nz,
                             Real dx, Real T) {
  sphcast::ParticleCloud cloud(name);
  cloud.resize(static_cast<std::size_t>(nx) * ny * nz);
  auto& volume = cloud.addScalarField(field::volume);
  auto& temperature = cloud.addScalarField(field::T);
  std::size_t n = 0;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i, ++n) {
        cloud.positions()[n] = lower + dx * Vector(i + Real(0.5), j + Real(0.5), k + Real(0.5));
        volume[n] = dx * dx * dx;
        temperature[n] = T;
      }
    }
  }
  cloud.attributes()["spacing"] = double(dx);
  return cloud;
}

struct HeatCase {
  sphcast::MaterialLibrary library = sphcast::MaterialLibrary::fromDictionary(
      sphcast::Dictionary::parse(properties, "physicalProperties"), "physicalProperties");
  sphcast::ParticleCloud metal{"metal"}, mold{"mold"};
  std::unique_ptr<sphcast::Neighbourhood> neighbourhood;
  std::unique_ptr<sphcast::EnergyEquation> energy;
  std::unique_ptr<sphcast::ExposedArea> area;

  HeatCase(int perSide, const std::string& paths) {
    const Real dx = Real(1.5e-3);
    metal = block("metal", Vector::Zero(), perSide, perSide, perSide, dx, 970);
    // a cup three layers thick under and around the block
    mold = block("mold", Vector::Constant(-3 * dx), perSide + 6, perSide + 6, perSide + 3, dx, 300);
    const auto& x = mold.positions();
    std::vector<std::size_t> order, dropped;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const bool inside =
          (x[i].array() > 0).all() && x[i][0] < perSide * dx && x[i][1] < perSide * dx;
      (inside ? dropped : order).push_back(i);
    }
    const std::size_t kept = order.size();
    order.insert(order.end(), dropped.begin(), dropped.end());
    mold.reorder(order);
    mold.resize(kept);
    neighbourhood = std::make_unique<sphcast::Neighbourhood>(3 * dx, sphcast::PeriodicBox());
    neighbourhood->addCloud(metal, sphcast::Neighbourhood::Motion::fixed);
    neighbourhood->addCloud(mold, sphcast::Neighbourhood::Motion::fixed);
    sphcast::HeatTransferContext context;
    context.dimension = 3;
    context.supportRadius = 3 * dx;
    context.spacing = dx;
    context.neighbourhood = neighbourhood.get();
    context.clouds = {{&metal, &library.get("metal", {}, "material"), false, 0, {}},
                      {&mold, &library.get("iron", {}, "material"), false, 0, {}}};
    energy = std::make_unique<sphcast::EnergyEquation>(
        context,
        sphcast::Dictionary::parse("h { clouds (metal mold); " + paths + " }").subDict("h"));
    if (energy->needsExposedArea()) {
      area = std::make_unique<sphcast::ExposedArea>(
          energy->exposedAreaForm(), 3, 3 * dx, dx,
          std::vector<sphcast::ParticleCloud*>{&metal, &mold},
          std::vector<const sphcast::ParticleCloud*>{&metal, &mold}, *neighbourhood,
          std::vector<const sphcast::ParticleCloud*>{&mold});  // as the solver: walls ungated
    }
    neighbourhood->update(sphcast::CloudOrder::keep);
    if (area) area->compute();
    energy->start();
  }
};

void HeatStep(benchmark::State& state, const char* paths) {
  const int perSide = static_cast<int>(std::lround(std::cbrt(double(state.range(0)))));
  HeatCase heat(perSide, paths);
  std::string limiter;
  const double dt = heat.energy->stableDeltaT(limiter);
  for (auto _ : state) {
    heat.energy->halfKick(dt);
    heat.energy->computeRates();
    heat.energy->halfKick(dt);
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<long>(heat.metal.size() + heat.mold.size()));
  state.counters["particles"] = double(heat.metal.size() + heat.mold.size());
}
BENCHMARK_CAPTURE(HeatStep, conduction, "conduction on;")
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(HeatStep, allPaths,
                  "conduction on; moldContact { coefficients ((metal iron 3000)); }"
                  "atmosphere { T 300; coefficients ((metal 20) (iron 20)); } radiation { T 300; }")
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The periodic streaming block of flowStepBenchmark, with conduction in it, in the solver's
// order of passes.
void FlowAndHeatStep(benchmark::State& state) {
  const int perSide = static_cast<int>(std::lround(std::cbrt(double(state.range(0)))));
  const Real dx = Real(1.25e-3);
  sphcast::MaterialLibrary library = sphcast::MaterialLibrary::fromDictionary(
      sphcast::Dictionary::parse(properties, "physicalProperties"), "physicalProperties");
  sphcast::ParticleCloud fluid = block("metal", Vector::Zero(), perSide, perSide, perSide, dx, 970);
  auto& U = fluid.addVectorField(field::U);
  auto& rho = fluid.addScalarField(field::rho);
  auto& mass = fluid.addScalarField(field::mass);
  auto& mu = fluid.addScalarField(field::viscosity);
  auto& rest = fluid.addScalarField(field::restDensity);
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    U[i] = Vector(1 + Real(0.01) * std::sin(Real(0.1) * Real(i)), 0, 0);
    rho[i] = rest[i] = 2400;
    mass[i] = 2400 * dx * dx * dx;
    mu[i] = Real(1.28e-3);
  }
  sphcast::FlowSettings settings;
  settings.dimension = 3;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = 50;
  settings.gravity = Vector(0, 0, Real(-9.81));
  for (int axis = 0; axis < 3; ++axis) settings.periodic.setPeriodic(axis, 0, perSide * dx);
  sphcast::Neighbourhood neighbourhood(settings.supportRadius, settings.periodic);
  neighbourhood.addCloud(fluid, sphcast::Neighbourhood::Motion::moving);
  sphcast::WeaklyCompressibleFlow flow(settings, fluid, {}, neighbourhood);
  sphcast::HeatTransferContext context;
  context.dimension = 3;
  context.supportRadius = settings.supportRadius;
  context.spacing = dx;
  context.neighbourhood = &neighbourhood;
  context.clouds = {{&fluid, &library.get("metal", {}, "material"), false, 0, {}}};
  sphcast::EnergyEquation energy(
      context, sphcast::Dictionary::parse("h { clouds (metal); conduction on; }").subDict("h"));
  neighbourhood.update();
  flow.start();
  energy.start();
  std::string limiter;
  const double deltaT = flow.stepLimits(0.25).smallest(limiter);
  for (auto _ : state) {
    flow.kickAndDrift(deltaT);
    energy.halfKick(deltaT);
    neighbourhood.update();
    flow.keepClearOfWalls();
    flow.computeRatesAndKick(deltaT);
    energy.computeRates();
    energy.halfKick(deltaT);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(fluid.size()));
  state.counters["particles"] = double(fluid.size());
}
BENCHMARK(FlowAndHeatStep)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond)->UseRealTime();

// The exposed area pass alone (s_i, grad s_i, A_i over the metal and the cup), which a step
// with a flow and air or radiation adds.
void ExposedAreaPass(benchmark::State& state) {
  const int perSide = static_cast<int>(std::lround(std::cbrt(double(state.range(0)))));
  HeatCase heat(perSide, "atmosphere { T 300; coefficients ((metal 20) (iron 20)); }");
  for (auto _ : state) heat.area->compute();
  state.SetItemsProcessed(state.iterations() *
                          static_cast<long>(heat.metal.size() + heat.mold.size()));
}
BENCHMARK(ExposedAreaPass)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
