#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sphcast {

// The ranks of a run and the few collective operations a decomposed run needs: reductions of
// step limits, books and checks, and exchanges of packed particles between ranks. With MPI
// (built with SPHCAST_WITH_MPI, the default) it wraps an MPI communicator; without, or in a run
// without -parallel, it is one rank and every operation is the identity, so the same code runs
// serial. Collective: every rank of the communicator must make the same calls in the same order.
class Communicator {
 public:
  // All the ranks mpirun started (MPI_COMM_WORLD); one rank when MPI is not initialised.
  static Communicator world();
  // This rank alone (MPI_COMM_SELF): the serial reference inside a parallel run.
  static Communicator self();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool master() const { return rank_ == 0; }

  double sum(double value) const;
  std::int64_t sum(std::int64_t value) const;
  double min(double value) const;
  double max(double value) const;
  bool any(bool value) const;
  // Element by element over the ranks, in place (one message for many sums).
  void sum(std::vector<double>& values) const;
  void sum(std::vector<std::int64_t>& values) const;
  void min(std::vector<double>& values) const;
  void max(std::vector<double>& values) const;
  // value of every rank, by rank
  std::vector<std::int64_t> gather(std::int64_t value) const;
  // The first non-empty text of the ranks, by rank ("" when all are empty): what one rank
  // found wrong, for every rank to stop with.
  std::string firstNonEmpty(const std::string& text) const;

  // Sends outgoing[r] to rank r and returns what each rank sent here, by rank (outgoing has
  // size() entries; outgoing[rank()] comes back as it is). partners: the ranks this one may
  // exchange anything with, the same relation seen from both sides (a rank lists r exactly
  // when r lists it); empty: every rank (counts by all-to-all, for a rebalance).
  std::vector<std::vector<char>> exchange(std::vector<std::vector<char>> outgoing,
                                          const std::vector<int>& partners = {}) const;

  void barrier() const;

 private:
  Communicator(std::intptr_t handle, bool mpi, int rank, int size)
      : handle_(handle), mpi_(mpi), rank_(rank), size_(size) {}
  std::intptr_t handle_;  // the MPI_Comm (a pointer or an int, by implementation)
  bool mpi_;              // false: one rank without MPI, every operation the identity
  int rank_;
  int size_;
};

// Starts MPI for a run with -parallel (threads funnelled: OpenMP inside a rank, MPI calls from
// its master thread) and finalises it at the end of main(); without -parallel it does nothing
// and the run is serial, and in a build without MPI -parallel is an Error. A fatal error on
// one rank ends them all (MPI_Abort, as OpenFOAM's FatalError does in parallel; the error
// names its rank), so that none waits for it in a collective; a CollectiveError, which every
// rank throws alike, ends them normally.
class ParallelRun {
 public:
  explicit ParallelRun(bool parallel);
  ~ParallelRun();
  ParallelRun(const ParallelRun&) = delete;
  ParallelRun& operator=(const ParallelRun&) = delete;

  bool started() const { return started_; }

 private:
  bool started_ = false;
};

// Whether this build can run -parallel.
bool builtWithMpi();

}  // namespace sphcast
