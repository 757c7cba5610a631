#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <source_location>
#include <string>
#include <vector>

#include "particles/CellGrid.h"
#include "particles/NeighbourList.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The halo of a decomposed run (parallel/DomainDecomposition.h implements it): the copies of
// other ranks' particles that each cloud holds after its own (ParticleCloud::haloSize()).
class HaloSync {
 public:
  virtual ~HaloSync() = default;
  // Collective: the halo's entries of `values` (indexed like the cloud's particles) from their
  // owners. `where`: the model's call, which the call-site check compares over the ranks.
  virtual void refresh(const ParticleCloud& cloud, void* values, std::size_t bytesPerParticle,
                       const std::source_location& where) = 0;
  // Collective: the halo's entries of the named fields of the cloud from their owners.
  virtual void refresh(ParticleCloud& cloud, const std::vector<std::string>& fields,
                       const std::source_location& where) = 0;
  // Collective: each of `values` summed over the ranks, in place; and the largest of `value`
  // (a model's sums over its owned particles: an implicit solve's dot products).
  virtual void sumOverRanks(std::vector<double>& values, const std::source_location& where) = 0;
  virtual double maxOverRanks(double value, const std::source_location& where) = 0;
};

// How a cloud is stored along the grid after a search.
enum class CloudOrder {
  byCell,  // a moving cloud is reordered along its cell grid (neighbours close in memory)
  keep     // left as it is (a restart: the order it was written in, for bit-identical sums)
};

// The cell grids and pair lists that every model of a step reads, updated once per step for
// all the clouds of a case (doc/design.md §3, "the step"). The solver owns it; each model asks,
// when it is built, for the pairs of clouds it needs (requestPairs), and reads them
// (pairs(a, b)) when it adds its rates. A list is built once for all the models that share it.
//
// A moving cloud (the metal) is re-binned at a rebuild and reordered along its grid; a rigid
// cloud (a mold that moves as one body, bodies/RigidBody.h) is re-binned at a rebuild when it
// has moved, but never reordered (its particles keep their places in the body's frame), and its
// list with itself is built once (a rigid motion keeps every distance); a fixed cloud (a mold at
// rest) is binned once and never reordered, and a list between two fixed clouds (mold-mold
// conduction) is built once. Fields live in the clouds, so a reorder needs no hook in any model.
//
// Every list a model reads holds exactly the pairs closer than the kernel's support radius h,
// at the positions of the last update(). With a skin s > 0 a rebuild searches the cells with
// the radius h + s into a wide list, and the updates after it only filter the wide list at the
// new positions (a pass over its pairs, no cells), until two particles of a list may have closed
// in by s since the rebuild: the largest displacement of one cloud's particles plus that of the
// other's (twice the one within a cloud) reaching s. The filtered list is what a search with h
// would give, in the wide list's order (Verlet's list with a skin; Verlet 1967); a row whose
// particle and wide neighbours all kept their positions bit for bit since the last update (held
// frozen metal, a mold at rest) keeps its pairs where they are, untouched. A rebuild also
// comes with any change of a cloud's layout (particles added, removed or reordered by anyone
// else), a non-finite position, or when the caller asks for one (the solver does before a write,
// so that a restart, which rebuilds, reproduces the run bit for bit).
class Neighbourhood {
 public:
  enum class Motion { moving, rigid, fixed };

  // radius: the kernel's support radius h; skin: s >= 0 (0: a search at every update); a skin
  // that would leave a periodic axis's period no more than twice h + s is cut to fit.
  Neighbourhood(Real radius, const PeriodicBox& periodic, Real skin = 0);

  // Registers a cloud (once); its address must stay valid while the neighbourhood lives.
  // A cloud registered fixed and then rigid becomes rigid (a body's mold that a heat or flow
  // model registered first).
  void addCloud(ParticleCloud& cloud, Motion motion);
  void addFixedCloud(const ParticleCloud& cloud);
  bool has(const ParticleCloud& cloud) const;

  // Asks for the neighbours in `b` of each particle of `a` (a == b: within one cloud, self
  // excluded). Both clouds must be registered. Asking again for the same pair does nothing.
  void requestPairs(const ParticleCloud& a, const ParticleCloud& b);

