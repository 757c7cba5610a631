#pragma once

#include <map>
#include <string>
#include <vector>

#include "castAnalysis/CastAnalysis.h"

namespace sphcast {

// type timeSeries: per cloud and written time, postProcessing/<name>/<cloud>.csv with
//   time, particles, Tmin, Tmean, Tmax (K, mean by mass), solidFraction (by mass), liquid
//   (f_s = 0), frozen, flowing (not frozen), solid (f_s = 1), densityDeviationMin/Max
//   (rho / rho_s - 1), kineticEnergy (J), internalEnergy (sum m u, J), internalEnergyChange (since
//   the run's start, J), heatLost (J: what left the cloud through held surfaces, the air and
//   radiation since the start; a held mold's books hold the heat it took from the metal)
// ("nan" where the cloud lacks the field), and PNG plots of them (<quantity>_<cloud>.png); and
// the heat books of the case in energyBalance.csv (time, internalEnergyChange and heatLost summed
// over the heat clouds, imbalance = their sum, relativeImbalance = that over the clouds' start
// heat content), plotted in energyBalance.png. Under -time / -latestTime the rows of those times
// are replaced or added. Written times only: a quantity that needs every step (the energy balance's
// round-off, the largest speed) is the run's function objects' (energyBalance, fieldMinMax). Keys:
// clouds (optional; every cloud of the case by default).
class TimeSeries : public CastAnalysis {
 public:
  TimeSeries(const std::string& name, const Dictionary& dict, const AnalysisContext& context);

  void add(const WrittenTime& time) override;
  ReportSection finish() override;

  static std::string csvHeader();
  // One row of the table for a cloud at a time.
  static std::string csvRow(double time, const ParticleCloud& cloud);
  // The heat books of every cloud with u, mass and internalEnergyAtStart; empty when none has.
  static std::string energyBalanceRow(const WrittenTime& time);
  static std::string spillLine(double time, const ParticleCloud& cloud);

 private:
  std::vector<std::string> clouds_;
  std::map<std::string, std::string> csv_;  // cloud -> rows
  std::map<std::string, std::string> lastRow_;
  std::string energy_, lastEnergyRow_;
  // per cloud run by a flow (it carries the run's domain): the last time's spill line
  std::map<std::string, std::string> spill_;
};

}  // namespace sphcast
