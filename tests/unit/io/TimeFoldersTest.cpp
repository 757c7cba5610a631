#include "io/TimeFolders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "io/PvdIndex.h"
#include "io/VtpCloud.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

namespace fs = std::filesystem;

// <case>.pvd is named after the case folder: a copy of the case under another name keeps the
// old name's index, which the solver no longer updates. It is found (and warned of), the
// user's own .pvd files are not.
TEST(TimeFolders, AnIndexLeftByACopyUnderAnotherNameIsStale) {
  const testing::TemporaryCase copied("coarse");
  const CaseFolder caseFolder(copied.root());
  ParticleCloud metal("metal");
  metal.resize(2);
  writeTimeFolder(caseFolder, TimeState{}, {&metal});
  writeTimeFolder(caseFolder, TimeState{0.1, "0.1", 10, 0.01}, {&metal});
  writeCaseIndex(caseFolder);
  EXPECT_TRUE(staleCaseIndexes(caseFolder).empty());

  // As after `cp -r fine coarse`: fine.pvd indexes the same time folders.
  fs::copy_file(caseFolder.pvdFile(), copied.root() / "fine.pvd");
  writePvd(copied.root() / "elsewhere.pvd", {{0, "0", "metal", "../other/0/metal.vtp"}});
  copied.write("notAnIndex.pvd", "<html/>");
  EXPECT_EQ(staleCaseIndexes(caseFolder), std::vector<fs::path>{copied.root() / "fine.pvd"});

  ::testing::internal::CaptureStderr();
  warnOfStaleCaseIndexes(caseFolder);
  const std::string warning = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(warning.find((copied.root() / "fine.pvd").string() +
                         " indexes this case's time folders, but is no longer updated"),
            std::string::npos)
      << warning;
  EXPECT_NE(warning.find("The series is " + caseFolder.pvdFile().string() + "; remove fine.pvd."),
            std::string::npos)
      << warning;
  EXPECT_TRUE(fs::exists(copied.root() / "fine.pvd"));  // warned of, not removed
}

// A mold of constant/particles is shown at every time, but where a time folder has its own
// (a mold carrying heat, written with its T) the index points there: ParaView colours the mold
// by T at every time (it listed the mold without T before).
TEST(TimeFolders, TheIndexShowsATimesOwnCloudRatherThanTheStaticOne) {
  const testing::TemporaryCase folder("cast");
  const CaseFolder caseFolder(folder.root());
  ParticleCloud metal("metal"), mold("mold"), core("core");
  metal.resize(2);
  mold.resize(3);
  core.resize(1);
  fs::create_directories(folder.root() / "constant/particles");
  writeCloudVtp(mold, folder.root() / "constant/particles/mold.vtp");
  writeCloudVtp(core, folder.root() / "constant/particles/core.vtp");
  writeTimeFolder(caseFolder, TimeState{}, {&metal});
  writeTimeFolder(caseFolder, TimeState{0.1, "0.1", 10, 0.01}, {&metal, &mold});
  writeCaseIndex(caseFolder);
  const std::vector<PvdEntry> expected{
      {0, "0", "core", "constant/particles/core.vtp"},
      {0, "0", "metal", "0/metal.vtp"},
      {0, "0", "mold", "constant/particles/mold.vtp"},
      {0.1, "0.1", "core", "constant/particles/core.vtp"},
      {0.1, "0.1", "metal", "0.1/metal.vtp"},
      {0.1, "0.1", "mold", "0.1/mold.vtp"}};
  std::vector<PvdEntry> indexed = readPvd(caseFolder.pvdFile());
  std::sort(indexed.begin(), indexed.end(), [](const PvdEntry& a, const PvdEntry& b) {
    return std::tie(a.time, a.part) < std::tie(b.time, b.part);
  });
  EXPECT_EQ(indexed, expected);
}

}  // namespace
}  // namespace sphcast
