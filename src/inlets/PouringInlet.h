#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/Real.h"
#include "materials/InternalEnergyTable.h"
#include "materials/TemperatureTable.h"
#include "parallel/Communicator.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

class Dictionary;

// What a pouring inlet is (constant/inlets, inlets/InletSetup.h reads it).
struct PouringInletSettings {
  std::string name;
  std::string cloud;  // the fluid cloud it feeds
  Vector centre = Vector::Zero();
  Vector direction = -Vector::UnitZ();  // unit: the pouring direction, normal to the disk
  double radius = 0;                    // of the disk (2D: half the slot's width), m
  double speed = 0;                     // m/s along direction (adjusted to massRate if given)
  double temperature = 0;               // K; 0: not given (a fluid without heat)
  std::optional<double> massRate;       // kg/s (2D: per metre of depth)
  std::optional<double> totalMass;      // kg to pour, then stop (2D: per metre of depth)
  std::optional<double> totalVolume;    // or m^3 (2D: m^2) at rho_s(T)
  double startTime = 0;
  std::optional<double> endTime;
};

// A ladle's or a sprue's stream: metal particles emitted through a disk (2D: a slot in the
// plane z = 0) on a square lattice of the particle spacing dx, in layers dx apart, at the
// temperature T, the density rho_s(T) and the material's viscosity. Each layer is placed dx
// behind the last one (exactly: from that layer's own positions), so the spacing is the
// lattice's and the mass rate N m V / dx is steady (N points of the disk, m = rho_s dx^D).
// With massRate given, V is set to give it exactly (the disk's lattice area N dx^D-1 differs from
// pi r^2 by a fraction of a row), and the log says by how much V moved.
//
// Without a pressure wave: the particles within one support radius h of the disk (the buffer,
// field `inlet` = the inlet's number + 1) are held at the inlet's velocity and rho_s (zero
// gauge pressure), a piston that feeds the stream; the fluid beyond them sees a full kernel of
// particles behind it. A particle leaves the buffer, free, once it is h past the disk.
//
// New particles get every field of the cloud: U, rho, restDensity, mass, volume (dx^D, as
// setCastFields writes it), viscosity and T as above, u = u(T) when the cloud carries heat, the
// fields `unsetFields` names at -1 (history not yet recorded: fill time, solidification times), the
// others 0; an `id` field continues the cloud's numbering. The energy they bring (sum m u) is added
// to the cloud's attribute inflowEnergy, so that the energy books close.
//
// In a decomposed run (comm of more than one rank) every rank finds the same layers due (from
// the buffer particles of all) and keeps the same books; rank 0 appends the particles, after
// the solver dropped the fluid's halo, and the next search migrates them to their ranks.
class PouringInlet {
 public:
  // `number`: the inlet's place among the case's (its buffer mark is number + 1). The fluid's
  // rho_s(T) and mu(T), and u(T) when the cloud carries heat (else null).
  PouringInlet(PouringInletSettings settings, int number, ParticleCloud& fluid, int dimension,
               Real supportRadius, const TemperatureTable& density,
               const TemperatureTable& viscosity, const InternalEnergyTable* energy,
               std::vector<std::string> unsetFields,
               const Communicator& comm = Communicator::self());

  const PouringInletSettings& settings() const { return settings_; }
  std::size_t particlesPerLayer() const { return layer_.size(); }
  double particleMass() const { return particleMass_; }
  double speed() const { return speed_; }  // as emitted
  double massRate() const;                 // as emitted: N m V / dx
  double emittedMass() const { return emittedMass_; }
  long emittedLayers() const { return layers_; }
  bool finished(double time) const;

  // The layers due at `time` (after the drift): appends them to the fluid cloud; returns the
  // number of particles added. emit = appendLayers(layersDue(time)).
  std::size_t emit(double time);
  // Collective: the distances past the disk of the layers due at `time`, the same on every rank
  // (from the buffer particles of them all). Empty: none.
  std::vector<Real> layersDue(double time) const;
  // Appends the layers (rank 0 holds their particles; every rank keeps the books).
  std::size_t appendLayers(const std::vector<Real>& distances);
  // After the flow's kick: the buffer particles back to the inlet's velocity and rho_s; those
  // h past the disk are released.
  void holdBuffer();

  // <time>/uniform/inlets's entry (full precision) and reading it back.
  std::string stateDictionary() const;
  void readState(const Dictionary& state);

 private:
  void appendLayer(Real distance);
  bool finishedWith(double time, double emittedMass) const;
  // the smallest distance past the disk of the inlet's buffer particles; false if it has none
  bool lastLayerDistance(Real& distance) const;

  Communicator comm_;
  PouringInletSettings settings_;
  Real mark_;  // the buffer's value of the field `inlet`
  ParticleCloud& fluid_;
  int dimension_;
  Real spacing_;
  Real bufferLength_;
  std::vector<std::string> unsetFields_;
  std::vector<Vector> layer_;  // the lattice points of the disk, relative to its centre
  double particleMass_ = 0;
  Real restDensity_ = 0;
  Real viscosity_ = 0;
  Real energy_ = 0;  // u(T), J/kg, when the cloud carries heat
  double speed_ = 0;
  double emittedMass_ = 0;
  long layers_ = 0;
  std::int64_t nextId_ = 0;
};

}  // namespace sphcast
