#include "core/TimeControl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

namespace fs = std::filesystem;

const std::string header = "FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }\n";

class TimeControlTest : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(tmp.root() / "0"); }
  void controlDict(const std::string& entries) const { tmp.write("system/controlDict", header + entries); }

  // Steps with a constant stable step until the end; returns the names of the write times.
  std::vector<std::string> runRecordingWrites(TimeControl& time, double stable) const {
    std::vector<std::string> written;
    while (time.run()) {
      time.adjustDeltaT(stable, "test limit");
      time.advance();
      if (time.writeTime()) written.push_back(time.timeName());
    }
    return written;
  }

  testing::TemporaryCase tmp;
};

TEST_F(TimeControlTest, AdjustableRunTimeLandsExactlyOnEveryWriteTimeAndEndTime) {
  controlDict("endTime 0.1; deltaT 1e-3; adjustTimeStep yes; writeControl adjustableRunTime;"
              "writeInterval 0.02;");
  const CaseFolder caseFolder(tmp.root());
  TimeControl time(caseFolder);
  std::vector<double> writeValues;
  while (time.run()) {
    time.adjustDeltaT(0.003, "test limit");
    EXPECT_LE(time.deltaT(), 0.003 * (1 + 1e-12));
    time.advance();
    if (time.writeTime()) writeValues.push_back(time.value());
  }
  ASSERT_EQ(writeValues.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(writeValues[k], static_cast<double>(k + 1) * 0.02) << "write " << k;
  }
  EXPECT_EQ(time.value(), 0.1);
  EXPECT_EQ(time.timeName(), "0.1");
  // 0.02 / 0.003 = 6.67: seven equal steps of 0.02/7 per interval, not six and a sliver.
  EXPECT_EQ(time.timeIndex(), 35);
  EXPECT_FALSE(time.finalWriteWanted());
}

TEST_F(TimeControlTest, AdjustTimeStepGrowsAtMostTwentyPercentAndHonoursMaxDeltaT) {
  controlDict("endTime 1; deltaT 1e-4; adjustTimeStep on; maxDeltaT 0.01; writeControl runTime;"
              "writeInterval 1;");
  const CaseFolder caseFolder(tmp.root());
  TimeControl time(caseFolder);
  double previous = 1e-4;
  time.adjustDeltaT(1.0, "test limit");  // the first step is limited by nothing but maxDeltaT
  EXPECT_EQ(time.deltaT(), 0.01);
  EXPECT_EQ(time.deltaTLimiter(), "maxDeltaT");
  TimeControl growing(caseFolder);
  growing.adjustDeltaT(1e-4, "test limit");
  growing.advance();
  for (int step = 0; step < 30; ++step) {
    growing.adjustDeltaT(1.0, "test limit");
    EXPECT_LE(growing.deltaT(), 1.2 * previous * (1 + 1e-12));
    EXPECT_LE(growing.deltaT(), 0.01);
    previous = growing.deltaT();
    growing.advance();
  }
  // Capped by maxDeltaT, less the sliver that makes the steps to endTime equal.
  EXPECT_NEAR(previous, 0.01, 0.01 * 0.01);
}

TEST_F(TimeControlTest, TimeStepWriteControlWritesEveryNthStep) {
  controlDict("endTime 0.01; deltaT 0.001; writeControl timeStep; writeInterval 4;");
  const CaseFolder caseFolder(tmp.root());
  TimeControl time(caseFolder);
  const auto written = runRecordingWrites(time, 1.0);
  EXPECT_EQ(written, (std::vector<std::string>{"0.004", "0.008"}));
  EXPECT_EQ(time.timeIndex(), 10);
  EXPECT_TRUE(time.finalWriteWanted());  // 0.01 is the end and was not a write step
}

