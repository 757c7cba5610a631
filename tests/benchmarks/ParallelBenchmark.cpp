// The serial parts of a decomposed run's bookkeeping, on one process: the recursive bisection of
// a 3D cloud into 8 and 64 subdomains (the build a start and every re-balance do), and the
// packing and unpacking of particles into messages (a halo refresh or a migration moves every
// field of each particle: here the flow's fluid cloud, 8 scalar fields, 2 vectors, the id and
// the position, 144 bytes a particle). Bytes/s counts the particles' payload.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "parallel/ParticleTransfer.h"
#include "parallel/RecursiveBisection.h"
#include "particles/FieldNames.h"

namespace {

namespace field = sphcast::field;

using sphcast::Communicator;
using sphcast::ParticleCloud;
using sphcast::Real;
using sphcast::RecursiveBisection;
using sphcast::Vector;

// A jittered cube of count particles with the fields of the flow's fluid cloud.
ParticleCloud fluidCloud(std::size_t count) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> shake(-0.2, 0.2);
  ParticleCloud cloud("metal");
  cloud.resize(count);
  for (const char* name :
       {"densityRate", "fillTime", "mass", "p", "restDensity", "rho", "viscosity", "volume"}) {
    auto& field = cloud.addScalarField(name);
    for (auto& value : field) value = static_cast<Real>(shake(random));
  }
  cloud.addVectorField(field::U);
  cloud.addVectorField(field::acceleration);
  auto& id = cloud.addIdField("id");
  const auto side = static_cast<std::size_t>(std::cbrt(static_cast<double>(count)) + 1);
  for (std::size_t i = 0; i < count; ++i) {
    cloud.positions()[i] =
        Vector(static_cast<Real>(static_cast<double>(i % side) + shake(random)),
               static_cast<Real>(static_cast<double>(i / side % side) + shake(random)),
               static_cast<Real>(static_cast<double>(i / (side * side)) + shake(random)));
    id[i] = static_cast<std::int64_t>(i);
  }
  return cloud;
}

void RecursiveBisectionBuild(benchmark::State& state) {
  const ParticleCloud cloud = fluidCloud(static_cast<std::size_t>(state.range(0)));
  const std::vector<std::int64_t> weights(cloud.size(), 1);
  const int parts = static_cast<int>(state.range(1));
  for (auto _ : state) {
    auto rcb =
        RecursiveBisection::build(Communicator::self(), cloud.positions(), weights, parts, 3);
    benchmark::DoNotOptimize(rcb);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(cloud.size()));
}
BENCHMARK(RecursiveBisectionBuild)
    ->Args({10'000, 8})
    ->Args({100'000, 8})
    ->Args({100'000, 64})
    ->Unit(benchmark::kMillisecond);

// Packs a tenth of the cloud (a halo's share), then unpacks it into another cloud.
void PackAndUnpackParticles(benchmark::State& state) {
  const ParticleCloud cloud = fluidCloud(static_cast<std::size_t>(state.range(0)));
  std::vector<std::size_t> sent(cloud.size() / 10);
  for (std::size_t k = 0; k < sent.size(); ++k) sent[k] = 10 * k;
  std::vector<char> buffer;
  ParticleCloud received = cloud;
  for (auto _ : state) {
    buffer.clear();
    sphcast::packParticles(cloud, sent, buffer);
    received.resize(0);
    sphcast::unpackParticles(buffer, received);
    benchmark::DoNotOptimize(received.positions().data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(sent.size()));
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(buffer.size()));
  state.counters["bytesPerParticle"] =
      static_cast<double>(buffer.size()) / static_cast<double>(sent.size());
}
BENCHMARK(PackAndUnpackParticles)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

}  // namespace
