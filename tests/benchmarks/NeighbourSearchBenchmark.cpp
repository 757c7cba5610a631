// Neighbour search on a 3D lattice (spacing dx, jittered by up to 5% of dx as after a few
// steps) at h/dx = 2 (~33 neighbours) and 3 (~113 neighbours), 1e4..1e6 particles:
//  - CellGridBuildAndReorder: bin by counting sort, reorder a cloud of the fields a flow step
//    carries (U, rho, p, m, T), renumber the grid: particles/s.
//  - NeighbourListBuild: the CSR list within the cloud: particles/s and pairs/s, with the
//    neighbours per particle and the list's bytes per particle as counters.
//  - NeighbourListBuildPeriodic: the same, the cube periodic on all three axes (minimum image).
//  - NeighbourListFilter: the list within h filtered from a wide list searched with h (1 + 0.1),
//    what a step costs while its lists are reused (particles/Neighbourhood.h): pairs/s of the
//    filtered list.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "particles/CellGrid.h"
#include "particles/FieldNames.h"
#include "particles/NeighbourList.h"
#include "particles/ParticleCloud.h"

namespace {

namespace field = sphcast::field;

using sphcast::Real;
using sphcast::Vector;

// A cube of side^3 particles (side^3 >= count) at spacing 1, in lattice order.
sphcast::ParticleCloud latticeCloud(std::int64_t count) {
  const auto side = static_cast<std::size_t>(std::ceil(std::cbrt(double(count)) - 1e-9));
  sphcast::ParticleCloud cloud("metal");
  cloud.resize(side * side * side);
  for (const char* name : {"rho", "p", "m", "T"}) cloud.addScalarField(name);
  cloud.addVectorField(field::U);
  std::mt19937 random(42);
  std::uniform_real_distribution<Real> jitter(Real(-0.05), Real(0.05));
  std::size_t i = 0;
  for (std::size_t z = 0; z < side; ++z) {
    for (std::size_t y = 0; y < side; ++y) {
      for (std::size_t x = 0; x < side; ++x) {
        cloud.positions()[i++] =
            Vector(Real(x) + jitter(random), Real(y) + jitter(random), Real(z) + jitter(random));
      }
    }
  }
  return cloud;
}

void CellGridBuildAndReorder(benchmark::State& state) {
  auto cloud = latticeCloud(state.range(0));
  sphcast::CellGrid grid(Real(state.range(1)));
  grid.build(cloud.positions());  // steady state: the cloud is near cell order from an earlier step
  cloud.reorder(grid.sortPermutation());
  for (auto _ : state) {
    grid.build(cloud.positions());
    cloud.reorder(grid.sortPermutation());
    grid.adoptCellOrder();
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(cloud.size()));
  state.counters["particles"] = double(cloud.size());
  state.counters["cells"] = double(grid.cellCount());
  state.counters["gridBytes/particle"] = double(grid.memoryBytes()) / double(cloud.size());
}

// Particles per second (items), pairs per second and neighbours per particle of a list made
// once per iteration.
void reportList(benchmark::State& state, const sphcast::NeighbourList& list) {
  const double particles = double(list.particleCount());
  const double pairs = double(list.pairCount());
  state.SetItemsProcessed(state.iterations() * std::int64_t(list.particleCount()));
  state.counters["particles"] = particles;
  state.counters["pairs/s"] =
      benchmark::Counter(pairs * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["neighbours"] = pairs / particles;
}

void listBuild(benchmark::State& state, bool periodic) {
  auto cloud = latticeCloud(state.range(0));
  sphcast::PeriodicBox box;
  if (periodic) {  // the lattice's cells [x - 1/2, x + 1/2) tile the box
    const Real side = std::round(std::cbrt(Real(cloud.size())));
    for (int axis = 0; axis < 3; ++axis) box.setPeriodic(axis, Real(-0.5), side);
  }
  sphcast::CellGrid grid(Real(state.range(1)), box);
  grid.build(cloud.positions());
  cloud.reorder(grid.sortPermutation());
  grid.adoptCellOrder();
  sphcast::NeighbourList list;
  list.buildWithin(cloud.positions(), grid);  // steady state: buffers sized by an earlier step
  for (auto _ : state) {
    list.buildWithin(cloud.positions(), grid);
    benchmark::DoNotOptimize(list.neighbours().data());
  }
  reportList(state, list);
  const double particles = double(cloud.size());
  const double pairs = double(list.pairCount());
  state.counters["listBytes/particle"] = double(list.memoryBytes()) / particles;
  state.counters["CSRBytes/particle"] = (double(list.offsets().size()) * 8 + pairs * 4) / particles;
}

void NeighbourListFilter(benchmark::State& state) {
  auto cloud = latticeCloud(state.range(0));
  const Real h = Real(state.range(1));
  sphcast::CellGrid grid(h * Real(1.1));
  grid.build(cloud.positions());
  cloud.reorder(grid.sortPermutation());
  grid.adoptCellOrder();
  sphcast::NeighbourList wide, list;
  wide.buildWithin(cloud.positions(), grid);
  const sphcast::PeriodicBox none;
  list.filterFrom(wide, cloud.positions(), cloud.positions(), h, none);  // buffers sized
  for (auto _ : state) {
    list.filterFrom(wide, cloud.positions(), cloud.positions(), h, none);
    benchmark::DoNotOptimize(list.neighbours().data());
  }
  reportList(state, list);
  state.counters["wideNeighbours"] = double(wide.pairCount()) / double(cloud.size());
}

void NeighbourListBuild(benchmark::State& state) { listBuild(state, false); }
void NeighbourListBuildPeriodic(benchmark::State& state) { listBuild(state, true); }

// Args: particles, h/dx
void latticeSizes(benchmark::internal::Benchmark* benchmark) {
  for (const std::int64_t hOverDx : {2, 3}) {
    for (const std::int64_t count : {10'000, 100'000, 1'000'000}) {
      benchmark->Args({count, hOverDx});
    }
  }
  benchmark->ArgNames({"N", "hOverDx"})->UseRealTime()->Unit(benchmark::kMillisecond);
}

BENCHMARK(CellGridBuildAndReorder)->Apply(latticeSizes);
BENCHMARK(NeighbourListBuild)->Apply(latticeSizes);
BENCHMARK(NeighbourListBuildPeriodic)->Apply(latticeSizes);
BENCHMARK(NeighbourListFilter)->Apply(latticeSizes);

}  // namespace
