// The collectives' safety nets: a rank that takes another path than the others is an error
// naming every rank's call (with SPHCAST_CHECK_COLLECTIVES), not a hang, also where partners
// exchange point to point; an exchange with no partners sends and receives nothing while the
// others exchange among themselves.
// Collective: every rank runs every test (under mpirun -np 1, 2 and 4 in CTest).
#include "parallel/Communicator.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/Error.h"

namespace sphcast {
namespace {

// The check's line for a rank: "rank r, collective call n: <operation> at <file>:<line>
// (<function>)", one line per rank; empty if the message has none.
std::string callOf(const std::string& message, int rank) {
  const std::string start = "rank " + std::to_string(rank) + ", collective call ";
  const auto at = message.find(start);
  return at == std::string::npos ? std::string() : message.substr(at, message.find('\n', at) - at);
}

TEST(CommunicatorTest, ARankOnAnotherPathIsAnErrorNamingEveryRanksCall) {
  const Communicator world = Communicator::world();
  if (world.size() < 2) GTEST_SKIP() << "needs 2 ranks or more";
  const bool wasChecking = Communicator::checkCallSites(true);
  EXPECT_EQ(world.sum(1.0), world.size());  // the same call on every rank passes
  std::string message;
  try {
    if (world.master()) {
      world.sum(1.0);
    } else {
      world.max(1.0);
    }
  } catch (const CollectiveError& error) {
    message = error.what();
  }
  Communicator::checkCallSites(wasChecking);
  EXPECT_NE(message.find("the ranks took different paths"), std::string::npos) << message;
  EXPECT_NE(callOf(message, 0).find(": sum at "), std::string::npos) << message;
  EXPECT_NE(callOf(message, 1).find(": max at "), std::string::npos) << message;
  EXPECT_NE(message.find("CommunicatorTest.cpp:"), std::string::npos) << message;
  // as before, and every rank still in step
  EXPECT_EQ(world.sum(2.0), 2.0 * world.size());
}

// The halo refreshes' pattern: partners only. A rank that skips one (the odd ranks here) would
// go on to its next call while its partner waits for its messages; with the check, the calls
// are compared over every rank first and both are named.
TEST(CommunicatorTest, PartnersInDifferentExchangesAreAnErrorNamingBothCalls) {
  const Communicator world = Communicator::world();
  if (world.size() % 2 != 0) GTEST_SKIP() << "needs an even number of ranks";
  const int partner = world.rank() ^ 1;  // 0 with 1, 2 with 3
  const std::vector<int> partners{partner};
  std::vector<std::vector<char>> outgoing(static_cast<std::size_t>(world.size()));
  outgoing[static_cast<std::size_t>(partner)].assign(5, 'x');
  const bool wasChecking = Communicator::checkCallSites(true);
  EXPECT_EQ(world.exchange(outgoing, partners)[static_cast<std::size_t>(partner)].size(), 5u);
  std::string message;
  try {
    if (world.rank() % 2 == 0) world.exchange(outgoing, partners);  // the odd ranks skip it
    world.exchange(outgoing, partners);
  } catch (const CollectiveError& error) {
    message = error.what();
  }
  Communicator::checkCallSites(wasChecking);
  EXPECT_NE(message.find("the ranks took different paths"), std::string::npos) << message;
  // "...: exchange with partners at <this file>:<line> (...)", the two lines differing
  const std::string mine = callOf(message, world.rank()), theirs = callOf(message, partner);
  EXPECT_NE(mine.find(": exchange with partners at "), std::string::npos) << message;
  EXPECT_NE(theirs.find(": exchange with partners at "), std::string::npos) << message;
  EXPECT_NE(mine.substr(mine.find(" at ")), theirs.substr(theirs.find(" at "))) << message;
  EXPECT_EQ(world.sum(1.0), world.size());  // every rank still in step
}

TEST(CommunicatorTest, AnExchangeWithNoPartnersSendsNothing) {
  const Communicator world = Communicator::world();
  // ranks 0 and 1 are partners; the others have none
  std::vector<int> partners;
  if (world.size() > 1 && world.rank() < 2) partners.push_back(1 - world.rank());
  std::vector<std::vector<char>> outgoing(static_cast<std::size_t>(world.size()));
  for (int r = 0; r < world.size(); ++r) {
    outgoing[static_cast<std::size_t>(r)].assign(3, static_cast<char>('a' + world.rank()));
  }
  const auto incoming = world.exchange(outgoing, partners);
  for (int r = 0; r < world.size(); ++r) {
    const auto& from = incoming[static_cast<std::size_t>(r)];
    const bool expected = r == world.rank() || (world.rank() < 2 && r < 2);
    EXPECT_EQ(from.size(), expected ? 3u : 0u) << "from rank " << r;
    if (expected) {
      EXPECT_EQ(from[0], static_cast<char>('a' + r));
    }
  }
  EXPECT_EQ(world.sum(1.0), world.size());  // and no rank was left waiting
}

}  // namespace
}  // namespace sphcast
