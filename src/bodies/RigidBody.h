#pragma once

#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <Eigen/Geometry>

#include "core/Real.h"
#include "parallel/Communicator.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

class Dictionary;

using Matrix3 = Eigen::Matrix<Real, 3, 3>;
using Quaternion = Eigen::Quaternion<Real>;

// What a body is and how it may move (constant/dynamicBodies, bodies/BodySetup.h reads it).
struct RigidBodySettings {
  std::string name;   // the body's (its sub-dictionary's) name
  std::string cloud;  // the mold cloud that moves as the body

  // Mass, centre and inertia: the mass given, or density x the particles' volume; the centre
  // and the inertia given, or from the particles (each a cube, 2D a square, of the cloud's
  // spacing; the mass spread uniformly over them).
  std::optional<double> mass;
  std::optional<double> density;
  std::optional<Vector> centreOfMass;
  std::optional<Vector> momentOfInertia;  // principal, about the centre, along x y z (kg m^2)

  // Prescribed motion (a press a machine drives): the centre's displacement from its start
  // against time, linear between the table's points (held at the ends), no rotation; the loads
  // are still measured. Dynamic otherwise.
  std::vector<std::tuple<double, Vector>> displacement;
  bool prescribed() const { return !displacement.empty(); }

  // Constraints of the dynamic motion: translation free, locked, or along an axis; rotation
  // free or locked; held where it is before releaseTime; an end stop.
  enum class Translation { free, axis, locked };
  Translation translation = Translation::free;
  Vector axis = Vector::UnitZ();  // unit, for Translation::axis
  bool rotationLocked = false;
  double releaseTime = 0;
  // The centre's travel from its start, along the axis, at which the body stops: a hard stop,
  // perfectly inelastic (the body stays at the stop, no rebound, while the forces push it on;
  // it leaves when they pull it back).
  std::optional<Vector> endStop;

  // A press's load at the centre: a force against time (N), and a pressure against time (Pa)
  // on pressedArea along pressDirection (a press's curve), together; each table linear between
  // its points and held at its ends (one point: a constant).
  std::vector<std::tuple<double, Vector>> appliedForce;
  std::vector<std::tuple<double, double>> appliedPressure;
  double pressedArea = 0;                    // m^2
  Vector pressDirection = -Vector::UnitZ();  // unit
  Vector appliedForceAt(double time) const;  // N: the three together at `time`
};

// A mold cloud moving as one rigid body, the other half of the flow's moving walls
// (sph/WeaklyCompressibleFlow.h). Newton-Euler with the flow's kick-drift-kick:
//   v^{n+1/2} = v^n + dt/2 a^n,  L^{n+1/2} = L^n + dt/2 tau^n,
//   c^{n+1} = c^n + dt v^{n+1/2},  q^{n+1} = exp(dt w^{n+1/2} / 2) q^n,  w = R I_0^-1 R^T L,
//   (the flow's rates at the new positions give F^{n+1}, tau^{n+1})
//   v^{n+1} = v^{n+1/2} + dt/2 a^{n+1},  L^{n+1} = L^{n+1/2} + dt/2 tau^{n+1},
// with M a = F_fluid + M g + F_applied (the fluid's load is the exact negative of the pair terms
// the body's particles put on the metal, WallLoad), so that metal and body conserve momentum
// pair by pair; the wall clearance's impulse is taken at once. Constraints project a and v (and
// the impulses) on the free directions; the angular momentum L (not w) is kicked, so a free
// body conserves it to round-off.
//
// The particles are placed from their places in the body's frame (restPosition, restNormal:
// the cloud as it was at the start) at every drift: x_k = c + R r_k, n_k = R n0_k, and they get
// the body's U = v + w x (x_k - c) and acceleration a + w x (w x (x_k - c)) for the flow's
// mirror states.
class RigidBody {
 public:
  // Adds the fields the body keeps in its cloud (U, acceleration, restPosition, restNormal:
  // from the cloud's present state when it does not have them yet, i.e. at the start).
  // A restart reads the state back with readState before the first step.
  // A decomposed run's body: the state on every rank alike, its particles each rank's own and
  // halo (comm: the ranks, whose particles the mass properties sum).
  RigidBody(RigidBodySettings settings, ParticleCloud& cloud, const Vector& gravity,
            const Communicator& comm = Communicator::self());

