// The surface-tension models on a 3D ball of liquid metal at rest (AC4CH's rho and Gamma_g,
// h = 3 dx), at 1e4 and 1e5 particles:
//   SurfaceTensionPass: the surface-energy model's passes alone (surface/SurfaceEnergyTension.h:
//     s_i and the energy, then the pair forces), skipping the pairs inside the liquid
//     (surfaceOnly) or not (allPairs);
//   ContinuumSurfaceForcePass: the continuum surface force's passes alone
//     (surface/ContinuumSurfaceForce.h: colour gradient, colour near the surface, normals,
//     curvature, force), summing the colour gradient itself;
//   PairwiseForcePass: the pairwise force's one pass (surface/PairwiseForce.h);
//   FlowStep: a whole flow step over one shared neighbourhood, alone, with the flow summing the
//     colour gradient for a model that adds nothing (its cost in the flow's pair loop), with
//     the surface energy, with the continuum surface force.
// Reports particle-steps/s (items).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/dictionary/Dictionary.h"
#include "materials/MaterialLibrary.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "sph/WeaklyCompressibleFlow.h"
#include "surface/ContinuumSurfaceForce.h"
#include "surface/PairwiseForce.h"
#include "surface/SurfaceEnergyTension.h"

namespace {

namespace field = sphcast::field;

using sphcast::Real;
using sphcast::Vector;

constexpr Real dx = Real(1.5e-3);

sphcast::ParticleCloud ball(long count) {
  const Real radius = dx * Real(std::cbrt(3.0 * double(count) / (4 * std::numbers::pi)));
  const int reach = static_cast<int>(std::ceil(radius / dx));
  sphcast::ParticleCloud fluid("metal");
  std::vector<Vector> points;
  for (int k = -reach; k <= reach; ++k) {
    for (int j = -reach; j <= reach; ++j) {
      for (int i = -reach; i <= reach; ++i) {
        const Vector x = dx * Vector(i + Real(0.5), j + Real(0.5), k + Real(0.5));
        if (x.norm() < radius) points.push_back(x);
      }
    }
  }
  fluid.resize(points.size());
  auto& U = fluid.addVectorField(field::U);
  auto& rho = fluid.addScalarField(field::rho);
  auto& mass = fluid.addScalarField(field::mass);
  auto& mu = fluid.addScalarField(field::viscosity);
  auto& rest = fluid.addScalarField(field::restDensity);
  fluid.addVectorField(field::acceleration);
  fluid.addScalarField(field::densityRate);
  for (std::size_t i = 0; i < points.size(); ++i) {
    fluid.positions()[i] = points[i];
    U[i] = Vector::Zero();
    rho[i] = rest[i] = Real(2398.8);
    mass[i] = rho[i] * dx * dx * dx;
    mu[i] = Real(1.28e-3);
  }
  fluid.attributes()["spacing"] = double(dx);
  return fluid;
}

sphcast::SurfaceTensionSettings tensionSettings(bool surfaceOnly) {
  const sphcast::MaterialLibrary library = sphcast::MaterialLibrary::fromDictionary(
      sphcast::Dictionary::parse("AC4CH { surfaceTension 0.89; }", "physicalProperties"),
      "physicalProperties");
  sphcast::SurfaceTensionSettings settings;
  settings.dimension = 3;
  settings.supportRadius = 3 * dx;
  settings.spacing = dx;
  settings.gasTension =
      *library.get("AC4CH", sphcast::SourceLocation{}, "benchmark").surfaceTension;
  settings.surfaceParticlesOnly = surfaceOnly;
  return settings;
}

void SurfaceTensionPass(benchmark::State& state, bool surfaceOnly) {
  auto fluid = ball(state.range(0));
  sphcast::Neighbourhood neighbourhood(3 * dx, sphcast::PeriodicBox());
  neighbourhood.addCloud(fluid, sphcast::Neighbourhood::Motion::moving);
  sphcast::SurfaceEnergyTension tension(tensionSettings(surfaceOnly), fluid, {}, neighbourhood);
  neighbourhood.update();
  for (auto _ : state) tension.addAcceleration();
  state.SetItemsProcessed(state.iterations() * static_cast<long>(fluid.size()));
  state.counters["particles"] = double(fluid.size());
}
BENCHMARK_CAPTURE(SurfaceTensionPass, surfaceOnly, true)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(SurfaceTensionPass, allPairs, false)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// One model's passes alone (addAcceleration), on the ball with a neighbourhood of its own.
template <class Model>
void ModelPass(benchmark::State& state) {
  auto fluid = ball(state.range(0));
  sphcast::Neighbourhood neighbourhood(3 * dx, sphcast::PeriodicBox());
  neighbourhood.addCloud(fluid, sphcast::Neighbourhood::Motion::moving);
  Model tension(tensionSettings(true), fluid, {}, neighbourhood);
  neighbourhood.update();
  for (auto _ : state) tension.addAcceleration();
  state.SetItemsProcessed(state.iterations() * static_cast<long>(fluid.size()));
  state.counters["particles"] = double(fluid.size());
}
void ContinuumSurfaceForcePass(benchmark::State& state) {
  ModelPass<sphcast::ContinuumSurfaceForce>(state);
}
BENCHMARK(ContinuumSurfaceForcePass)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
void PairwiseForcePass(benchmark::State& state) { ModelPass<sphcast::PairwiseForce>(state); }
BENCHMARK(PairwiseForcePass)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

enum class Tension { none, colourGradientOnly, surfaceEnergy, continuumSurfaceForce };

// A force model that only asks the flow for the colour gradient.
class ColourGradientOnly : public sphcast::FluidForceModel {
 public:
  std::string limitName() const override { return "none"; }
  void addAcceleration() override { gradient_.clear(); }
  double stableDeltaT() const override { return 1e30; }
  double seconds() const override { return 0; }
  std::vector<Vector>* colourGradientBuffer() override { return &gradient_; }

