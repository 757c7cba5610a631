// The main() of the parallel tests: runs under `mpirun -np N` (N = 1, 2, 4 in CTest) or alone.
// Every rank runs every test (the tests are collective); rank 0 prints the usual report, the
// others their failures only, and every rank exits with the verdict of all.
#include <gtest/gtest.h>

#include <iostream>

#include "parallel/Communicator.h"

namespace {

// A failure on a rank other than 0, printed with the rank (its default printer is removed).
class RankFailurePrinter : public ::testing::EmptyTestEventListener {
 public:
  explicit RankFailurePrinter(int rank) : rank_(rank) {}
  void OnTestPartResult(const ::testing::TestPartResult& result) override {
    if (!result.failed()) return;
    std::cerr << "[rank " << rank_ << "] " << (result.file_name() ? result.file_name() : "?") << ":"
              << result.line_number() << ": failure\n"
              << result.summary() << std::endl;
  }

 private:
  int rank_;
};

}  // namespace

int main(int argc, char** argv) {
  sphcast::ParallelRun mpi(sphcast::builtWithMpi());
  ::testing::InitGoogleTest(&argc, argv);
  const sphcast::Communicator world = sphcast::Communicator::world();
  if (!world.master()) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new RankFailurePrinter(world.rank()));
  }
  const int status = RUN_ALL_TESTS();
  return world.any(status != 0) ? 1 : 0;
}
