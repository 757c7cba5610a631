#pragma once

#include <cstddef>
#include <cstdint>
#include <source_location>
#include <string>
#include <vector>

namespace sphcast {

// The ranks of a run and the few collective operations a decomposed run needs: reductions of
// step limits, books and checks, and exchanges of packed particles between ranks. With MPI
// (built with SPHCAST_WITH_MPI, the default) it wraps an MPI communicator; without, or in a run
// without -parallel, it is one rank and every operation is the identity, so the same code runs
// serial. Collective: every rank of the communicator must make the same calls in the same order.
// With the environment variable SPHCAST_CHECK_COLLECTIVES set, every collective call first
// compares its number and its caller's file and line over the ranks, and a rank that took
// another path is a CollectiveError naming every rank's call (a debugging aid: it costs an
// all-gather per call).
class Communicator {
 public:
  // All the ranks mpirun started (MPI_COMM_WORLD); one rank when MPI is not initialised.
  static Communicator world();
  // This rank alone (MPI_COMM_SELF): the serial reference inside a parallel run.
  static Communicator self();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool master() const { return rank_ == 0; }

  // where: the caller, for SPHCAST_CHECK_COLLECTIVES (below); leave it to its default.
  double sum(double value, std::source_location where = std::source_location::current()) const;
  std::int64_t sum(std::int64_t value,
                   std::source_location where = std::source_location::current()) const;
  double min(double value, std::source_location where = std::source_location::current()) const;
  double max(double value, std::source_location where = std::source_location::current()) const;
  bool any(bool value, std::source_location where = std::source_location::current()) const;
  // Element by element over the ranks, in place (one message for many sums).
  void sum(std::vector<double>& values,
           std::source_location where = std::source_location::current()) const;
  void sum(std::vector<std::int64_t>& values,
           std::source_location where = std::source_location::current()) const;
  void min(std::vector<double>& values,
           std::source_location where = std::source_location::current()) const;
  void max(std::vector<double>& values,
           std::source_location where = std::source_location::current()) const;
  // value of every rank, by rank
  std::vector<std::int64_t> gather(
      std::int64_t value, std::source_location where = std::source_location::current()) const;
  // The first non-empty text of the ranks, by rank ("" when all are empty): what one rank
  // found wrong, for every rank to stop with.
  std::string firstNonEmpty(const std::string& text,
                            std::source_location where = std::source_location::current()) const;

  // Rank 0's text, on every rank.
  std::string broadcast(const std::string& text,
                        std::source_location where = std::source_location::current()) const;

  // Collective: sends outgoing[r] to rank r and returns what each rank sent here, by rank
  // (outgoing has size() entries; outgoing[rank()] comes back as it is). Every rank with every
  // rank (the counts by all-to-all: a migration, a rebalance).
  std::vector<std::vector<char>> exchange(
      std::vector<std::vector<char>> outgoing,
      std::source_location where = std::source_location::current()) const;
  // The same with the partners only: the ranks this one may exchange anything with, the same
  // relation seen from both sides (a rank lists r exactly when r lists it); an empty list sends
  // and receives nothing. Every rank still makes the call: the exchanges are numbered, and the
  // call-site check compares `where` over every rank as for the collectives.
  std::vector<std::vector<char>> exchange(
      std::vector<std::vector<char>> outgoing, const std::vector<int>& partners,
      std::source_location where = std::source_location::current()) const;

  void barrier(std::source_location where = std::source_location::current()) const;

  // Turns the call-site check (SPHCAST_CHECK_COLLECTIVES, above) on or off for every
  // communicator and returns whether it was on; collective: every rank at the same point.
  static bool checkCallSites(bool on);

 private:
  void checkCallSite(const std::source_location& where, const char* operation) const;
  // partners null: all ranks
  std::vector<std::vector<char>> exchangeWith(std::vector<std::vector<char>> outgoing,
                                              const std::vector<int>* partners) const;
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
