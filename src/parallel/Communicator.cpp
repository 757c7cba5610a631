// MPI behind the Communicator; a build without MPI (SPHCAST_WITH_MPI off) compiles the serial
// identities only.
#include "parallel/Communicator.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <map>
#include <string>
#include <type_traits>
#include <utility>

#include "core/CommandLine.h"
#include "core/Error.h"

#ifdef SPHCAST_WITH_MPI
#include <mpi.h>
#endif

namespace sphcast {

#ifdef SPHCAST_WITH_MPI
namespace {

bool mpiRunning() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised && !finalised;
}

// An MPI_Comm is a pointer in Open MPI and an int in MPICH: either fits in an intptr_t.
static_assert(sizeof(MPI_Comm) <= sizeof(std::intptr_t));

MPI_Comm toComm(std::intptr_t handle) {
  MPI_Comm comm;
  std::memcpy(&comm, &handle, sizeof comm);
  return comm;
}

std::intptr_t fromComm(MPI_Comm comm) {
  std::intptr_t handle = 0;
  std::memcpy(&handle, &comm, sizeof comm);
  return handle;
}

template <class T>
MPI_Datatype mpiType() {
  if constexpr (std::is_same_v<T, double>) {
    return MPI_DOUBLE;
  } else {
    static_assert(std::is_same_v<T, std::int64_t>);
    return MPI_INT64_T;
  }
}

}  // namespace

Communicator Communicator::world() {
  if (!mpiRunning()) return Communicator(0, false, 0, 1);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return Communicator(fromComm(MPI_COMM_WORLD), true, rank, size);
}

Communicator Communicator::self() {
  if (!mpiRunning()) return Communicator(0, false, 0, 1);
  return Communicator(fromComm(MPI_COMM_SELF), true, 0, 1);
}

#else

Communicator Communicator::world() { return Communicator(0, false, 0, 1); }
Communicator Communicator::self() { return Communicator(0, false, 0, 1); }

#endif

namespace {
enum class Reduction { sum, min, max };

template <class T>
void reduceInPlace(std::intptr_t handle, bool mpi, T* values, std::size_t count, Reduction how) {
#ifdef SPHCAST_WITH_MPI
  if (!mpi || count == 0) return;
  const MPI_Op op = how == Reduction::sum ? MPI_SUM : how == Reduction::min ? MPI_MIN : MPI_MAX;
  MPI_Allreduce(MPI_IN_PLACE, values, static_cast<int>(count), mpiType<T>(), op, toComm(handle));
#else
  (void)handle, (void)mpi, (void)values, (void)count, (void)how;
#endif
}
}  // namespace

double Communicator::sum(double value, std::source_location where) const {
  checkCallSite(where, "sum");
  reduceInPlace(handle_, mpi_, &value, 1, Reduction::sum);
  return value;
}
std::int64_t Communicator::sum(std::int64_t value, std::source_location where) const {
  checkCallSite(where, "sum");
  reduceInPlace(handle_, mpi_, &value, 1, Reduction::sum);
  return value;
}
double Communicator::min(double value, std::source_location where) const {
  checkCallSite(where, "min");
  reduceInPlace(handle_, mpi_, &value, 1, Reduction::min);
  return value;
}
double Communicator::max(double value, std::source_location where) const {
  checkCallSite(where, "max");
  reduceInPlace(handle_, mpi_, &value, 1, Reduction::max);
  return value;
}
void Communicator::sum(std::vector<double>& values, std::source_location where) const {
  checkCallSite(where, "sum");
  reduceInPlace(handle_, mpi_, values.data(), values.size(), Reduction::sum);
}
void Communicator::sum(std::vector<std::int64_t>& values, std::source_location where) const {
  checkCallSite(where, "sum");
  reduceInPlace(handle_, mpi_, values.data(), values.size(), Reduction::sum);
}
void Communicator::min(std::vector<double>& values, std::source_location where) const {
  checkCallSite(where, "min");
  reduceInPlace(handle_, mpi_, values.data(), values.size(), Reduction::min);
}
void Communicator::max(std::vector<double>& values, std::source_location where) const {
  checkCallSite(where, "max");
  reduceInPlace(handle_, mpi_, values.data(), values.size(), Reduction::max);
}

