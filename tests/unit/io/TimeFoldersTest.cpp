#include "io/TimeFolders.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io/PvdIndex.h"
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

}  // namespace
}  // namespace sphcast
