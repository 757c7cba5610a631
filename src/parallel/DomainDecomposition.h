#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "parallel/Communicator.h"
#include "parallel/DecompositionSettings.h"
#include "parallel/ParticleTransfer.h"
#include "parallel/RecursiveBisection.h"
#include "particles/Neighbourhood.h"

namespace sphcast {

// A run decomposed over the ranks of a communicator (doc/design.md §5, "Parallel runs"): space
// cut into one subdomain per rank by recursive bisection of every cloud's weighted particles (or
// by hierarchical cuts, as decomposeParDict says);
// each rank holds the particles of its subdomain, followed by a halo of copies of the other
// ranks' particles within the neighbour search's reach (h plus the lists' skin; a graded mold's
// coarsest support plus the skin), so that a pair loop over its own particles finds exactly the
// neighbours a serial run finds. The solver's search goes through update(); a model brings the
// halo up to date between two of its passes through the neighbourhood's syncHalo, which lands
// in refresh().
class DomainDecomposition : public HaloSync {
 public:
  struct Cloud {
    ParticleCloud* cloud = nullptr;
    bool moves = false;       // migrates at every rebuild (the metal); else at re-balances
    std::int64_t weight = 1;  // one particle's share of a rank's work
    // its halo's reach, 0: the search's (haloRadius); a mold particleized at graded spacing
    // takes its coarsest particles' support plus the skin (their pairs reach that far), and
    // where it has the field supportReach, each particle its own reach plus the skin
    double haloRadius = 0;
    double skin = 0;
    bool perParticleReach = false;  // the field supportReach holds each particle's reach
  };

  // haloRadius: the neighbour search's reach (support radius plus skin).
  DomainDecomposition(const Communicator& comm, DecompositionSettings settings, double haloRadius,
                      const PeriodicBox& periodic, int dimension);

  // Collective: cuts space by the particles of every cloud, wherever they are (a serial start's
  // all on rank 0, a restart's as its pieces fell), and leaves each rank its own, in cell
  // order, with their halos. The clouds must stay where they are while this lives.
  void distribute(std::vector<Cloud> clouds);

  // Collective: the search of a step. The moving clouds' halos are refreshed; then, when
  // `rebuild` or the neighbourhood's rebuild is due on any rank, their particles migrate to
  // the ranks of their subdomains and get new halos (after a re-balance of every cloud when the
  // most loaded rank carries more than 1 + maxImbalance times the mean). The neighbourhood is
  // then updated, with every cloud kept in its order.
  void update(Neighbourhood& neighbourhood, bool rebuild = false);

  // Collective: drops a cloud's halo, so that particles can join its owned ones (an inlet's
  // new layer); the next update() rebuilds.
  void dropHalo(ParticleCloud& cloud);

  void refresh(const ParticleCloud& cloud, void* values, std::size_t bytesPerParticle,
               const std::source_location& where) override;
  void refresh(ParticleCloud& cloud, const std::vector<std::string>& fields,
               const std::source_location& where) override;
  void sumOverRanks(std::vector<double>& values, const std::source_location& where) override {
    comm_.sum(values, where);
  }
  double maxOverRanks(double value, const std::source_location& where) override {
    return comm_.max(value, where);
  }

  const Communicator& communicator() const { return comm_; }
  const RecursiveBisection& bisection() const { return bisection_; }
  long rebalances() const { return rebalances_; }
  // Collective: the most loaded rank's weight over the mean (1: perfect balance).
  double imbalance() const;
  // Collective: "2 subdomains, ...; halo 412 particles, 9.8 % of the 4,210 owned" for the log.
  std::string describe() const;

 private:
  void decompose();
  void redistribute(std::size_t c);  // drops the halo, migrates, puts the owned in cell order
  std::size_t indexOf(const ParticleCloud& cloud) const;
  void buildHalo(std::size_t c);

  Communicator comm_;
  DecompositionSettings settings_;
  double haloRadius_;
  PeriodicBox periodic_;
  int dimension_;
  RecursiveBisection bisection_;
  std::vector<Cloud> clouds_;
  std::vector<HaloExchange> halos_;
  long rebalances_ = 0;
  bool rebuildPending_ = false;  // a halo was dropped
};

}  // namespace sphcast