bool Communicator::any(bool value, std::source_location where) const {
  std::vector<std::int64_t> flag{value ? 1 : 0};
  sum(flag, where);
  return flag[0] > 0;
}

std::vector<std::int64_t> Communicator::gather(std::int64_t value,
                                               std::source_location where) const {
  checkCallSite(where, "gather");
  std::vector<std::int64_t> all(static_cast<std::size_t>(size_), 0);
#ifdef SPHCAST_WITH_MPI
  if (mpi_) {
    MPI_Allgather(&value, 1, MPI_INT64_T, all.data(), 1, MPI_INT64_T, toComm(handle_));
    return all;
  }
#endif
  all[0] = value;
  return all;
}

std::string Communicator::firstNonEmpty(const std::string& text, std::source_location where) const {
  const std::vector<std::int64_t> lengths = gather(static_cast<std::int64_t>(text.size()), where);
  int root = -1;
  for (int r = 0; r < size_ && root < 0; ++r) {
    if (lengths[static_cast<std::size_t>(r)] > 0) root = r;
  }
  if (root < 0) return "";
  if (!mpi_ || size_ == 1) return text;
  std::string shared =
      root == rank_
          ? text
          : std::string(static_cast<std::size_t>(lengths[static_cast<std::size_t>(root)]), '\0');
#ifdef SPHCAST_WITH_MPI
  MPI_Bcast(shared.data(), static_cast<int>(shared.size()), MPI_CHAR, root, toComm(handle_));
#endif
  return shared;
}

std::string Communicator::broadcast(const std::string& text, std::source_location where) const {
  checkCallSite(where, "broadcast");
  if (!mpi_ || size_ == 1) return text;
#ifdef SPHCAST_WITH_MPI
  std::int64_t length = static_cast<std::int64_t>(text.size());
  MPI_Bcast(&length, 1, MPI_INT64_T, 0, toComm(handle_));
  std::string shared = master() ? text : std::string(static_cast<std::size_t>(length), '\0');
  constexpr std::int64_t chunk = std::int64_t(1) << 30;  // an int count of bytes per message
  for (std::int64_t offset = 0; offset < length; offset += chunk) {
    MPI_Bcast(shared.data() + offset, static_cast<int>(std::min(chunk, length - offset)), MPI_CHAR,
              0, toComm(handle_));
  }
  return shared;
#else
  return text;
#endif
}

std::vector<std::vector<char>> Communicator::exchange(std::vector<std::vector<char>> outgoing,
                                                      std::source_location where) const {
  checkCallSite(where, "exchange");
  return exchangeWith(std::move(outgoing), nullptr);
}

// A partners' exchange sends to its partners only, but every rank makes the call: its number
// (below) is checked with each partner, and its call site with every rank like a collective's
// (a rank that skipped one would otherwise wait in the next collective while its partner waits
// for its messages).
std::vector<std::vector<char>> Communicator::exchange(std::vector<std::vector<char>> outgoing,
                                                      const std::vector<int>& partners,
                                                      std::source_location where) const {
  checkCallSite(where, "exchange with partners");
  return exchangeWith(std::move(outgoing), &partners);
}

