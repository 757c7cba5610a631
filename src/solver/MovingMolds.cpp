#include "solver/MovingMolds.h"

#include <sstream>

#include "core/Error.h"
#include "core/Log.h"
#include "particles/FieldNames.h"

namespace sphcast {

namespace {

void logBody(const RigidBody& body, const RigidBodySettings& settings, const ParticleCloud& cloud,
             const Communicator& comm) {
  const Eigen::IOFormat plain(Eigen::StreamPrecision, Eigen::DontAlignCols, " ", " ");
  info() << "Body " << settings.name << ": cloud " << cloud.name() << " ("
         << comm.sum(static_cast<std::int64_t>(cloud.ownedSize())) << " particles), mass "
         << body.mass() << " kg, centre (" << body.centre().transpose().format(plain) << "), ";
  if (settings.prescribed()) {
    info() << "prescribed displacement (" << settings.displacement.size() << " points)\n";
    return;
  }
  switch (settings.translation) {
    case RigidBodySettings::Translation::free:
      info() << "translation free";
      break;
    case RigidBodySettings::Translation::axis:
      info() << "translation along (" << settings.axis.transpose().format(plain) << ")";
      break;
    case RigidBodySettings::Translation::locked:
      info() << "translation locked";
      break;
  }
  info() << ", rotation " << (settings.rotationLocked ? "locked" : "free");
  if (settings.releaseTime > 0) info() << ", held until t = " << settings.releaseTime << " s";
  if (settings.endStop) {
    info() << ", end stop at a travel of (" << settings.endStop->transpose().format(plain)
           << ") (hard: no rebound)";
  }
  if (settings.appliedForce.size() == 1) {
    info() << ", applied force (" << std::get<1>(settings.appliedForce[0]).transpose().format(plain)
           << ") N";
  } else if (!settings.appliedForce.empty()) {
    const auto& [t1, last] = settings.appliedForce.back();
    info() << ", applied force against time (" << settings.appliedForce.size() << " points, ("
           << last.transpose().format(plain) << ") N from t = " << t1 << " s)";
  }
  if (!settings.appliedPressure.empty()) {
    const auto& [t1, last] = settings.appliedPressure.back();
    info() << ", pressed at " << last << " Pa from t = " << t1 << " s ("
           << settings.appliedPressure.size() << " points) on " << settings.pressedArea
           << " m^2 along (" << settings.pressDirection.transpose().format(plain)
           << "): " << last * settings.pressedArea << " N";
  }
  info() << '\n';
}

}  // namespace

MovingMolds::MovingMolds(const BodySetup& setup,
                         const std::function<ParticleCloud&(const std::string&)>& cloudOf,
                         const std::optional<Dictionary>& state, const std::string& stateFile,
                         const std::vector<const ParticleCloud*>& walls, const Vector& gravity,
                         double time, WeaklyCompressibleFlow& flow, Neighbourhood& neighbourhood,
                         const Communicator& comm)
    : flow_(&flow), neighbourhood_(&neighbourhood), comm_(comm) {
  for (const RigidBodySettings& settings : setup.bodies) {
    ParticleCloud& cloud = cloudOf(settings.cloud);
    const bool hadRestPositions = cloud.hasVectorField(field::restPosition);
    auto body = std::make_unique<RigidBody>(settings, cloud, gravity, comm_);
    if (state && state->found(settings.name)) {
      body->readState(state->subDict(settings.name), time);
    } else if (hadRestPositions) {
      throw Error("cloud '" + cloud.name() + "' has moved as body '" + settings.name + "', but " +
                  stateFile + " has no state for it");
    }
    neighbourhood.addCloud(cloud, Neighbourhood::Motion::rigid);
    flow.measureLoadOn(cloud);
    std::vector<const ParticleCloud*> molds;  // it may not pass into the other walls
    for (const ParticleCloud* wall : walls) {
      if (wall == &cloud) continue;
      neighbourhood.requestPairs(cloud, *wall);
      molds.push_back(wall);
    }
    otherMolds_.push_back(molds);
    contacts_.emplace_back();
    logBody(*body, settings, cloud, comm_);
    bodies_.push_back(std::move(body));
  }
}

std::vector<const RigidBody*> MovingMolds::bodyList() const {
  std::vector<const RigidBody*> list;
  for (const auto& body : bodies_) list.push_back(body.get());
  return list;
}

void MovingMolds::drift(double deltaT, double time) {
  for (auto& body : bodies_) body->kickAndDrift(deltaT, time);
}

void MovingMolds::keepOutOfMolds(Real spacing) {
  const bool parallel = comm_.size() > 1;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const auto molds = wallSurfaceViews(bodies_[b]->cloud(), otherMolds_[b], *neighbourhood_);
    BodyContact contact =
        deepestBodyContact(*bodies_[b], molds, neighbourhood_->periodicBox(), spacing);
    if (parallel) {
      const double deepest = comm_.max(static_cast<double>(contact.depth));
      const bool mine = deepest > 0 && static_cast<double>(contact.depth) == deepest;
      const double first = comm_.min(mine ? double(comm_.rank()) : double(comm_.size()));
      std::vector<double> normal(3, 0.0);
      if (mine && first == double(comm_.rank())) {
        for (int a = 0; a < 3; ++a) normal[a] = contact.normal[a];
      }
      comm_.sum(normal);
      contact.depth = static_cast<Real>(deepest);
      contact.normal = Vector(static_cast<Real>(normal[0]), static_cast<Real>(normal[1]),
                              static_cast<Real>(normal[2]));
    }
    if (contact.depth > 0) bodies_[b]->pushBack(contact.depth * contact.normal, contact.normal);
    contacts_[b] = contact;
  }
}

