#include "solver/CastingSolver.h"

#include <algorithm>
#include <limits>
#include <ostream>

#include "core/Error.h"
#include "solver/Gravity.h"

namespace sphcast {

CastingSolver::CastingSolver(const CaseFolder& caseFolder)
    : caseFolder_(caseFolder),
      time_(caseFolder),
      motion_(readGravity(caseFolder)),
      writer_(caseFolder, time_.settings().purgeWrite) {
  for (const std::string& repaired : caseFolder_.recoverInterruptedWrites()) {
    info() << "Repaired interrupted write: " << repaired << std::endl;
  }
  info() << "Starting from time " << time_.startTimeName() << " (index " << time_.timeIndex()
         << ")\n";
  clouds_ = readTimeFolderClouds(caseFolder_, time_.startTimeName());
  if (clouds_.empty()) {
    throw Error("time folder " + (caseFolder_.root() / time_.startTimeName()).string() +
                " holds no cloud (.vtp) to run");
  }
  for (const ParticleCloud& cloud : clouds_) {
    info() << "Cloud " << cloud.name() << ": " << cloud.size() << " particles"
           << (cloud.hasVectorField("U") ? ", moving" : ", static (no U field)") << '\n';
    if (time_.settings().adjustTimeStep && cloud.hasVectorField("U")) {
      motion_.stableDeltaT(cloud, time_.settings().maxCo);  // fail now, not after writing
    }
  }
  info() << std::endl;
}

double CastingSolver::stableDeltaT() const {
  double stable = std::numeric_limits<double>::max();
  for (const ParticleCloud& cloud : clouds_) {
    if (cloud.hasVectorField("U")) {
      stable = std::min(stable, motion_.stableDeltaT(cloud, time_.settings().maxCo));
    }
  }
  return stable;
}

void CastingSolver::evolve(double deltaT) {
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
         << "Time = " << time_.timeName() << "\n\n"
         << clock_.timesLine() << '\n'
         << clock_.progressLine(time_.progress(), stepsTaken_) << '\n'
         << std::endl;  // flushed: a killed run's log ends at its last step
}

void CastingSolver::logRereadMessage() {
  const std::string message = time_.takeRereadMessage();
  if (!message.empty()) info() << message << "\n\n";
}

void CastingSolver::run() {
  info() << "Starting time loop\n\n";
  while (time_.run()) {
    logRereadMessage();
    time_.adjustDeltaT(stableDeltaT(), "maxCo on particle travel");
    time_.advance();
    ++stepsTaken_;
    evolve(time_.deltaT());
    const bool printBlock = stepsTaken_ % time_.settings().logInterval == 0 || time_.writeTime();
    logStep(printBlock);
    if (time_.writeTime()) writeResults();
  }
  logRereadMessage();
  info() << "Stopping: " << time_.stopReason() << " at time " << time_.timeName() << '\n';
  if (time_.finalWriteWanted()) writeResults();
  info() << clock_.timesLine() << "\n\nEnd\n\n";
}

}  // namespace sphcast