std::vector<std::vector<char>> Communicator::exchangeWith(std::vector<std::vector<char>> outgoing,
                                                          const std::vector<int>* partners) const {
  if (outgoing.size() != static_cast<std::size_t>(size_)) {
    throw Error("Communicator::exchange: one outgoing buffer per rank expected");
  }
  std::vector<std::vector<char>> incoming(static_cast<std::size_t>(size_));
  incoming[static_cast<std::size_t>(rank_)] = std::move(outgoing[static_cast<std::size_t>(rank_)]);
#ifdef SPHCAST_WITH_MPI
  if (!mpi_ || size_ == 1) return incoming;
  const MPI_Comm comm = toComm(handle_);
  std::vector<int> peers;
  if (partners) {
    peers = *partners;
  } else {
    for (int r = 0; r < size_; ++r) peers.push_back(r);
  }
  peers.erase(std::remove(peers.begin(), peers.end(), rank_), peers.end());
  // The sizes first (a count per partner: all-to-all for everyone, messages otherwise), each
  // with the exchange's number on this communicator: an exchange that meets another (a rank
  // that skipped one) is an Error naming both, not a hang or a silent mix of messages. Then the
  // bytes, each message tagged and matched by its source.
  static std::map<std::intptr_t, std::int64_t> exchangesSoFar;
  const std::int64_t number = ++exchangesSoFar[handle_];
  std::vector<std::int64_t> sendCounts(2 * static_cast<std::size_t>(size_), 0);
  std::vector<std::int64_t> receiveCounts(2 * static_cast<std::size_t>(size_), 0);
  for (int r = 0; r < size_; ++r) sendCounts[2 * static_cast<std::size_t>(r) + 1] = number;
  for (int r : peers) {
    sendCounts[2 * static_cast<std::size_t>(r)] =
        static_cast<std::int64_t>(outgoing[static_cast<std::size_t>(r)].size());
  }
  if (!partners) {
    MPI_Alltoall(sendCounts.data(), 2, MPI_INT64_T, receiveCounts.data(), 2, MPI_INT64_T, comm);
  } else {
    std::vector<MPI_Request> requests(2 * peers.size());
    std::size_t k = 0;
    for (int r : peers) {
      MPI_Irecv(&receiveCounts[2 * static_cast<std::size_t>(r)], 2, MPI_INT64_T, r, 1, comm,
                &requests[k++]);
    }
    for (int r : peers) {
      MPI_Isend(&sendCounts[2 * static_cast<std::size_t>(r)], 2, MPI_INT64_T, r, 1, comm,
                &requests[k++]);
    }
    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  }
  for (int r : peers) {
    const std::int64_t theirs = receiveCounts[2 * static_cast<std::size_t>(r) + 1];
    if (theirs != number) {
      throw Error("Communicator::exchange: rank " + std::to_string(rank_) + "'s exchange " +
                  std::to_string(number) + " met rank " + std::to_string(r) + "'s exchange " +
                  std::to_string(theirs) + " (the ranks took different paths)");
    }
  }
  // messages of at most 1 GiB each (an int count of bytes)
  constexpr std::int64_t chunk = std::int64_t(1) << 30;
  std::vector<MPI_Request> requests;
  for (int r : peers) {
    auto& buffer = incoming[static_cast<std::size_t>(r)];
    const std::int64_t expected = receiveCounts[2 * static_cast<std::size_t>(r)];
    buffer.resize(static_cast<std::size_t>(expected));
    for (std::int64_t offset = 0; offset < expected; offset += chunk) {
      const auto bytes = std::min(chunk, expected - offset);
      requests.emplace_back();
      MPI_Irecv(buffer.data() + offset, static_cast<int>(bytes), MPI_BYTE, r, 2, comm,
                &requests.back());
    }
  }
  for (int r : peers) {
    const auto& buffer = outgoing[static_cast<std::size_t>(r)];
    const auto total = static_cast<std::int64_t>(buffer.size());
    for (std::int64_t offset = 0; offset < total; offset += chunk) {
      const auto bytes = std::min(chunk, total - offset);
      requests.emplace_back();
      MPI_Isend(buffer.data() + offset, static_cast<int>(bytes), MPI_BYTE, r, 2, comm,
                &requests.back());
    }
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
#else
  (void)partners;
#endif
  return incoming;
}

void Communicator::barrier(std::source_location where) const {
  checkCallSite(where, "barrier");
#ifdef SPHCAST_WITH_MPI
  if (mpi_) MPI_Barrier(toComm(handle_));
#endif
}

namespace {
bool& checkingCallSites() {
  static bool checking = std::getenv("SPHCAST_CHECK_COLLECTIVES") != nullptr;
  return checking;
}
}  // namespace

bool Communicator::checkCallSites(bool on) { return std::exchange(checkingCallSites(), on); }

void Communicator::checkCallSite(const std::source_location& where, const char* operation) const {
#ifdef SPHCAST_WITH_MPI
  if (!checkingCallSites() || !mpi_ || size_ == 1) return;
  const MPI_Comm comm = toComm(handle_);
  static std::map<std::intptr_t, std::int64_t> callsSoFar;
  const std::int64_t number = ++callsSoFar[handle_];
  const std::string site = std::string(operation) + " at " + where.file_name() + ":" +
                           std::to_string(where.line()) + " (" + where.function_name() + ")";
  const std::int64_t mine[2] = {number, static_cast<std::int64_t>(std::hash<std::string>{}(site))};
  std::vector<std::int64_t> all(2 * static_cast<std::size_t>(size_));
  MPI_Allgather(mine, 2, MPI_INT64_T, all.data(), 2, MPI_INT64_T, comm);
  bool alike = true;
  for (int r = 0; r < size_; ++r) {
    alike = alike && all[2 * static_cast<std::size_t>(r)] == mine[0] &&
            all[2 * static_cast<std::size_t>(r) + 1] == mine[1];
  }
  if (alike) return;
  // every rank sees the same table: all gather the sites and throw alike
  const int length = static_cast<int>(site.size());
  std::vector<int> lengths(static_cast<std::size_t>(size_)),
      offsets(static_cast<std::size_t>(size_));
  MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int r = 0; r < size_; ++r) {
    offsets[static_cast<std::size_t>(r)] = total;
    total += lengths[static_cast<std::size_t>(r)];
  }
  std::string sites(static_cast<std::size_t>(total), '\0');
  MPI_Allgatherv(site.data(), length, MPI_CHAR, sites.data(), lengths.data(), offsets.data(),
                 MPI_CHAR, comm);
  std::string message = "the ranks took different paths (SPHCAST_CHECK_COLLECTIVES):";
  for (int r = 0; r < size_; ++r) {
    const auto k = static_cast<std::size_t>(r);
    message +=
        "\n    rank " + std::to_string(r) + ", collective call " + std::to_string(all[2 * k]) +
        ": " +
        sites.substr(static_cast<std::size_t>(offsets[k]), static_cast<std::size_t>(lengths[k]));
  }
  throw CollectiveError(message);
#else
  (void)where, (void)operation;
#endif
}

