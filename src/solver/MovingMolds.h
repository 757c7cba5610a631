#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bodies/BodySetup.h"
#include "bodies/BodyWallContact.h"
#include "bodies/RigidBody.h"
#include "core/Real.h"
#include "parallel/Communicator.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {

// The rigid bodies of constant/dynamicBodies in the time loop (doc/physics.md §10.6): each a
// wall cloud of the flow moved as one body. Their phases run beside the flow's in a step
// (drift after its first kick, kept out of the other molds and pushed by the wall clearance
// after the search, kicked with the loads the flow measured), each load summed over the ranks
// of a decomposed run, so that every rank moves every body alike. Their state is saved before
// a step (the last good state a failed check restores) and written to uniform/dynamicBodies.
class MovingMolds {
 public:
  MovingMolds() = default;
  // The bodies of `setup`, each on its cloud (cloudOf gives it), registered in the
  // neighbourhood as rigid and measured by the flow; a restart reads their state from `state`
  // (its uniform/dynamicBodies; stateFile names it in messages). `walls` are the flow's.
  MovingMolds(const BodySetup& setup,
              const std::function<ParticleCloud&(const std::string&)>& cloudOf,
              const std::optional<Dictionary>& state, const std::string& stateFile,
              const std::vector<const ParticleCloud*>& walls, const Vector& gravity, double time,
              WeaklyCompressibleFlow& flow, Neighbourhood& neighbourhood, const Communicator& comm);

  bool empty() const { return bodies_.empty(); }
  const std::vector<std::unique_ptr<RigidBody>>& bodies() const { return bodies_; }
  std::vector<const RigidBody*> bodyList() const;

  // Their phases of a step (the flow's own are WeaklyCompressibleFlow's).
  void drift(double deltaT, double time);
  // In a decomposed run each rank scans its own particles of a body, and every rank moves the
  // body back by the deepest contact of all (of the lowest rank at a tie).
  void keepOutOfMolds(Real spacing);
  void pushByClearance(double deltaT, double time);
  void kick(double deltaT, double time);
  // The incompressible step's coupling (WeaklyCompressibleFlow::SubStepHooks::predict): the
  // velocities of the particles of the body on `wall` after a step of deltaT ending at
  // timeAfter under the fluid's load (summed over the ranks); false when no body moves it.
  bool predictVelocities(const ParticleCloud& wall, const Vector& force, const Vector& torque,
                         double deltaT, double timeAfter, std::vector<Vector>& velocity) const;

  // The shortest of their acceleration limits, below `stable`, naming the body in `limiter`.
  double limitStep(double stable, double spacing, std::string& limiter) const;

  // The state before a step, and back to it (a failed check's last good state).
  void saveState();
  void restoreState(double time);
  // The text of <time>/uniform/dynamicBodies.
  std::string stateFileText(const std::string& timeName) const;
  // A line per body for the log: travel, velocity, the fluid's force, a contact.
  void log(double spacing) const;

 private:
  // Two of the fluid's loads on a body, every rank's particles summed (a serial run's as they
  // are): each phase reduces only the pair it takes.
  std::pair<Vector, Vector> summedOverRanks(const Vector& a, const Vector& b) const;

  WeaklyCompressibleFlow* flow_ = nullptr;
  Neighbourhood* neighbourhood_ = nullptr;
  Communicator comm_ = Communicator::self();
  std::vector<std::unique_ptr<RigidBody>> bodies_;
  std::vector<std::vector<const ParticleCloud*>> otherMolds_;  // per body
  std::vector<BodyContact> contacts_;                          // of the last step
  std::vector<std::string> lastGood_;                          // their state before the step
};

}  // namespace sphcast
