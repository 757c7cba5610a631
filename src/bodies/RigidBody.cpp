#include "bodies/RigidBody.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <type_traits>
#include <vector>

#include <Eigen/Eigenvalues>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "particles/FieldNames.h"

namespace sphcast {

RigidBody::RigidBody(RigidBodySettings settings, ParticleCloud& cloud, const Vector& gravity,
                     const Communicator& comm)
    : settings_(std::move(settings)), cloud_(cloud), gravity_(gravity), comm_(comm) {
  if (comm_.sum(static_cast<std::int64_t>(cloud_.ownedSize())) == 0) {
    throw Error("body '" + settings_.name + "': its cloud '" + cloud_.name() + "' is empty");
  }
  cloud_.scalarField(field::volume);  // each look-up throws an Error naming the cloud's fields
  const auto& normal = cloud_.vectorField(field::normal);
  // the places in the body's frame: the cloud as it is at the start (a restart reads them back)
  if (!cloud_.hasVectorField(field::restPosition)) {
    cloud_.addVectorField(field::restPosition) = cloud_.positions();
    cloud_.addVectorField(field::restNormal) = normal;
  }
  // the second feet of particleizeMold (geometry/WallSurfacePatches.h) turn with the body too
  if (cloud_.hasVectorField(field::secondNormal) &&
      !cloud_.hasVectorField(field::restSecondNormal)) {
    cloud_.addVectorField(field::restSecondNormal) = cloud_.vectorField(field::secondNormal);
  }
  cloud_.addVectorField(field::U);
  cloud_.addVectorField(field::acceleration);
  computeMassProperties();
  centre_ = startCentre_;
  // until the first loads (setLoadsAndKick with dt 0 at the start): gravity and the press
  force_ = static_cast<Real>(mass_) * gravity_ + settings_.appliedForceAt(0);
  // a driven body's acceleration is the table's: zero between its points
  if (!settings_.prescribed()) acceleration_ = constrained(force_ / static_cast<Real>(mass_));
}

// Uniform density over the particles' volumes (each particle a cube of its volume for its own
// inertia), unless the dictionary gives the values.
void RigidBody::computeMassProperties() {
  const auto& rest = cloud_.vectorField(field::restPosition);
  const auto& volume = cloud_.scalarField(field::volume);
  // over every rank's own particles in a decomposed run
  std::vector<double> sums(4, 0.0);  // the volume, its first moment
  for (std::size_t k = 0; k < cloud_.ownedSize(); ++k) {
    sums[0] += volume[k];
    for (int a = 0; a < 3; ++a) sums[1 + a] += double(volume[k]) * double(rest[k][a]);
  }
  comm_.sum(sums);
  const double totalVolume = sums[0];
  const Vector moment(static_cast<Real>(sums[1]), static_cast<Real>(sums[2]),
                      static_cast<Real>(sums[3]));
  if (!(totalVolume > 0)) {
    throw Error("body '" + settings_.name + "': the particles of cloud '" + cloud_.name() +
                "' have no volume");
  }
  mass_ = settings_.mass ? *settings_.mass : *settings_.density * totalVolume;
  startCentre_ = settings_.centreOfMass ? *settings_.centreOfMass
                                        : Vector(moment / static_cast<Real>(totalVolume));
  if (settings_.momentOfInertia) {
    principalInertia_ = *settings_.momentOfInertia;
    principalAxes_.setIdentity();
    return;
  }
  const Real density = static_cast<Real>(mass_ / totalVolume);
  // each particle's own: a cube (2D: a square) of side dx, m dx^2 / 6 about its centre
  const auto spacing = cloud_.attributes().find("spacing");
  Matrix3 inertia = Matrix3::Zero();
  for (std::size_t k = 0; k < cloud_.ownedSize(); ++k) {
    const Vector d = rest[k] - startCentre_;
    const Real m = density * volume[k];
    const Real side = spacing != cloud_.attributes().end() ? static_cast<Real>(spacing->second)
                                                           : std::cbrt(volume[k]);
    const Real own = m * side * side / 6;
    inertia +=
        m * (d.squaredNorm() * Matrix3::Identity() - d * d.transpose()) + own * Matrix3::Identity();
  }
  std::vector<double> entries(inertia.data(), inertia.data() + 9);
  comm_.sum(entries);
  for (int e = 0; e < 9; ++e) inertia.data()[e] = static_cast<Real>(entries[e]);
  const Eigen::SelfAdjointEigenSolver<Matrix3> principal(inertia);
  principalInertia_ = principal.eigenvalues();
  principalAxes_ = principal.eigenvectors();
}

Vector RigidBody::inverseInertiaTimes(const Vector& angularMomentum) const {
  const Matrix3 axes = orientation_.toRotationMatrix() * principalAxes_;
  Vector inBody = axes.transpose() * angularMomentum;
  for (int a = 0; a < 3; ++a) {
    inBody[a] = principalInertia_[a] > 0 ? inBody[a] / principalInertia_[a] : Real(0);
  }
  return axes * inBody;
}

Vector RigidBody::angularVelocity() const {
  if (settings_.rotationLocked || settings_.prescribed()) return Vector::Zero();
  return inverseInertiaTimes(angularMomentum_);
}

bool RigidBody::driven(double time) const {
  return settings_.prescribed() && time < std::get<0>(settings_.displacement.back());
}

bool RigidBody::letGoWithin(double time, double window) const {
  return !settings_.prescribed() && settings_.releaseTime <= time &&
         time < settings_.releaseTime + window;
}

bool RigidBody::held(double stepStart) const {
  return !settings_.prescribed() && stepStart < settings_.releaseTime;
}

Vector RigidBody::constrained(const Vector& linear) const {
  switch (settings_.translation) {
    case RigidBodySettings::Translation::free:
      return linear;
    case RigidBodySettings::Translation::axis:
      return linear.dot(settings_.axis) * settings_.axis;
    case RigidBodySettings::Translation::locked:
      break;
  }
  return Vector::Zero();
}

namespace {

// A table's value at `time`: linear between its points, held at its ends.
template <class Value>
Value tableAt(const std::vector<std::tuple<double, Value>>& table, double time) {
  if (time <= std::get<0>(table.front())) return std::get<1>(table.front());
  if (time >= std::get<0>(table.back())) return std::get<1>(table.back());
  const auto after = std::upper_bound(
      table.begin(), table.end(), time,
      [](double t, const std::tuple<double, Value>& point) { return t < std::get<0>(point); });
  const auto before = after - 1;
  const double t0 = std::get<0>(*before), t1 = std::get<0>(*after);
  const double weight = (time - t0) / (t1 - t0);
  if constexpr (std::is_same_v<Value, double>) {
    return (1 - weight) * std::get<1>(*before) + weight * std::get<1>(*after);
  } else {
    const Real w = static_cast<Real>(weight);
    return (1 - w) * std::get<1>(*before) + w * std::get<1>(*after);
  }
}

}  // namespace

Vector RigidBodySettings::appliedForceAt(double time) const {
  Vector force = Vector::Zero();
  if (!appliedForce.empty()) force += tableAt(appliedForce, time);
  if (!appliedPressure.empty()) {
    force += static_cast<Real>(tableAt(appliedPressure, time) * pressedArea) * pressDirection;
  }
  return force;
}

Vector RigidBody::prescribedDisplacement(double time) const {
  return tableAt(settings_.displacement, time);
}

// x_k = x0_k + d + (R - I) r_k: with R = I exactly (no rotation) a particle moves by d alone,
// so a 2D body stays on its plane to the bit.
void RigidBody::placeParticles() {
  const Matrix3 rotation = orientation_.toRotationMatrix();
  const Matrix3 turn = rotation - Matrix3::Identity();
  const Vector travel = centre_ - startCentre_;
  const auto& rest = cloud_.vectorField(field::restPosition);
  const auto& restNormal = cloud_.vectorField(field::restNormal);
  auto& x = cloud_.positions();
  auto& normal = cloud_.vectorField(field::normal);
  // the second feet of particleizeMold (geometry/WallSurfacePatches.h), where it gave any
  const bool seconds = cloud_.hasVectorField(field::restSecondNormal);
  const Vector* restSecond = seconds ? cloud_.vectorField(field::restSecondNormal).data() : nullptr;
  Vector* second = seconds ? cloud_.vectorField(field::secondNormal).data() : nullptr;
  const bool turned = !turn.isZero(0);
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = turned ? Vector(rest[k] + travel + turn * (rest[k] - startCentre_))
                  : Vector(rest[k] + travel);
    normal[k] = turned ? Vector(rotation * restNormal[k]) : restNormal[k];
    if (seconds) second[k] = turned ? Vector(rotation * restSecond[k]) : restSecond[k];
  }
}