  const RigidBodySettings& settings() const { return settings_; }
  ParticleCloud& cloud() { return cloud_; }
  const ParticleCloud& cloud() const { return cloud_; }

  double mass() const { return mass_; }
  const Vector& centre() const { return centre_; }
  Vector displacement() const { return centre_ - startCentre_; }
  const Vector& velocity() const { return velocity_; }
  Vector angularVelocity() const;
  const Quaternion& orientation() const { return orientation_; }
  // The last total force (fluid + gravity + applied, before the constraints) and the fluid's
  // share of it.
  const Vector& force() const { return force_; }
  const Vector& fluidForce() const { return fluidForce_; }
  bool atEndStop() const { return atStop_; }
  // Whether a table drives the body at `time` (it still changes after it).
  bool driven(double time) const;
  // Whether the body was let go within `window` before `time` (releaseTime in (time - window,
  // time]); a body never held was let go at 0.
  bool letGoWithin(double time, double window) const;

  // The first kick and the drift to time `timeAfter` = t + dt; moves the particles.
  void kickAndDrift(double deltaT, double timeAfter);
  // The wall clearance's impulse (N s; angular, N m s about the origin), taken at once (by the
  // body unless it is held or driven) in the step of deltaT ending at `time`.
  void takeImpulse(const Vector& impulse, const Vector& angularImpulse, double deltaT, double time);
  // The loads at the new positions (fluid force, torque about the origin) and the second kick
  // of the step of deltaT ending at `time`. At the start (deltaT 0) it sets the acceleration the
  // first step's kick uses.
  void setLoadsAndKick(const Vector& fluidForce, const Vector& fluidTorque, double deltaT,
                       double time);

  // A contact with a mold (BodyWallContact.h): the centre moved by `displacement` (projected on
  // the translation constraint) and the velocity into the mold (against its outward `normal`)
  // removed; the particles placed again.
  void pushBack(const Vector& displacement, const Vector& normal);

  // The velocity each of the body's particles would have after a step of deltaT ending at
  // timeAfter under the fluid's load (force; torque about the origin), with gravity, the
  // applied load and the constraints as setLoadsAndKick and kickAndDrift take them, the body
  // left as it is: the incompressible step's strong coupling (IncompressiblePressure.h) asks it
  // at every iteration. A driven body's is its table's over the step, a held one's zero.
  void predictParticleVelocities(const Vector& fluidForce, const Vector& fluidTorque,
                                 double deltaT, double timeAfter, std::vector<Vector>& u) const;

  // The largest step the body allows: 0.25 sqrt(dx / |a|) (the particles' acceleration limit).
  double stableDeltaT(double spacing) const;

  // <time>/uniform/dynamicBodies's entry for this body, every value in full precision, and
  // reading it back (a restart continues bit for bit).
  std::string stateDictionary() const;
  void readState(const Dictionary& state, double time);

 private:
  void computeMassProperties();
  // Held where it is during every step that starts before releaseTime.
  bool held(double stepStart) const;
  void holdStill();        // no speed, no spin: the particles' U and acceleration zero
  void halfKick(Real dt);  // v and L by dt/2 of the last acceleration and torque
  Vector stopDirection() const { return settings_.endStop->normalized(); }
  Vector constrained(const Vector& linear) const;
  void placeParticles();
  // U and acceleration of the particles (zero while the body is held)
  void updateParticleVelocities(bool heldNow);
  Vector inverseInertiaTimes(const Vector& angularMomentum) const;
  Vector prescribedDisplacement(double time) const;

  RigidBodySettings settings_;
  ParticleCloud& cloud_;
  Vector gravity_;
  Communicator comm_;
  double mass_ = 0;
  Vector startCentre_ = Vector::Zero();          // the centre of mass at the rest positions
  Vector principalInertia_ = Vector::Zero();     // about the centre, in the body's frame
  Matrix3 principalAxes_ = Matrix3::Identity();  // columns: the body frame's principal axes

  Vector centre_ = Vector::Zero();
  Quaternion orientation_ = Quaternion::Identity();
  Vector velocity_ = Vector::Zero();
  Vector angularMomentum_ = Vector::Zero();
  Vector acceleration_ = Vector::Zero();  // constrained, of the last kick
  Vector torque_ = Vector::Zero();        // about the centre, of the last kick
  Vector force_ = Vector::Zero();
  Vector fluidForce_ = Vector::Zero();
  bool atStop_ = false;
};

}  // namespace sphcast