#ifdef SPHCAST_WITH_MPI
namespace {
void endRanksAfterFatalError(bool everyRank) {
  if (!mpiRunning()) return;
  if (everyRank) {
    MPI_Finalize();
  } else {
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
}
}  // namespace
#endif

ParallelRun::ParallelRun(bool parallel) {
#ifdef SPHCAST_WITH_MPI
  if (!parallel) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  started_ = true;
  setFatalErrorHandler(endRanksAfterFatalError);
  const Communicator world = Communicator::world();
  if (!world.master()) setErrorPrefix("[" + std::to_string(world.rank()) + "] ");
  if (provided < MPI_THREAD_FUNNELED) {
    throw Error(
        "-parallel: this MPI library cannot run OpenMP threads beside its ranks "
        "(MPI_THREAD_FUNNELED not provided); set OMP_NUM_THREADS=1");
  }
#else
  if (parallel) {
    throw Error(
        "-parallel: this build has no MPI; configure with -DSPHCAST_WITH_MPI=ON "
        "(Debian: apt-get install libopenmpi-dev openmpi-bin) and build again");
  }
#endif
}

ParallelRun::~ParallelRun() {
#ifdef SPHCAST_WITH_MPI
  // while an error unwinds, runApplication prints it and then ends the ranks
  if (started_ && mpiRunning() && std::uncaught_exceptions() == 0) MPI_Finalize();
#endif
}

bool builtWithMpi() {
#ifdef SPHCAST_WITH_MPI
  return true;
#else
  return false;
#endif
}

}  // namespace sphcast