void RigidBody::updateParticleVelocities(bool heldNow) {
  const Vector omega = angularVelocity();
  const Vector linearAcceleration = heldNow ? Vector::Zero() : acceleration_;
  const auto& x = cloud_.positions();
  auto& u = cloud_.vectorField(field::U);
  auto& a = cloud_.vectorField(field::acceleration);
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < x.size(); ++k) {
    const Vector arm = x[k] - centre_;
    u[k] = velocity_ + omega.cross(arm);
    a[k] = linearAcceleration + omega.cross(omega.cross(arm));
  }
}

void RigidBody::holdStill() {
  velocity_.setZero();
  angularMomentum_.setZero();
  updateParticleVelocities(true);
}

void RigidBody::halfKick(Real dt) {
  velocity_ += Real(0.5) * dt * acceleration_;
  if (!settings_.rotationLocked) angularMomentum_ += Real(0.5) * dt * torque_;
}

void RigidBody::kickAndDrift(double deltaT, double timeAfter) {
  const Real dt = static_cast<Real>(deltaT);
  if (settings_.prescribed()) {
    const Vector before = prescribedDisplacement(timeAfter - deltaT);
    const Vector after = prescribedDisplacement(timeAfter);
    centre_ = startCentre_ + after;
    velocity_ = (after - before) / dt;
    placeParticles();
    updateParticleVelocities(false);
    return;
  }
  if (held(timeAfter - deltaT)) {
    holdStill();
    return;
  }
  halfKick(dt);
  centre_ += dt * velocity_;
  if (settings_.endStop) {
    const Vector direction = stopDirection();
    const Real beyond = (centre_ - startCentre_).dot(direction) - settings_.endStop->norm();
    if (beyond >= 0) {  // a hard stop: at the stop, with no speed into it
      centre_ -= beyond * direction;
      velocity_ -= std::max(velocity_.dot(direction), Real(0)) * direction;
      atStop_ = true;
    }
  }
  if (!settings_.rotationLocked) {
    const Vector omega = angularVelocity();
    const Real angle = omega.norm() * dt;
    if (angle > 0) {
      orientation_ = (Quaternion(Eigen::AngleAxis<Real>(angle, omega.normalized())) * orientation_)
                         .normalized();
    }
  }
  placeParticles();
  updateParticleVelocities(false);
}

