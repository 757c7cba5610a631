// The rigid bodies of constant/dynamicBodies: their clouds and their set-up (their phases in the
// step: MovingMolds.h).
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
  models_.movingMolds = MovingMolds(
      bodySetup_, [&](const std::string& name) -> ParticleCloud& { return cloudNamed(name); },
      state, stateFile.string(), models_.walls, gravity_, time_.value(), *models_.flow,
      *models_.neighbourhood, comm_);
  for (const auto& body : models_.movingMolds.bodies()) {
    ParticleCloud* cloud = findCloud(body->cloud().name());
    if (std::find(evolving_.begin(), evolving_.end(), cloud) == evolving_.end()) {
      evolving_.push_back(cloud);
      lastGood_.push_back(*cloud);
    }
  }
  info() << "    bodies' history: postProcessing/dynamicBodies/" << time_.startTimeName()
         << "/<body>.dat (every step)\n";
}

}  // namespace sphcast