 private:
  std::vector<Vector> gradient_;
};

void FlowStep(benchmark::State& state, Tension model) {
  auto fluid = ball(state.range(0));
  sphcast::FlowSettings settings;
  settings.dimension = 3;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = 50;
  sphcast::Neighbourhood neighbourhood(3 * dx, sphcast::PeriodicBox());
  neighbourhood.addCloud(fluid, sphcast::Neighbourhood::Motion::moving);
  sphcast::WeaklyCompressibleFlow flow(settings, fluid, {}, neighbourhood);
  std::unique_ptr<sphcast::SurfaceTensionModel> tension;
  ColourGradientOnly colourGradientOnly;
  if (model == Tension::colourGradientOnly) flow.addForceModel(colourGradientOnly);
  if (model == Tension::surfaceEnergy) {
    tension = std::make_unique<sphcast::SurfaceEnergyTension>(
        tensionSettings(true), fluid, std::vector<const sphcast::ParticleCloud*>{}, neighbourhood);
  } else if (model == Tension::continuumSurfaceForce) {
    tension = std::make_unique<sphcast::ContinuumSurfaceForce>(
        tensionSettings(true), fluid, std::vector<const sphcast::ParticleCloud*>{}, neighbourhood);
  }
  if (tension) flow.addForceModel(*tension);
  neighbourhood.update();
  flow.start();
  std::string limiter;
  const double deltaT = flow.stepLimits(0.25).smallest(limiter);
  for (auto _ : state) {
    flow.kickAndDrift(deltaT);
    neighbourhood.update();
    flow.computeRatesAndKick(deltaT);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(fluid.size()));
  state.counters["particles"] = double(fluid.size());
  // the model's own share of a step (its addAcceleration's wall time)
  if (tension) state.counters["tension_ms"] = 1e3 * tension->seconds() / double(state.iterations());
}
BENCHMARK_CAPTURE(FlowStep, flowAlone, Tension::none)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(FlowStep, summingTheColourGradient, Tension::colourGradientOnly)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(FlowStep, withSurfaceTension, Tension::surfaceEnergy)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(FlowStep, withContinuumSurfaceForce, Tension::continuumSurfaceForce)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
