#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "inlets/InletSetup.h"
#include "inlets/PouringInlet.h"
#include "materials/InternalEnergyTable.h"
#include "materials/TemperatureTable.h"
#include "parallel/Communicator.h"
#include "parallel/DomainDecomposition.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The pouring inlets of constant/inlets in the time loop (doc/physics.md §10.7): the layers
// they emit into the fluid after its drift, their buffers held after its kick, their state
// saved before a step (the last good state a failed check restores) and written to
// uniform/inlets.
class PouringInlets {
 public:
  PouringInlets() = default;
  // The inlets of `setup` feeding `fluid` (dimension, h, rho_s and mu the flow's; energy: the
  // fluid's u(T) when it carries heat, else null; unset: the fields a new particle starts
  // without). A restart reads their state from `state` (its uniform/inlets).
  PouringInlets(const InletSetup& setup, ParticleCloud& fluid, int dimension, Real supportRadius,
                const TemperatureTable& restDensity, const TemperatureTable& viscosity,
                const InternalEnergyTable* energy, const std::vector<std::string>& unset,
                const std::optional<Dictionary>& state, const Communicator& comm);

  bool empty() const { return inlets_.empty(); }
  // Whether any inlet still pours at `time`.
  bool pouring(double time) const;

  // The layers due by `time`, appended to the fluid. In a decomposed run a new layer joins rank
  // 0's own particles: every rank drops the fluid's halo first (they all find the same layers
  // due), and the next search rebuilds it and sends the layer's particles to their ranks.
  void pour(double time, DomainDecomposition* decomposition);
  void holdBuffers();

  void saveState();
  void restoreState();
  // The text of <time>/uniform/inlets.
  std::string stateFileText(const std::string& timeName) const;
  // A line per inlet for the log: what it has poured.
  void log(double time) const;

 private:
  ParticleCloud* fluid_ = nullptr;
  std::vector<std::unique_ptr<PouringInlet>> inlets_;
  std::vector<std::string> lastGood_;  // their state before the step
};

}  // namespace sphcast