void RigidBody::predictParticleVelocities(const Vector& fluidForce, const Vector& fluidTorque,
                                          double deltaT, double timeAfter,
                                          std::vector<Vector>& u) const {
  const auto& x = cloud_.positions();
  u.resize(x.size());
  Vector velocity = Vector::Zero();
  Vector omega = Vector::Zero();
  if (settings_.prescribed()) {
    velocity = (prescribedDisplacement(timeAfter) - prescribedDisplacement(timeAfter - deltaT)) /
               static_cast<Real>(deltaT);
  } else if (!held(timeAfter - deltaT)) {
    const Vector force =
        fluidForce + static_cast<Real>(mass_) * gravity_ + settings_.appliedForceAt(timeAfter);
    Vector acceleration = constrained(force / static_cast<Real>(mass_));
    if (atStop_) {  // the stop holds what pushes into it
      const Vector direction = stopDirection();
      acceleration -= std::max(acceleration.dot(direction), Real(0)) * direction;
    }
    velocity = velocity_ + static_cast<Real>(deltaT) * acceleration;
    if (!settings_.rotationLocked) {
      omega = inverseInertiaTimes(angularMomentum_ + static_cast<Real>(deltaT) *
                                                         (fluidTorque - centre_.cross(fluidForce)));
    }
  }
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < x.size(); ++k) u[k] = velocity + omega.cross(Vector(x[k] - centre_));
}

void RigidBody::takeImpulse(const Vector& impulse, const Vector& angularImpulse, double deltaT,
                            double time) {
  if (settings_.prescribed() || held(time - deltaT)) return;  // the machine, or the holder
  velocity_ += constrained(impulse / static_cast<Real>(mass_));
  if (atStop_) {  // the stop takes what pushes into it
    const Vector direction = stopDirection();
    velocity_ -= std::max(velocity_.dot(direction), Real(0)) * direction;
  }
  if (!settings_.rotationLocked) angularMomentum_ += angularImpulse - centre_.cross(impulse);
  updateParticleVelocities(false);
}

