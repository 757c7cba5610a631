// Write and read speed of a time folder's cloud file (.vtp: appended data, zlib, UInt64 headers,
// base64, written atomically with fsync). The cloud is a metal cloud as the solver writes it:
// positions, 2 vector fields, 4 scalar fields and 1 id field, in full precision.
// Bytes/s counts the cloud's in-memory payload; the file size is reported as fileMB.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <string>

#include "io/VtpCloud.h"
#include "particles/FieldNames.h"
#include "particles/ParticleCloud.h"

namespace {

namespace field = sphcast::field;

namespace fs = std::filesystem;
using sphcast::ParticleCloud;
using sphcast::Real;
using sphcast::Vector;

// Random values in physical ranges: full-precision doubles compress little, as in a real run.
ParticleCloud metalCloud(std::size_t count) {
  std::mt19937_64 random(42);
  auto uniform = [&](double low, double high) {
    return static_cast<Real>(std::uniform_real_distribution<double>(low, high)(random));
  };
  ParticleCloud cloud("metal");
  cloud.resize(count);
  auto& velocity = cloud.addVectorField(field::U);
  auto& acceleration = cloud.addVectorField(field::acceleration);
  auto& temperature = cloud.addScalarField(field::T);
  auto& density = cloud.addScalarField(field::rho);
  auto& pressure = cloud.addScalarField(field::p);
  auto& solidFraction = cloud.addScalarField(field::solidFraction);
  auto& id = cloud.addIdField("id");
  for (std::size_t i = 0; i < count; ++i) {
    cloud.positions()[i] = Vector(uniform(0, 0.1), uniform(0, 0.1), uniform(0, 0.2));
    velocity[i] = Vector(uniform(-1, 1), uniform(-1, 1), uniform(-2, 0));
    acceleration[i] = Vector(uniform(-50, 50), uniform(-50, 50), uniform(-60, 40));
    temperature[i] = uniform(300, 1000);
    density[i] = uniform(2300, 2700);
    pressure[i] = uniform(-1e4, 1e5);
    solidFraction[i] = uniform(0, 1);
    id[i] = static_cast<std::int64_t>(i);
  }
  cloud.attributes()["spacing"] = 0.00225;
  return cloud;
}

std::int64_t payloadBytes(const ParticleCloud& cloud) {
  const std::size_t reals = 3 * (1 + cloud.vectorFields().size()) + cloud.scalarFields().size();
  return static_cast<std::int64_t>(
      cloud.size() * (reals * sizeof(Real) + cloud.idFields().size() * sizeof(std::int64_t)));
}

// A fresh folder per benchmark, removed when it ends.
class ScratchFolder {
 public:
  ScratchFolder()
      : path_(fs::temp_directory_path() /
              ("sphCastCloudIoBenchmark_" + std::to_string(std::random_device{}()))) {
    fs::create_directories(path_);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  ~ScratchFolder() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void reportThroughput(benchmark::State& state, const ParticleCloud& cloud, const fs::path& file) {
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(cloud.size()));
  state.SetBytesProcessed(state.iterations() * payloadBytes(cloud));
  state.counters["fileMB"] = static_cast<double>(fs::file_size(file)) / 1e6;
  state.counters["payloadMB"] = static_cast<double>(payloadBytes(cloud)) / 1e6;
}

void writeCloudVtpBenchmark(benchmark::State& state) {
  const ParticleCloud cloud = metalCloud(static_cast<std::size_t>(state.range(0)));
  const ScratchFolder folder;
  const fs::path file = folder.path() / "metal.vtp";
  for (auto _ : state) sphcast::writeCloudVtp(cloud, file);
  reportThroughput(state, cloud, file);
}

void readCloudVtpBenchmark(benchmark::State& state) {
  const ParticleCloud cloud = metalCloud(static_cast<std::size_t>(state.range(0)));
  const ScratchFolder folder;
  const fs::path file = folder.path() / "metal.vtp";
  sphcast::writeCloudVtp(cloud, file);
  for (auto _ : state) {
    ParticleCloud read = sphcast::readCloudVtp(file, "metal");
    benchmark::DoNotOptimize(read.positions().data());
  }
  reportThroughput(state, cloud, file);
}

}  // namespace

BENCHMARK(writeCloudVtpBenchmark)
    ->Name("CloudIo/writeCloudVtp")
    ->RangeMultiplier(10)
    ->Range(10'000, 1'000'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(readCloudVtpBenchmark)
    ->Name("CloudIo/readCloudVtp")
    ->RangeMultiplier(10)
    ->Range(10'000, 1'000'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