  // Brings every requested list to the present positions: a rebuild (the moving clouds
  // binned, reordered when order is byCell, every list with a moving end searched) when one is
  // due or `rebuild` is true, else the lists with a moving end filtered from their wide lists.
  void update(CloudOrder order = CloudOrder::byCell, bool rebuild = false);

  // Whether the next update() would search the cells: a layout change, or particles that may
  // have closed in by the skin (a decomposed run asks every rank, and rebuilds on all at once).
  bool rebuildDue();

  // A decomposed run's halo (null: serial). A model's pass whose per-particle output a later
  // pair loop reads at a neighbour calls syncHalo after it, so that the halo's copies hold
  // their owners' values; in a serial run that does nothing.
  void setHaloSync(HaloSync* sync) { haloSync_ = sync; }
  bool decomposed() const { return haloSync_ != nullptr; }
  // (values: plain values, as Real, Vector or an Eigen matrix, one per particle of the cloud)
  template <class T>
  void syncHalo(const ParticleCloud& cloud, std::vector<T>& values,
                std::source_location where = std::source_location::current()) const {
    if (haloSync_) haloSync_->refresh(cloud, values.data(), sizeof(T), where);
  }
  void syncHalo(ParticleCloud& cloud, const std::vector<std::string>& fields,
                std::source_location where = std::source_location::current()) const {
    if (haloSync_) haloSync_->refresh(cloud, fields, where);
  }
  // Sums and maxima over the ranks of a decomposed run; a serial run's are its own.
  void sumOverRanks(std::vector<double>& values,
                    std::source_location where = std::source_location::current()) const {
    if (haloSync_) haloSync_->sumOverRanks(values, where);
  }
  double maxOverRanks(double value,
                      std::source_location where = std::source_location::current()) const {
    return haloSync_ ? haloSync_->maxOverRanks(value, where) : value;
  }

  // The list requested for (a, b), as of the last update(); throws Error if never requested.
  const NeighbourList& pairs(const ParticleCloud& a, const ParticleCloud& b) const;
  const CellGrid& grid(const ParticleCloud& cloud) const;

  Real radius() const { return radius_; }
  Real skin() const { return skin_; }
  const PeriodicBox& periodicBox() const { return periodic_; }
  // Pairs in all lists of the last update (for the log's throughput figures).
  std::size_t pairCount() const;
  // Updates so far that searched the cells, and that only filtered.
  std::size_t rebuildCount() const { return rebuilds_; }
  std::size_t reuseCount() const { return reuses_; }

 private:
  struct Entry {
    const ParticleCloud* cloud = nullptr;
    ParticleCloud* movable = nullptr;  // the cloud to reorder: null for a fixed or rigid cloud
    bool moves = false;                // moving or rigid
    std::unique_ptr<CellGrid> grid;
    bool binned = false;
    bool movedNow = false;                // moved since the last update (a list to renew)
    std::vector<Vector> binnedPositions;  // at the last binning (moving and rigid clouds)
    std::uint64_t binnedLayout = 0;       // the cloud's layoutVersion() then
    // at the last update: a rigid cloud's tell whether it moved, a moving cloud's (with a skin)
    // which of its particles moved
    std::vector<Vector> lastPositions;
    std::vector<std::uint8_t> moved;  // per particle: moved since the last update
  };
  struct Pairs {
    std::size_t a, b;    // entries
    NeighbourList list;  // closer than h
    NeighbourList wide;  // closer than h + s, at the last rebuild (only with a skin)
    bool built = false;
  };
  std::size_t entryOf(const ParticleCloud& cloud) const;
  void rebuild(CloudOrder order);
  void filter();
  void flagMovedParticles();
  // A rigid cloud's list with itself never changes (a rigid motion keeps every distance).
  bool keptForever(const Pairs& pairs) const;

  Real radius_;
  Real skin_;
  PeriodicBox periodic_;
  std::vector<Entry> entries_;
  std::vector<Pairs> pairs_;
  std::size_t rebuilds_ = 0;
  std::size_t reuses_ = 0;
  HaloSync* haloSync_ = nullptr;
};

}  // namespace sphcast
