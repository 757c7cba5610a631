#include "core/CaseFolder.h"

#include <gtest/gtest.h>

#include "core/Error.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

namespace fs = std::filesystem;

TEST(TimeName, PrintsAsOpenFoamDoes) {
  EXPECT_EQ(timeName(0.0, TimeFormat::general, 6), "0");
  EXPECT_EQ(timeName(0.1, TimeFormat::general, 6), "0.1");
  EXPECT_EQ(timeName(0.1 + 0.2, TimeFormat::general, 6), "0.3");  // 0.30000000000000004
  EXPECT_EQ(timeName(1e-5, TimeFormat::general, 6), "1e-05");
  EXPECT_EQ(timeName(0.0012345678, TimeFormat::general, 6), "0.00123457");
  EXPECT_EQ(timeName(12.5, TimeFormat::fixed, 3), "12.500");
  EXPECT_EQ(timeName(0.05, TimeFormat::scientific, 2), "5.00e-02");
  EXPECT_EQ(timeName(-1e-310, TimeFormat::general, 6), "0");
}

TEST(CaseFolder, ListsTimeFoldersNumericallyAndIgnoresOthers) {
  testing::TemporaryCase tmp;
  for (const char* name : {"0", "0.1", "1e-05", "10", "2", ".0.2.writing", "constant2", "abc"}) {
    fs::create_directories(tmp.root() / name);
  }
  const CaseFolder caseFolder(tmp.root());
  std::vector<std::string> names;
  for (const auto& time : caseFolder.times()) names.push_back(time.name);
  EXPECT_EQ(names, (std::vector<std::string>{"0", "1e-05", "0.1", "2", "10"}));
  EXPECT_EQ(caseFolder.name(), "case");
  EXPECT_EQ(caseFolder.pvdFile(), tmp.root() / "case.pvd");
}

TEST(CaseFolder, RefusesAFolderWithoutSystem) {
  testing::TemporaryCase tmp;
  fs::remove_all(tmp.root() / "system");
  try {
    CaseFolder caseFolder(tmp.root());
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(std::string(error.what()),
              "'" + tmp.root().string() + "' is not a case folder: it has no system/ folder");
  }
  EXPECT_THROW(CaseFolder(tmp.root() / "missing"), Error);
}

TEST(CaseFolder, RecoversEveryStateAnInterruptedWriteCanLeave) {
  testing::TemporaryCase tmp;
  const CaseFolder caseFolder(tmp.root());
  // Killed while writing 0.1: the unfinished folder goes.
  fs::create_directories(caseFolder.writingFolder("0.1"));
  // Killed between the two renames replacing 0.2: the old complete folder comes back.
  fs::create_directories(caseFolder.replacedFolder("0.2") / "uniform");
  fs::create_directories(caseFolder.writingFolder("0.2"));
  // Killed after the second rename of 0.3: the set-aside copy is garbage.
  fs::create_directories(tmp.root() / "0.3");
  fs::create_directories(caseFolder.replacedFolder("0.3"));
  // Killed while purging 0.05.
  fs::create_directories(caseFolder.purgedFolder("0.05"));

  EXPECT_EQ(caseFolder.recoverInterruptedWrites().size(), 5u);
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(tmp.root())) {
    left.push_back(entry.path().filename().string());
  }
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"0.2", "0.3", "constant", "system"}));
  EXPECT_TRUE(fs::exists(tmp.root() / "0.2" / "uniform"));
}

TEST(SelectTimes, TakesListsAndRanges) {
  const std::vector<TimeFolder> times = {{0, "0"}, {0.1, "0.1"}, {0.2, "0.2"}, {0.5, "0.5"}};
  auto names = [](const std::vector<TimeFolder>& selected) {
    std::string joined;
    for (const auto& t : selected) joined += t.name + " ";
    return joined;
  };
  EXPECT_EQ(names(selectTimes(times, "0.1,0.5")), "0.1 0.5 ");
  EXPECT_EQ(names(selectTimes(times, "0.1:0.3")), "0.1 0.2 ");
  EXPECT_EQ(names(selectTimes(times, ":0.1,0.5")), "0 0.1 0.5 ");
  EXPECT_EQ(names(selectTimes(times, "0.2:")), "0.2 0.5 ");
  EXPECT_EQ(names(selectTimes(times, "0.3")), "");
  EXPECT_THROW(selectTimes(times, "0.1,abc"), Error);
  EXPECT_THROW(selectTimes(times, "0.1,,0.2"), Error);
}

}  // namespace
}  // namespace sphcast