TEST_F(TimeControlTest, RunTimeWriteControlWritesTheStepNearestEachInterval) {
  controlDict("endTime 0.1; deltaT 0.003; writeControl runTime; writeInterval 0.025;");
  const CaseFolder caseFolder(tmp.root());
  TimeControl time(caseFolder);
  const auto written = runRecordingWrites(time, 1.0);
  // Fixed steps of 0.003 are never shortened; the write falls on the first step within half a
  // step of 0.025 k: 0.024, 0.051, 0.075, 0.099.
  EXPECT_EQ(written, (std::vector<std::string>{"0.024", "0.051", "0.075", "0.099"}));
}

TEST_F(TimeControlTest, RestartFromLatestTimeContinuesFromTheExactSavedState) {
  controlDict("startFrom latestTime; endTime 1; deltaT 0.1; writeControl timeStep; writeInterval 1;");
  TimeState saved{0.30000000000000004, "0.3", 3, 0.1};
  tmp.write("0.3/uniform/time", uniformTimeDictionary(saved));
  const CaseFolder caseFolder(tmp.root());
  const TimeControl time(caseFolder);
  EXPECT_EQ(time.value(), 0.30000000000000004);  // bit-exact, not the rounded folder name
  EXPECT_EQ(time.timeIndex(), 3);
  EXPECT_EQ(time.startTimeName(), "0.3");
}

// A time folder without uniform/time (copied by hand, or from another tool) starts at its
// name's value and index 0, as in OpenFOAM, with a warning saying so.
TEST_F(TimeControlTest, RestartWithoutUniformTimeWarnsWhatItAssumes) {
  controlDict(
      "startFrom latestTime; endTime 1; deltaT 0.1; writeControl timeStep; writeInterval 1;");
  fs::create_directories(tmp.root() / "0.3");
  const CaseFolder caseFolder(tmp.root());
  ::testing::internal::CaptureStderr();
  const TimeControl time(caseFolder);
  const std::string warning = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(time.value(), 0.3);
  EXPECT_EQ(time.timeIndex(), 0);
  EXPECT_NE(warning.find((tmp.root() / "0.3/uniform/time").string() +
                         " is missing: starting at time 0.3 (the folder's name) with time index 0"),
            std::string::npos)
      << warning;

  // Time 0 (setCastFields writes uniform/time, but an older 0/ may lack it) is exact anyway.
  controlDict(
      "startFrom firstTime; endTime 1; deltaT 0.1; writeControl timeStep; writeInterval 1;");
  ::testing::internal::CaptureStderr();
  const TimeControl fromZero(caseFolder);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST_F(TimeControlTest, StartFromStartTimeNeedsThatFolder) {
  controlDict("startFrom startTime; startTime 0.5; endTime 1; deltaT 0.1; writeInterval 1;");
  const CaseFolder caseFolder(tmp.root());
  try {
    TimeControl time(caseFolder);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(std::string(error.what()),
              (tmp.root() / "system/controlDict").string() +
                  ": startFrom startTime: no time folder '0.5' in " + tmp.root().string());
  }
}

TEST_F(TimeControlTest, EditingStopAtToWriteNowStopsTheRunAndAsksForAFinalWrite) {
  controlDict("endTime 1; deltaT 0.01; writeControl timeStep; writeInterval 1000;");
  const CaseFolder caseFolder(tmp.root());
  TimeControl time(caseFolder);
  for (int step = 0; step < 3; ++step) {
    ASSERT_TRUE(time.run());
    time.advance();
  }
  controlDict("endTime 1; deltaT 0.01; writeControl timeStep; writeInterval 1000; stopAt writeNow;");
  EXPECT_FALSE(time.run());
  EXPECT_EQ(time.stopReason(), "stopAt writeNow");
  EXPECT_TRUE(time.finalWriteWanted());
  EXPECT_EQ(time.timeIndex(), 3);
}

TEST_F(TimeControlTest, EditingStopAtToNoWriteNowStopsWithoutWriting) {
  controlDict("endTime 1; deltaT 0.01; writeInterval 1000;");
  const CaseFolder caseFolder(tmp.root());
  TimeControl time(caseFolder);
  ASSERT_TRUE(time.run());
  time.advance();
  controlDict("endTime 1; deltaT 0.01; writeInterval 1000; stopAt noWriteNow;");
  EXPECT_FALSE(time.run());
  EXPECT_FALSE(time.finalWriteWanted());
}

TEST_F(TimeControlTest, ABrokenEditDuringTheRunKeepsThePreviousSettings) {
  controlDict("endTime 1; deltaT 0.01; writeInterval 1000;");
  const CaseFolder caseFolder(tmp.root());
  TimeControl time(caseFolder);
  controlDict("endTime 1; deltaT 0.01 writeInterval 1000;");  // missing ';'
  EXPECT_TRUE(time.run());
  const std::string message = time.takeRereadMessage();
  EXPECT_NE(message.find("Warning: ignoring modified"), std::string::npos) << message;
  EXPECT_EQ(time.settings().endTime, 1.0);
}

// A parallel run's ranks: one saw the file change, and every rank parses the text one rank
// read, not its own (a half-saved file read at different moments would part the ranks).
TEST_F(TimeControlTest, AnEditIsTakenFromTheTextTheRanksShare) {
  controlDict("endTime 1; deltaT 0.01; writeInterval 1000;");
  const CaseFolder caseFolder(tmp.root());
  TimeControl time(caseFolder);
  std::string seen;
  time.agreeOnChanges([](bool) { return true; },  // another rank saw it change
                      [&](const std::string& mine) {
                        seen = mine;
                        return header + "endTime 2; deltaT 0.01; writeInterval 1000;";
                      });
  EXPECT_TRUE(time.run());
  EXPECT_NE(seen.find("endTime 1;"), std::string::npos) << seen;  // this rank's own text
  EXPECT_EQ(time.settings().endTime, 2.0);                        // the shared one's value
  EXPECT_EQ(time.takeRereadMessage().rfind("Re-read", 0), 0u);
}

TEST_F(TimeControlTest, AnUnknownKeyNamesTheNearestValidOne) {
  controlDict("endTme 1; deltaT 0.01; writeInterval 10;");
  const CaseFolder caseFolder(tmp.root());
  try {
    TimeControl time(caseFolder);
    FAIL() << "no error";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("controlDict:2:1: unknown key 'endTme'"), std::string::npos) << message;
    EXPECT_NE(message.find("did you mean 'endTime'?"), std::string::npos) << message;
  }
}