void RigidBody::setLoadsAndKick(const Vector& fluidForce, const Vector& fluidTorque, double deltaT,
                                double time) {
  const Real dt = static_cast<Real>(deltaT);
  fluidForce_ = fluidForce;
  force_ = fluidForce + static_cast<Real>(mass_) * gravity_ + settings_.appliedForceAt(time);
  torque_ = fluidTorque - centre_.cross(fluidForce);  // gravity and the applied force: at c
  if (settings_.prescribed()) {
    updateParticleVelocities(false);
    return;
  }
  Vector acceleration = constrained(force_ / static_cast<Real>(mass_));
  if (atStop_) {
    const Vector direction = stopDirection();
    const Real into = acceleration.dot(direction);
    if (into >= 0) {
      acceleration -= into * direction;  // the stop holds it
    } else {
      atStop_ = false;  // pulled back off the stop
    }
  }
  acceleration_ = acceleration;
  if (held(time - deltaT)) {
    holdStill();
    return;
  }
  halfKick(dt);
  updateParticleVelocities(false);
}

void RigidBody::pushBack(const Vector& displacement, const Vector& normal) {
  if (settings_.prescribed()) return;  // the machine drives it
  centre_ += constrained(displacement);
  const Real into = velocity_.dot(normal);
  if (into < 0) velocity_ -= constrained(into * normal);
  placeParticles();
  updateParticleVelocities(false);
}

double RigidBody::stableDeltaT(double spacing) const {
  const double a = acceleration_.norm();
  return a > 0 ? 0.25 * std::sqrt(spacing / a) : std::numeric_limits<double>::infinity();
}

namespace {
std::string vectorText(const Vector& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.17g %.17g %.17g)", static_cast<double>(v[0]),
                static_cast<double>(v[1]), static_cast<double>(v[2]));
  return text;
}
}  // namespace

std::string RigidBody::stateDictionary() const {
  char quaternion[128];
  std::snprintf(quaternion, sizeof quaternion, "(%.17g %.17g %.17g %.17g)",
                static_cast<double>(orientation_.w()), static_cast<double>(orientation_.x()),
                static_cast<double>(orientation_.y()), static_cast<double>(orientation_.z()));
  std::string text = settings_.name + "\n{\n";
  auto line = [&text](const char* key, const std::string& value) {
    char padded[32];
    std::snprintf(padded, sizeof padded, "    %-16s", key);
    text += padded + value + ";\n";
  };
  line("centreOfMass", vectorText(centre_));
  line("displacement", vectorText(centre_ - startCentre_));
  line("orientation", quaternion);  // (w x y z)
  line("velocity", vectorText(velocity_));
  line("angularMomentum", vectorText(angularMomentum_));
  line("angularVelocity", vectorText(angularVelocity()));
  line("acceleration", vectorText(acceleration_));
  line("torque", vectorText(torque_));
  line("force", vectorText(force_));
  line("fluidForce", vectorText(fluidForce_));
  line("atEndStop", atStop_ ? "yes" : "no");
  return text + "}\n";
}

void RigidBody::readState(const Dictionary& state, double time) {
  centre_ = state.get<Vector>("centreOfMass");
  const auto q = state.get<std::vector<double>>("orientation");
  if (q.size() != 4) {
    throw DictionaryError(state.location("orientation"),
                          "'orientation' in " + state.name() + " must be a quaternion (w x y z)");
  }
  orientation_ = Quaternion(static_cast<Real>(q[0]), static_cast<Real>(q[1]),
                            static_cast<Real>(q[2]), static_cast<Real>(q[3]));
  velocity_ = state.get<Vector>("velocity");
  angularMomentum_ = state.get<Vector>("angularMomentum");
  acceleration_ = state.get<Vector>("acceleration");
  torque_ = state.get<Vector>("torque");
  force_ = state.get<Vector>("force");
  fluidForce_ = state.get<Vector>("fluidForce");
  atStop_ = state.get<bool>("atEndStop");
  placeParticles();
  updateParticleVelocities(held(time) && velocity_.isZero(0));
}

}  // namespace sphcast
