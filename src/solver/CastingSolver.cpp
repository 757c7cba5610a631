#include "solver/CastingSolver.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <ostream>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "io/VtpCloud.h"
#include "core/Gravity.h"

namespace sphcast {

CastingSolver::CastingSolver(const CaseFolder& caseFolder)
    : caseFolder_(caseFolder),
      repairedWrites_(caseFolder.recoverInterruptedWrites()),
      time_(caseFolder),
      gravity_(readGravity(caseFolder)),
      motion_(gravity_),
      flowSetup_(readFlowSetup(caseFolder, gravity_)),
      writer_(caseFolder, time_.settings().purgeWrite) {
  for (const std::string& repaired : repairedWrites_) {
    info() << "Repaired interrupted write: " << repaired << std::endl;
  }
  info() << "Starting from time " << time_.startTimeName() << " (index " << time_.timeIndex()
         << ")\n";
  clouds_ = readTimeFolderClouds(caseFolder_, time_.startTimeName());
  if (clouds_.empty()) {
    throw Error("time folder " + (caseFolder_.root() / time_.startTimeName()).string() +
                " holds no cloud (.vtp) to run");
  }
  if (flowSetup_.enabled) {
    setUpFlow();
  } else {
    for (const ParticleCloud& cloud : clouds_) {
      info() << "Cloud " << cloud.name() << ": " << cloud.size() << " particles"
             << (cloud.hasVectorField("U") ? ", moving ballistically" : ", static (no U field)")
             << '\n';
      if (time_.settings().adjustTimeStep && cloud.hasVectorField("U")) {
        motion_.stableDeltaT(cloud, time_.settings().maxCo);  // fail now, not after writing
      }
    }
  }
  setUpFunctionObjects();
  info() << std::endl;
}

ParticleCloud* CastingSolver::findCloud(const std::string& name) {
  for (ParticleCloud& cloud : clouds_) {
    if (cloud.name() == name) return &cloud;
  }
  return nullptr;
}

ParticleCloud& CastingSolver::cloudNamed(const std::string& name) {
  if (ParticleCloud* cloud = findCloud(name)) return *cloud;
  std::string present;
  for (const ParticleCloud& cloud : clouds_) present += " " + cloud.name();
  throw Error("constant/physicsModels names the fluid cloud '" + name + "', but time " +
              time_.startTimeName() + " holds only (" + present + " )");
}

void CastingSolver::setUpFlow() {
  ParticleCloud& fluid = cloudNamed(flowSetup_.fluidCloud);
  for (const std::string& added : prepareFluidFields(flowSetup_, fluid)) {
    info() << "Cloud " << fluid.name() << ": initial " << added << " from constant/\n";
  }
  // A wall cloud is taken from the start time when it is there (setCastFields may have set its
  // fields), else from constant/particles, where particleizeMold wrote it.
  std::vector<const ParticleCloud*> walls;
  for (const std::string& wallName : flowSetup_.wallClouds) {
    if (const ParticleCloud* inTime = findCloud(wallName)) {
      walls.push_back(inTime);
      continue;
    }
    const auto file = caseFolder_.constant() / "particles" / (wallName + ".vtp");
    if (!std::filesystem::exists(file)) {
      throw Error("wall cloud '" + wallName + "' is neither in time " + time_.startTimeName() +
                  " nor in constant/particles (run particleizeMold)");
    }
    staticClouds_.push_back(readCloudVtp(file, wallName));
  }
  for (const ParticleCloud& wall : staticClouds_) walls.push_back(&wall);
  flow_ = std::make_unique<WeaklyCompressibleFlow>(flowSetup_.settings, fluid, walls);
  fluid_ = &fluid;
  lastGoodFluid_ = std::make_unique<ParticleCloud>(fluid);
  domain_ = walls.empty() ? defaultDomain({&fluid}) : defaultDomain(walls);
  const FlowSettings& settings = flowSetup_.settings;
  info() << "Flow: weakly compressible SPH (" << settings.dimension << "D), densityScheme "
         << settings.densityScheme << ", kernelCorrection "
         << (settings.kernelCorrection ? "on" : "off") << ", viscousForm " << settings.viscousForm
         << ", h = " << settings.supportRadius << " m, c = " << settings.soundSpeed << " m/s\n"
         << "    fluid " << fluid.name() << ": " << fluid.size() << " particles, "
         << flow_->fluidPairCount() << " pairs\n";
  for (const ParticleCloud* wall : walls) {
    info() << "    wall " << wall->name() << ": " << wall->size() << " particles\n";
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (!settings.periodic.isPeriodic(axis)) continue;
    info() << "    periodic " << "xyz"[axis] << ": [" << settings.periodic.lower(axis) << ", "
           << settings.periodic.lower(axis) + settings.periodic.period(axis) << ")\n";
  }
  const Eigen::IOFormat plain(Eigen::StreamPrecision, Eigen::DontAlignCols, " ", " ");
  info() << "    domain (" << domain_.lower.transpose().format(plain) << ") ("
         << domain_.upper.transpose().format(plain)
         << "): a particle outside it, or not finite, stops the run\n";
  // Everything else stays where it is: only the fluid moves.
}

void CastingSolver::setUpFunctionObjects() {
  FunctionObjectContext context;
  context.caseRoot = caseFolder_.root();
  context.startTimeName = time_.startTimeName();
  context.startTime = time_.startValue();
  context.supportRadius = flowSetup_.enabled ? flowSetup_.settings.supportRadius : Real(0);
  context.gravity = gravity_;
  for (const ParticleCloud& cloud : clouds_) context.clouds.push_back(&cloud);
  functions_ = FunctionObjectList(Dictionary::read(caseFolder_.systemFile("controlDict")), context);
  for (const auto& object : functions_.objects()) {
    info() << "Function object " << object->name() << ": postProcessing/" << object->name() << '/'
           << time_.startTimeName() << '\n';
  }
}

double CastingSolver::stableDeltaT(std::string& limiter) const {
  if (flow_) return flow_->stepLimits(time_.settings().maxCo).smallest(limiter);
  limiter = "maxCo on particle travel";
  double stable = std::numeric_limits<double>::max();
  for (const ParticleCloud& cloud : clouds_) {
    if (cloud.hasVectorField("U")) {
      stable = std::min(stable, motion_.stableDeltaT(cloud, time_.settings().maxCo));
    }
  }
  return stable;
}

void CastingSolver::evolve(double deltaT) {
  if (flow_) {
    flow_->step(deltaT);
    return;
  }
  for (ParticleCloud& cloud : clouds_) {
    if (cloud.hasVectorField("U")) motion_.step(cloud, deltaT);
  }
}

void CastingSolver::writeResults() {
  std::vector<const ParticleCloud*> written;
  for (const ParticleCloud& cloud : clouds_) written.push_back(&cloud);
  writer_.setPurgeWrite(time_.settings().purgeWrite);
  writer_.write(time_.state(), written);
  info() << "Writing time " << time_.timeName() << std::endl;
}

void CastingSolver::logStep(bool printBlock) {
  if (!printBlock) return;
  info() << "deltaT = " << time_.deltaT() << "  (" << time_.deltaTLimiter() << ")\n"
         << "Time = " << time_.timeName() << "\n\n";
  if (flow_) {
    const auto [lowest, highest] = flow_->densityRange();
    info() << "Density range " << lowest << " .. " << highest << " kg/m^3\n";
  }
  info() << clock_.timesLine() << '\n'
         << clock_.progressLine(time_.progress(), stepsTaken_) << '\n'
         << std::endl;  // flushed: a killed run's log ends at its last step
}

void CastingSolver::logRereadMessage() {
  const std::string message = time_.takeRereadMessage();
  if (!message.empty()) info() << message << "\n\n";
}

void CastingSolver::stopIfParticlesWentBad(const TimeState& before) {
  const ParticleCheck check = checkParticles(*fluid_, domain_);
  if (check.good()) return;
  const std::string what = check.describe(*fluid_, domain_);
  *fluid_ = *lastGoodFluid_;
  std::vector<const ParticleCloud*> written;
  for (const ParticleCloud& cloud : clouds_) written.push_back(&cloud);
  writer_.write(before, written);
  throw Error("at time " + time_.timeName() + " (step " + std::to_string(time_.timeIndex()) +
              "): " + what + ". The last good state, time " + before.name +
              ", is written; restart from it with a smaller maxCo or deltaT, or look for a "
              "gap in the walls there.");
}

void CastingSolver::run() {
  info() << "Starting time loop\n\n";
  functions_.execute(time_.state(), false);
  while (time_.run()) {
    logRereadMessage();
    std::string limiter;
    const double stable = stableDeltaT(limiter);
    time_.adjustDeltaT(stable, limiter);
    const TimeState before = time_.state();
    if (flow_) *lastGoodFluid_ = *fluid_;  // reuses its storage: no allocation per step
    time_.advance();
    ++stepsTaken_;
    evolve(time_.deltaT());
    if (flow_) stopIfParticlesWentBad(before);
    const bool printBlock = stepsTaken_ % time_.settings().logInterval == 0 || time_.writeTime();
    logStep(printBlock);
    if (time_.writeTime()) writeResults();
    functions_.execute(time_.state(), time_.writeTime());
  }
  logRereadMessage();
  info() << "Stopping: " << time_.stopReason() << " at time " << time_.timeName() << '\n';
  if (time_.finalWriteWanted()) writeResults();
  info() << clock_.timesLine() << "\n\nEnd\n\n";
}

}  // namespace sphcast
