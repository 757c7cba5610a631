// particleizeMold logs, per patch, the nearest-neighbour distances it achieved (min, mean, max
// over dx): exact on a box, and within the bounds its thinning guarantees on the cone.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "geometry/MoldParticleization.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

using testing::TemporaryCase;

struct LoggedSpacing {
  std::size_t particles = 0;
  double min = 0.0, mean = 0.0, max = 0.0;  // over dx
};

// Runs particleizeMold on `geo` with the given patches and returns its log.
std::string particleizeLog(const std::string& geo, double spacing, const std::string& patches) {
  TemporaryCase mold;
  mold.write("constant/geometry/mold.geo", geo);
  std::ostringstream dict;
  dict << "FoamFile { version 2.0; format ascii; class dictionary; object particleizeMoldDict; }\n"
       << "geometry (\"mold.geo\");\nspacing " << spacing << ";\nwallLayers 2;\npatches\n{\n"
       << patches << "}\n";
  mold.write("system/particleizeMoldDict", dict.str());
  ::testing::internal::CaptureStdout();
  particleizeMold(CaseFolder(mold.root()));
  return ::testing::internal::GetCapturedStdout();
}

// The numbers of the log line "Patch <name> (...) -> cloud ...: N particles; nearest-neighbour
// distance / dx: min a, mean b, max c".
LoggedSpacing loggedSpacing(const std::string& log, const std::string& patch) {
  const std::regex line("Patch " + patch +
                        " \\([a-zA-Z]+, [a-zA-Z]+\\) -> cloud [a-zA-Z]+: ([0-9]+) particles; "
                        "nearest-neighbour distance / dx: min ([0-9.e+-]+), mean ([0-9.e+-]+), "
                        "max ([0-9.e+-]+)");
  std::smatch match;
  EXPECT_TRUE(std::regex_search(log, match, line)) << log;
  if (match.empty()) return {};
  return {std::stoul(match[1]), std::stod(match[2]), std::stod(match[3]), std::stod(match[4])};
}

TEST(MoldSpacingStatistics, BoxLogsExactlyTheSpacing) {
  const std::string log = particleizeLog(
      "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 0.1, 0.1, 0.1};\n"
      "Physical Surface(\"walls\") = {1, 2, 3, 4, 5};\nPhysical Volume(\"cavity\") = {1};\n",
      0.01, "    walls { cloud mold; type fixedWall; }\n");
  const LoggedSpacing walls = loggedSpacing(log, "walls");
  // 2 layers of 10 x 10 behind 5 faces, 8 edges with 2 x 2 x 10 corner points, 4 bottom
  // corners with 7 (the 2 x 2 x 2 block less the one 2.6 dx away, beyond the shell's reach).
  EXPECT_EQ(walls.particles, 2u * 500u + 8u * 40u + 4u * 7u);
  EXPECT_EQ(walls.min, 1.0);
  EXPECT_EQ(walls.mean, 1.0);
  EXPECT_EQ(walls.max, 1.0);
}

TEST(MoldSpacingStatistics, ConeLogsItsSpacingPerPatch) {
  // The frustum of the shell tests (radius 6 dx at the bottom, 10 dx at the top), its side and
  // its bottom as two patches.
  const std::string log = particleizeLog(
      "SetFactory(\"OpenCASCADE\");\nCone(1) = {0, 0, 0, 0, 0, 0.06, 0.03, 0.05};\n"
      "Physical Surface(\"side\") = {1};\nPhysical Surface(\"bottom\") = {3};\n"
      "Physical Volume(\"cavity\") = {1};\n",
      0.005,
      "    side { cloud mold; type fixedWall; }\n    bottom { cloud mold; type fixedWall; }\n");
  const LoggedSpacing side = loggedSpacing(log, "side");
  const LoggedSpacing bottom = loggedSpacing(log, "bottom");
  // The thinning keeps particles 0.75 dx apart; the mean of a curved shell lies between that and
  // the dx of a lattice; only particles cut flush at the open rim see their neighbour farther.
  EXPECT_GE(side.min, 0.75 - 1e-3);
  EXPECT_GT(side.mean, 0.90);
  EXPECT_LT(side.mean, 1.0);
  EXPECT_LE(side.max, 1.6);
  // The flat bottom is the square lattice except where it meets the side's curved layers.
  EXPECT_GE(bottom.min, 0.75 - 1e-3);
  EXPECT_GT(bottom.mean, 0.98);
  EXPECT_LE(bottom.max, 1.0 + 1e-3);
  EXPECT_GT(bottom.particles, 2u * 100u);  // 2 layers under a disc of 6 dx radius (113 points)
}

}  // namespace
}  // namespace sphcast
