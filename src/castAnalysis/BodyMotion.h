#pragma once

#include <optional>
#include <string>
#include <vector>

#include "castAnalysis/CastAnalysis.h"

namespace sphcast {

// A rigid body's motion and loads over the run (a press's punch: how far it travelled, when it
// reached its stop, what the metal pushed back with), from the solver's
// postProcessing/dynamicBodies/<startTime>/<body>.dat (every step; restarts joined):
//
//   press { type bodyMotion; body upperMold; }
//
// Writes postProcessing/<name>/<body>.csv (time, travel x y z, velocity x y z, the metal's force
// x y z, the total force x y z, at the end stop, then along the travel: travel, velocity, the
// metal's force, the press's load) and two plots: the travel and the velocity along the body's
// main direction of travel, and the metal's force along it (with the press's load where it has
// one). The report gives the final travel, when the body first reached its end stop, the largest
// force, and the press's largest and final load.
//
// With `gap`, a press's casting under a flat punch, at the last time selected:
//
//   gap { cloud metal; faceStart (0 0 0.02025); floorPoint (0 0 0); area 0.01946;
//         volumeBelow 6.885e-5; }
//
// the gap between the punch's face (faceStart moved by the travel) and the floor's plane, both
// normal to the travel, against the volume balance: the metal's volume (sum of m / rho) above
// the floor over the area under the punch, and what the gap would be with the space below the
// floor (a ditch, volumeBelow) full and the rest spread under the punch. Where the two differ,
// the metal does not fill the gap (voids, or a layer at each surface thicker than the lattice's).
class BodyMotion : public CastAnalysis {
 public:
  BodyMotion(const std::string& name, const Dictionary& dict, const AnalysisContext& context);
  void add(const WrittenTime& time) override;
  ReportSection finish() override;

 private:
  // rows: the body's history; the travel is the one of the last row at or before the time
  std::string gapReport(const std::vector<std::vector<double>>& rows,
                        const Vector& direction) const;

  std::string body_;
  SourceLocation bodyAt_;
  struct Gap {
    std::string cloud;
    Vector faceStart, floorPoint;
    double area = 0, volumeBelow = 0;
  };
  std::optional<Gap> gap_;
  // the gap's cloud at the last time seen: positions and volumes m / rho
  std::vector<Vector> positions_;
  std::vector<double> volumes_;
  std::string lastTime_;
  double lastTimeValue_ = 0;
};

}  // namespace sphcast
