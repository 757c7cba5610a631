// A film squeezed from a block under a piston: does the load press the particles together, so
// that the film is as thick as its volume says? (sph/DensityReinitialisation.h, doc/physics.md
// §7.4.) 2D, periodic along x over 20 spacings (dx = 3 mm, h = 3 dx, c = 25 m/s, AC4CH's density
// and a melt's viscosity): a block of metal 10 spacings wide and 2N high on a floor, a piston 2
// layers thick 1 dx above it, loaded to 400 Pa (the paper's punch over its pocket) and let go at
// once; it squeezes the block into a film N rows thick across the whole period. At 0.3 s the
// piston's face stands above the floor by the film's volume, sum_i m_i / rho_i over the period,
// plus the excess measured here. Measured with densityReinitialisation packed (relaxation 0.3):
// 0.000 dx at N = 2 and 0.003 at N = 8 by 0.5 s; with the continuity equation alone 0.78 /
// 0.88 / 1.14 dx at N = 2 / 4 / 8, the film's rows 1.21 dx apart at N = 2 with rho = rho_s.
#include "solver/CastingSolver.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/Log.h"
#include "io/TimeFolders.h"
#include "io/VtpCloud.h"
#include "particles/FieldNames.h"
#include "sph/FlowTestCases.h"

namespace fs = std::filesystem;

namespace sphcast {
namespace {

constexpr Real dx = 0.003;
constexpr int columns = 20;

void writeText(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "FoamFile { version 2.0; format ascii; class dictionary; object "
                      << file.filename().string() << "; }\n"
                      << text;
}

void addIds(ParticleCloud& cloud) {
  auto& id = cloud.addIdField("id");
  for (std::size_t i = 0; i < cloud.size(); ++i) id[i] = static_cast<std::int64_t>(i);
  cloud.attributes()["spacing"] = dx;
}

void writeSqueezeCase(const fs::path& root, int rows, const std::string& reinitialisation,
                      const std::string& endTime) {
  const Real width = columns * dx;
  const Real load = 400;  // Pa
  writeText(root / "system/controlDict",
            "application sphCastFoam; startFrom latestTime; stopAt endTime; endTime " + endTime +
                ";\ndeltaT 1e-5; adjustTimeStep yes; maxCo 0.5; writeControl adjustableRunTime;\n"
                "writeInterval " +
                endTime + "; logInterval 100000;\n");
  writeText(root / "system/sphSchemes",
            "densityScheme riemann; viscousForm Morris; supportRadius " + std::to_string(3 * dx) +
                "; soundSpeed 25;\n" + reinitialisation);
  writeText(root / "constant/physicsModels",
            "dimension 2; periodic { x (0 " + std::to_string(width) +
                "); }\n"
                "materials { metal alloy; floor iron; piston iron; }\n"
                "flow { model weaklyCompressible; fluid metal; walls (floor piston); }\n");
  writeText(root / "constant/physicalProperties",
            "alloy { density 2400; viscosity 1.3e-3; }\niron { density 7874; }\n");
  writeText(root / "constant/g", "dimensions [0 1 -2 0 0 0 0]; value (0 -9.81 0);\n");
  writeText(root / "constant/dynamicBodies",
            "piston { mass " + std::to_string(load * width / 9.81) +
                "; translation (0 1 0); rotation locked; releaseTime 0; }\n");
  ParticleCloud metal =
      testing::fluidBlock2D(columns / 2, 2 * rows, dx, Vector::Zero(), 2400, Real(1.3e-3));
  ParticleCloud floor = testing::emptyWall("floor");
  testing::addWallCells(
      floor, 0, columns, -4, 0, dx, Vector::Zero(), [](int, int) { return Vector(0, 1, 0); },
      [](int, int row) { return (Real(-row) - Real(0.5)) * dx; });
  ParticleCloud piston = testing::emptyWall("piston");
  const int face = 2 * rows + 1;
  testing::addWallCells(
      piston, 0, columns, face, face + 2, dx, Vector::Zero(),
      [](int, int) { return Vector(0, -1, 0); },
      [face](int, int row) { return (Real(row - face) + Real(0.5)) * dx; });
  for (ParticleCloud* cloud : {&metal, &floor, &piston}) addIds(*cloud);
  fs::create_directories(root / "constant/particles");
  fs::create_directories(root / "0");
  writeCloudVtp(floor, root / "constant/particles/floor.vtp");
  writeCloudVtp(metal, root / "0/metal.vtp");
  writeCloudVtp(piston, root / "0/piston.vtp");
}

// The clouds at endTime of the squeeze on `threads` OpenMP threads.
std::vector<ParticleCloud> squeeze(int rows, const std::string& reinitialisation,
                                   const std::string& endTime = "0.3", int threads = 1) {
  const fs::path root =
      fs::temp_directory_path() / ("sphCastSqueezedFilm_" + std::to_string(std::random_device{}()));
  writeSqueezeCase(root, rows, reinitialisation, endTime);
  silenceInfo(true);
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  CastingSolver(CaseFolder(root)).run();
  omp_set_num_threads(before);
  silenceInfo(false);
  std::vector<ParticleCloud> clouds = readTimeFolderClouds(CaseFolder(root), endTime);
  fs::remove_all(root);
  return clouds;
}

// The piston's face above the floor less the film's volume per unit width, in spacings.
double excessThickness(const std::vector<ParticleCloud>& clouds) {
  double face = 1e9, volume = 0;
  for (const ParticleCloud& cloud : clouds) {
    if (cloud.name() == "piston") {
      for (const Vector& x : cloud.positions()) face = std::min(face, double(x[1]) - 0.5 * dx);
    } else if (cloud.name() == "metal") {
      for (std::size_t i = 0; i < cloud.size(); ++i) {
        volume += cloud.scalarField(field::mass)[i] / cloud.scalarField(field::rho)[i];
      }
    }
  }
  return (face - volume / (columns * dx)) / dx;
}

TEST(SqueezedFilmPackingTest, TheLoadPacksTheFilmToItsVolume) {
  for (const int rows : {2, 4}) {
    const double excess = excessThickness(squeeze(rows, "densityReinitialisation packed;\n"));
    std::cout << "    " << rows << " rows, densityReinitialisation packed: the film " << excess
              << " dx thicker than its volume\n";
    EXPECT_LT(std::abs(excess), 0.05) << rows << " rows";
  }
}

// The continuity equation alone: the squeezed film's rows stand apart at rho_s and carry the
// load there (the standoff crossDitchPress showed under its punch).
TEST(SqueezedFilmPackingTest, ContinuityAloneLeavesTheSqueezedFilmThick) {
  const double excess = excessThickness(squeeze(2, ""));
  std::cout << "    2 rows, continuity alone: the film " << excess
            << " dx thicker than its volume\n";
  EXPECT_GT(excess, 0.5);
}

// The re-initialisation's sums (each particle's over its lists, in their order) and every other
// pass of the squeeze give the same bits on 1 and 2 threads (over the first 0.02 s, some 300
// steps: 2 threads on a loaded 2-core machine wait at every barrier).
TEST(SqueezedFilmPackingTest, SameBitsOnOneAndTwoThreads) {
  const auto one = squeeze(2, "densityReinitialisation packed;\n", "0.02", 1);
  const auto two = squeeze(2, "densityReinitialisation packed;\n", "0.02", 2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t c = 0; c < one.size(); ++c) {
    EXPECT_TRUE(one[c].identicalTo(two[c])) << one[c].name();
  }
}

}  // namespace
}  // namespace sphcast
