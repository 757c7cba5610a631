// One step of the ballistic solver pass (the whole-cloud update every later integrator also
// does: x += v dt + g dt^2/2, v += g dt) and its stable-step reduction, at 1e4..1e6 particles.
// Reported as particles (items) per second = particle-steps/s.
#include <benchmark/benchmark.h>

#include "particles/FieldNames.h"
#include "particles/ParticleCloud.h"
#include "solver/BallisticMotion.h"

namespace {

namespace field = sphcast::field;

sphcast::ParticleCloud movingCloud(std::size_t count) {
  sphcast::ParticleCloud cloud("metal");
  cloud.resize(count);
  auto& velocity = cloud.addVectorField(field::U);
  for (std::size_t i = 0; i < count; ++i) {
    cloud.positions()[i] = sphcast::Vector(sphcast::Real(i % 100), sphcast::Real(i / 100), 0);
    velocity[i] = sphcast::Vector(1, 0, 2);
  }
  cloud.attributes()["spacing"] = 0.001;
  return cloud;
}

void BallisticStep(benchmark::State& state) {
  auto cloud = movingCloud(static_cast<std::size_t>(state.range(0)));
  const sphcast::BallisticMotion motion(sphcast::Vector(0, 0, -9.81));
  for (auto _ : state) {
    motion.step(cloud, 1e-5);
    benchmark::DoNotOptimize(cloud.positions().data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BallisticStep)->RangeMultiplier(10)->Range(10'000, 1'000'000)->UseRealTime();

void BallisticStableDeltaT(benchmark::State& state) {
  const auto cloud = movingCloud(static_cast<std::size_t>(state.range(0)));
  const sphcast::BallisticMotion motion(sphcast::Vector(0, 0, -9.81));
  for (auto _ : state) benchmark::DoNotOptimize(motion.stableDeltaT(cloud, 0.25));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BallisticStableDeltaT)->RangeMultiplier(10)->Range(10'000, 1'000'000)->UseRealTime();

}  // namespace
