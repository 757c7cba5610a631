// The rigid bodies of constant/dynamicBodies in the time loop: their clouds, their set-up and
// restart, their phases beside the flow's, their state in uniform/ and their history.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <utility>

#include "core/Error.h"
#include "io/VtpCloud.h"
#include "parallel/ParticleTransfer.h"
#include "solver/CastingSolver.h"

namespace sphcast {

// A body's cloud is taken from the start time when it is there (a restart, or a mold carrying
// heat), else from constant/particles: from then on it is written to every time folder, since
// it moves. It must be one of the flow's walls.
void CastingSolver::loadBodyClouds() {
  for (const RigidBodySettings& body : bodySetup_.bodies) {
    const SourceLocation& at = bodySetup_.declaredAt.at(body.name);
    if (!flowSetup_.enabled) {
      throw DictionaryError(at, "body '" + body.name +
                                    "' moves under the fluid's load, but constant/physicsModels "
                                    "has no flow");
    }
    const auto& walls = flowSetup_.wallClouds;
    if (std::find(walls.begin(), walls.end(), body.cloud) == walls.end()) {
      throw DictionaryError(at, "body '" + body.name + "' moves cloud '" + body.cloud +
                                    "', which is not one of the flow's walls (constant/"
                                    "physicsModels, flow/walls)");
    }
    if (findCloud(body.cloud)) continue;
    const auto file = caseFolder_.constant() / "particles" / (body.cloud + ".vtp");
    if (!std::filesystem::exists(file)) {
      throw DictionaryError(at, "the cloud '" + body.cloud + "' of body '" + body.name +
                                    "' is neither in time " + time_.startTimeName() +
                                    " nor in constant/particles (run particleizeMold)");
    }
    clouds_.push_back(readOnMaster([&] { return readCloudVtp(file, body.cloud); }, comm_));
    info() << "Cloud " << body.cloud << ": from constant/particles (a rigid body: written from "
           << "now on)\n";
  }
}

// The bodies over the flow's walls; a restart reads their state from uniform/dynamicBodies.
void CastingSolver::setUpBodies() {
  const auto stateFile = caseFolder_.root() / time_.startTimeName() / "uniform" / "dynamicBodies";
  std::optional<Dictionary> state;
  if (std::filesystem::exists(stateFile)) state = Dictionary::read(stateFile);
  for (const RigidBodySettings& settings : bodySetup_.bodies) {
    ParticleCloud& cloud = cloudNamed(settings.cloud);
    const bool hadRestPositions = cloud.hasVectorField("restPosition");
    auto body = std::make_unique<RigidBody>(settings, cloud, gravity_, comm_);
    if (state && state->found(settings.name)) {
      body->readState(state->subDict(settings.name), time_.value());
    } else if (hadRestPositions) {
      throw Error("cloud '" + cloud.name() + "' of time " + time_.startTimeName() +
                  " has moved as body '" + settings.name + "', but " + stateFile.string() +
                  " has no state for it");
    }
    neighbourhood_->addCloud(cloud, Neighbourhood::Motion::rigid);
    flow_->measureLoadOn(cloud);
    std::vector<const ParticleCloud*> molds;  // it may not pass into the other walls
    for (const ParticleCloud* wall : wallClouds_) {
      if (wall == &cloud) continue;
      neighbourhood_->requestPairs(cloud, *wall);
      molds.push_back(wall);
    }
    bodyMolds_.push_back(molds);
    bodyContacts_.emplace_back();
    if (std::find(evolving_.begin(), evolving_.end(), &cloud) == evolving_.end()) {
      evolving_.push_back(&cloud);
      lastGood_.push_back(cloud);
    }
    const Eigen::IOFormat plain(Eigen::StreamPrecision, Eigen::DontAlignCols, " ", " ");
    info() << "Body " << settings.name << ": cloud " << cloud.name() << " ("
           << comm_.sum(static_cast<std::int64_t>(cloud.ownedSize())) << " particles), mass "
           << body->mass() << " kg, centre (" << body->centre().transpose().format(plain) << "), ";
    if (settings.prescribed()) {
      info() << "prescribed displacement (" << settings.displacement.size() << " points)\n";
    } else {
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
      if (!settings.appliedForce.isZero(0)) {
        info() << ", applied force (" << settings.appliedForce.transpose().format(plain) << ") N";
      }
      info() << '\n';
    }
    bodies_.push_back(std::move(body));
  }
  if (!bodies_.empty()) {
    info() << "    bodies' history: postProcessing/dynamicBodies/" << time_.startTimeName()
           << "/<body>.dat (every step)\n";
  }
}

void CastingSolver::driftBodies(double deltaT) {
  for (auto& body : bodies_) body->kickAndDrift(deltaT, time_.value());
}

// In a decomposed run each rank scans its own particles of the body, and every rank moves the
// body back by the deepest contact of all (of the lowest rank at a tie).
void CastingSolver::keepBodiesOutOfMolds() {
  const double spacing = fluid_->attributes().at("spacing");
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const auto molds = wallSurfaceViews(bodies_[b]->cloud(), bodyMolds_[b], *neighbourhood_);
    BodyContact contact = deepestBodyContact(*bodies_[b], molds, neighbourhood_->periodicBox(),
                                             static_cast<Real>(spacing));
    if (parallel_) {
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
    bodyContacts_[b] = contact;
  }
}

// Two of the fluid's loads on a body, every rank's particles summed (a serial run's as they
// are): each phase reduces only the pair it takes.
std::pair<Vector, Vector> CastingSolver::summedOverRanks(const Vector& a, const Vector& b) const {
  if (!parallel_) return {a, b};
  std::vector<double> sums{a[0], a[1], a[2], b[0], b[1], b[2]};
  comm_.sum(sums);
  return {
      Vector(static_cast<Real>(sums[0]), static_cast<Real>(sums[1]), static_cast<Real>(sums[2])),
      Vector(static_cast<Real>(sums[3]), static_cast<Real>(sums[4]), static_cast<Real>(sums[5]))};
}

void CastingSolver::pushBodiesByClearance(double deltaT) {
  for (auto& body : bodies_) {
    const WallLoad& load = flow_->wallLoad(body->cloud());
    const auto [impulse, angularImpulse] =
        summedOverRanks(load.clearanceImpulse, load.clearanceAngularImpulse);
    body->takeImpulse(impulse, angularImpulse, deltaT, time_.value());
  }
}

void CastingSolver::kickBodies(double deltaT) {
  for (auto& body : bodies_) {
    const WallLoad& load = flow_->wallLoad(body->cloud());
    const auto [force, torque] = summedOverRanks(load.force, load.torque);
    body->setLoadsAndKick(force, torque, deltaT, time_.value());
  }
}

void CastingSolver::logBodies() {
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
    if (bodyContacts_[b].depth > 0) {
      line << "  touched a mold (moved back "
           << bodyContacts_[b].depth / fluid_->attributes().at("spacing") << " dx)";
    }
    info() << line.str() << '\n';
  }
}

}  // namespace sphcast
