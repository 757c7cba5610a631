#pragma once

#include <cstddef>
#include <functional>
#include <source_location>
#include <string>
#include <vector>

#include "parallel/Communicator.h"
#include "parallel/RecursiveBisection.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// Moving particles between ranks, whole (every field) or a few fields at a time. The clouds of
// one name have the same fields on every rank (the models add them on all ranks alike); a
// message that does not match the receiving cloud's fields is an Error.

// Appends the particles `indices` of cloud to `buffer`: the count, then positions, scalar,
// vector and id fields, each field contiguous, in the cloud's (sorted) field order.
void packParticles(const ParticleCloud& cloud, const std::vector<std::size_t>& indices,
                   std::vector<char>& buffer);
// Appends the particles of a buffer packParticles wrote to the cloud.
void unpackParticles(const std::vector<char>& buffer, ParticleCloud& cloud);

// A cloud without its particles: its name, attributes and fields, as bytes, and back (an empty
// cloud ready to receive the particles of the packed one).
std::string packLayout(const ParticleCloud& cloud);
ParticleCloud unpackLayout(const std::string& bytes);

// Collective: the cloud `read` returns on rank 0, whole there; every other rank gets an empty
// cloud with its name, attributes and fields and does not read (a start of 10^8 particles is
// read once, not once per rank; the decomposition then sends each particle to its rank). An
// error of rank 0's read is a CollectiveError with its message on every rank.
ParticleCloud readOnMaster(const std::function<ParticleCloud()>& read, const Communicator& comm);

// Collective: sends every particle of cloud to the rank whose subdomain holds its position, and
// appends what the other ranks send (those that stay keep their order, the arrivals follow by
// rank). Returns the number of particles that left this rank. The cloud must hold no halo
// (an Error otherwise).
std::size_t migrateParticles(ParticleCloud& cloud, const RecursiveBisection& decomposition,
                             const Communicator& comm);

// The halo of one cloud: copies of the other ranks' particles closer than a radius to this
// rank's subdomain, appended after its own particles, so that a pair loop over the owned
// particles [0, ownedCount()) finds every neighbour it would find in a serial run.
// refresh() brings the copies' fields up to date from their owners between two builds (after
// each pass whose output a later pair loop reads); the owners must not be reordered in between.
class HaloExchange {
 public:
  // Collective: removes the halo of the last build, then appends the new one, grouped by rank.
  // reach: null, every particle sent within `radius` of a subdomain; else each within
  // min(radius, reach[i] + skin) (a graded mold's supportReach).
  void build(ParticleCloud& cloud, const RecursiveBisection& decomposition, double radius,
             const PeriodicBox& periodic, const Communicator& comm,
             const std::vector<Real>* reach = nullptr, double skin = 0);
  // Collective: overwrites the halo copies' positions and every field with their owners'.
  void refresh(ParticleCloud& cloud, const Communicator& comm) const;
  // Collective: overwrites the named scalar and vector fields only ("position": the positions).
  void refresh(ParticleCloud& cloud, const std::vector<std::string>& fields,
               const Communicator& comm,
               std::source_location where = std::source_location::current()) const;
  // Collective: overwrites the halo's entries of an array indexed like the cloud's particles
  // (a model's own per-particle values, bytesPerParticle each) with their owners'.
  void refresh(const ParticleCloud& cloud, void* values, std::size_t bytesPerParticle,
               const Communicator& comm,
               std::source_location where = std::source_location::current()) const;
  // Drops the halo (before a migration, a write or a count); the cloud then holds its owned
  // particles only, until the next build. Refreshes do nothing until then (every rank's halo
  // must be dropped alike), and particles may be added.
  void remove(ParticleCloud& cloud);

  std::size_t ownedCount() const { return owned_; }
  std::size_t haloCount() const { return halo_; }
  // The ranks this one exchanges halos with.
  const std::vector<int>& partners() const { return partners_; }
  // The particles of this rank sent to each rank (the halo fraction, message sizes).
  std::size_t sentCount() const;

 private:
  void checkLayout(const ParticleCloud& cloud) const;

  bool built_ = false;
  std::size_t owned_ = 0, halo_ = 0;
  std::vector<std::vector<std::size_t>> sendIndices_;  // per rank, into the owned particles
  std::vector<std::size_t> haloStart_;                 // per rank: where its copies start
  std::vector<std::size_t> haloSize_;
  std::vector<int> partners_;
};

}  // namespace sphcast
