// The ETA of a run that ends on the solid fraction (endWhenSolid) rather than at endTime.
#include <gtest/gtest.h>

#include "core/Log.h"

namespace sphcast {
namespace {

TEST(CompletionEstimate, FollowsTheRecentRiseOfTheMeasure) {
  CompletionEstimate estimate(60.0);
  EXPECT_FALSE(estimate.secondsLeft()) << "one sample holds no rate";
  estimate.add(0.0, 0.0);
  estimate.add(10.0, 0.0);
  EXPECT_FALSE(estimate.secondsLeft()) << "no rise, no estimate";
  // 1 % per second from t = 10 s: at 0.3 the rest takes 70 s
  for (int t = 11; t <= 40; ++t) estimate.add(t, 0.01 * (t - 10));
  ASSERT_TRUE(estimate.secondsLeft());
  // over the window 0..40 s the rate is 0.3 / 40; the rest 0.7 / (0.3 / 40) = 93.3 s
  EXPECT_NEAR(*estimate.secondsLeft(), 0.7 / (0.3 / 40.0), 1e-9);
  // the rate doubles and the window forgets the first: 2 % per second from 40 s to 100 s
  for (int t = 41; t <= 100; ++t) estimate.add(t, 0.3 + 0.01 * (t - 40));
  EXPECT_NEAR(*estimate.secondsLeft(), 0.1 / 0.01, 1e-9);
  estimate.add(101.0, 1.0);
  EXPECT_EQ(*estimate.secondsLeft(), 0.0);
}

TEST(RunClock, ProgressLineTakesTheSoonerEndAndNamesIt) {
  const RunClock clock;
  // nothing of endTime done yet: the other end is the only estimate
  EXPECT_NE(clock.progressLine(0.0, 0, std::make_pair(83.0, std::string("all solid")))
                .find("ETA 0:01:23 (all solid)"),
            std::string::npos);
  EXPECT_NE(clock.progressLine(0.0, 0).find("ETA -"), std::string::npos);
  // endTime half reached at once (wall ~0 s): its ETA ~0 s is sooner than 83 s
  const std::string line = clock.progressLine(0.5, 0, std::make_pair(83.0, std::string("x")));
  EXPECT_EQ(line.find("(x)"), std::string::npos) << line;
}

}  // namespace
}  // namespace sphcast