TEST_F(TimeControlTest, BadValuesNameTheKeyAndTheRule) {
  const std::pair<std::string, std::string> cases[] = {
      {"endTime 1; deltaT -0.01; writeInterval 10;", "'deltaT' must be positive in controlDict"},
      {"endTime 1; deltaT 0.01; writeInterval 2.5;",
       "'writeInterval' must be a whole number of steps with writeControl timeStep in controlDict"},
      {"endTime 1; deltaT 0.01; writeInterval 1; maxCo 2;", "'maxCo' must be in (0, 1] in controlDict"},
      {"endTime 1; deltaT 0.01; writeInterval 1; maxDi 0.7;", "'maxDi' must be in (0, 0.5] in controlDict"},
      {"endTime 1; deltaT 0.01; writeInterval 1; stopAt sometime;", "unknown stopAt 'sometime'"},
  };
  for (const auto& [entries, expected] : cases) {
    controlDict(entries);
    const CaseFolder caseFolder(tmp.root());
    try {
      TimeControl time(caseFolder);
      ADD_FAILURE() << "no error for " << entries;
    } catch (const DictionaryError& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
  }
}

TEST_F(TimeControlTest, TimeNamesGainDigitsRatherThanCollide) {
  controlDict("endTime 2e-6; deltaT 1e-7; writeControl timeStep; writeInterval 1; timePrecision 1;");
  const CaseFolder caseFolder(tmp.root());
  TimeControl time(caseFolder);
  const auto written = runRecordingWrites(time, 1.0);
  const std::set<std::string> distinct(written.begin(), written.end());
  EXPECT_EQ(distinct.size(), written.size());
  EXPECT_EQ(written.size(), 20u);
}

}  // namespace
}  // namespace sphcast
