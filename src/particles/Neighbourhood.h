#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "particles/CellGrid.h"
#include "particles/NeighbourList.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// How a cloud is stored along the grid after a search.
enum class CloudOrder {
  byCell,  // a moving cloud is reordered along its cell grid (neighbours close in memory)
  keep     // left as it is (a restart: the order it was written in, for bit-identical sums)
};

// The cell grids and pair lists that every model of a step reads, built once per step for
// all the clouds of a case (doc/design.md §3, "the step"). The solver owns it; each model asks,
// when it is built, for the pairs of clouds it needs (requestPairs), and reads them
// (pairs(a, b)) when it adds its rates. A list is built once for all the models that share it.
//
// A moving cloud (the metal) is re-binned at every update() and reordered along its grid; a
// rigid cloud (a mold that moves as one body, bodies/RigidBody.h) is re-binned at an update
// when it has moved, but never reordered (its particles keep their places in the body's frame),
// and its list with itself is built once (a rigid motion keeps every distance); a fixed cloud (a
// mold at rest) is binned once and never reordered, and a list between two fixed clouds
// (mold-mold conduction) is built once. Fields live in the clouds, so
// a reorder needs no hook in any model.
//
// Pair lists hold every pair closer than the search radius (the kernel's support radius h).
// Reusing lists over several steps (a skin: search radius h + s, rebuilt when a particle has
// moved s/2) needs only a larger radius here and a test in update(); the pair loops already
// skip nothing by distance and get W = 0 beyond h from the kernel's own clamp.
class Neighbourhood {
 public:
  enum class Motion { moving, rigid, fixed };

  Neighbourhood(Real radius, const PeriodicBox& periodic);

  // Registers a cloud (once); its address must stay valid while the neighbourhood lives.
  // A cloud registered fixed and then rigid becomes rigid (a body's mold that a heat or flow
  // model registered first).
  void addCloud(ParticleCloud& cloud, Motion motion);
  void addFixedCloud(const ParticleCloud& cloud);
  bool has(const ParticleCloud& cloud) const;

  // Asks for the neighbours in `b` of each particle of `a` (a == b: within one cloud, self
  // excluded). Both clouds must be registered. Asking again for the same pair does nothing.
  void requestPairs(const ParticleCloud& a, const ParticleCloud& b);

  // Bins the moving clouds (reordered when order is byCell), then rebuilds every requested list
  // with a moving end (every list, the first time).
  void update(CloudOrder order = CloudOrder::byCell);

  // The list requested for (a, b), as of the last update(); throws Error if never requested.
  const NeighbourList& pairs(const ParticleCloud& a, const ParticleCloud& b) const;
  const CellGrid& grid(const ParticleCloud& cloud) const;

  Real radius() const { return radius_; }
  const PeriodicBox& periodicBox() const { return periodic_; }
  // Pairs in all lists of the last update (for the log's throughput figures).
  std::size_t pairCount() const;

 private:
  struct Entry {
    const ParticleCloud* cloud = nullptr;
    ParticleCloud* movable = nullptr;  // the cloud to reorder: null for a fixed or rigid cloud
    bool moves = false;                // re-binned at every update (moving and rigid)
    std::unique_ptr<CellGrid> grid;
    bool binned = false;
    bool movedNow = false;                 // re-binned in this update
    std::vector<Vector> binnedPositions;  // a rigid cloud's, when last binned
  };
  struct Pairs {
    std::size_t a, b;  // entries
    NeighbourList list;
    bool built = false;
  };
  std::size_t entryOf(const ParticleCloud& cloud) const;

  Real radius_;
  PeriodicBox periodic_;
  std::vector<Entry> entries_;
  std::vector<Pairs> pairs_;
};

}  // namespace sphcast