std::pair<Vector, Vector> MovingMolds::summedOverRanks(const Vector& a, const Vector& b) const {
  if (comm_.size() == 1) return {a, b};
  std::vector<double> sums{a[0], a[1], a[2], b[0], b[1], b[2]};
  comm_.sum(sums);
  return {
      Vector(static_cast<Real>(sums[0]), static_cast<Real>(sums[1]), static_cast<Real>(sums[2])),
      Vector(static_cast<Real>(sums[3]), static_cast<Real>(sums[4]), static_cast<Real>(sums[5]))};
}

void MovingMolds::pushByClearance(double deltaT, double time) {
  for (auto& body : bodies_) {
    const WallLoad& load = flow_->wallLoad(body->cloud());
    const auto [impulse, angularImpulse] =
        summedOverRanks(load.clearanceImpulse, load.clearanceAngularImpulse);
    body->takeImpulse(impulse, angularImpulse, deltaT, time);
  }
}

void MovingMolds::kick(double deltaT, double time) {
  for (auto& body : bodies_) {
    const WallLoad& load = flow_->wallLoad(body->cloud());
    const auto [force, torque] = summedOverRanks(load.force, load.torque);
    body->setLoadsAndKick(force, torque, deltaT, time);
  }
}

bool MovingMolds::predictVelocities(const ParticleCloud& wall, const Vector& force,
                                    const Vector& torque, double deltaT, double timeAfter,
                                    std::vector<Vector>& velocity) const {
  for (const auto& body : bodies_) {
    if (&body->cloud() != &wall) continue;
    body->predictParticleVelocities(force, torque, deltaT, timeAfter, velocity);
    return true;
  }
  return false;
}

double MovingMolds::limitStep(double stable, double spacing, std::string& limiter) const {
  for (const auto& body : bodies_) {
    const double limit = body->stableDeltaT(spacing);
    if (limit < stable) {
      stable = limit;
      limiter = "body " + body->settings().name + "'s acceleration";
    }
  }
  return stable;
}

void MovingMolds::saveState() {
  lastGood_.resize(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) lastGood_[b] = bodies_[b]->stateDictionary();
}

void MovingMolds::restoreState(double time) {
  for (std::size_t b = 0; b < bodies_.size() && b < lastGood_.size(); ++b) {
    const Dictionary state = Dictionary::parse(lastGood_[b], "dynamicBodies");
    bodies_[b]->readState(state.subDict(bodies_[b]->settings().name), time);
  }
}

std::string MovingMolds::stateFileText(const std::string& timeName) const {
  return bodyStateFile(timeName, bodyList());
}

void MovingMolds::log(double spacing) const {
  const Eigen::IOFormat plain(Eigen::StreamPrecision, Eigen::DontAlignCols, " ", " ");
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const RigidBody& body = *bodies_[b];
    std::ostringstream line;
    line.precision(6);
    line << "Body " << body.settings().name << ": travel ("
         << body.displacement().transpose().format(plain) << ") m  velocity ("
         << body.velocity().transpose().format(plain) << ") m/s  fluid force ("
         << body.fluidForce().transpose().format(plain) << ") N"
         << (body.atEndStop() ? "  at the end stop" : "");
    if (contacts_[b].depth > 0)
      line << "  touched a mold (moved back " << contacts_[b].depth / spacing << " dx)";
    info() << line.str() << '\n';
  }
}

}  // namespace sphcast
