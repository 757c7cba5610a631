#include "core/CommandLine.h"

#include <gtest/gtest.h>

#include <string>

namespace sphcast {
namespace {

// -help lists the options as README.md gives them and users type them: one dash, as OpenFOAM.
TEST(CommandLine, HelpListsOptionsWithOneDash) {
  CommandLine args("castPostProcess", "Analyses the written times.");
  args.options()("latestTime", "only the latest time")(
      "time", boost::program_options::value<std::string>()->value_name("LIST"), "times");
  const char* const argv[] = {"castPostProcess", "-help"};
  ::testing::internal::CaptureStdout();
  const bool run = args.parse(2, argv);
  const std::string help = ::testing::internal::GetCapturedStdout();
  EXPECT_FALSE(run);
  EXPECT_EQ(help,
            "Usage: castPostProcess [OPTIONS]\n\n"
            "Analyses the written times.\n\n"
            "Options:\n"
            "  -case DIR (=.)  the case folder\n"
            "  -help           print this help and exit\n"
            "  -latestTime     only the latest time\n"
            "  -time LIST      times\n\n");
}

TEST(CommandLine, OptionsTakeOneDashOrTwo) {
  CommandLine args("sphCastFoam", "Runs the case.");
  const char* const oneDash[] = {"sphCastFoam", "-case", "a"};
  ASSERT_TRUE(args.parse(3, oneDash));
  EXPECT_EQ(args.casePath(), "a");
  CommandLine again("sphCastFoam", "Runs the case.");
  const char* const twoDashes[] = {"sphCastFoam", "--case", "b"};
  ASSERT_TRUE(again.parse(3, twoDashes));
  EXPECT_EQ(again.casePath(), "b");
}

}  // namespace
}  // namespace sphcast
