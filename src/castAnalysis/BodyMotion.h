#pragma once

#include <string>

#include "castAnalysis/CastAnalysis.h"

namespace sphcast {

// A rigid body's motion and loads over the run (a press's punch: how far it travelled, when it
// reached its stop, what the metal pushed back with), from the solver's
// postProcessing/dynamicBodies/<startTime>/<body>.dat (every step; restarts joined):
//
//   press { type bodyMotion; body upperMold; }
//
// Writes postProcessing/<name>/<body>.csv (time, travel x y z, velocity x y z, the metal's force
// x y z, the total force x y z, at the end stop) and two plots: the travel and the velocity
// along the body's main direction of travel, and the metal's force along it. The report gives
// the final travel, when the body first reached its end stop, and the largest force.
class BodyMotion : public CastAnalysis {
 public:
  BodyMotion(const std::string& name, const Dictionary& dict, const AnalysisContext& context);
  void add(const WrittenTime&) override {}
  ReportSection finish() override;

 private:
  std::string body_;
  SourceLocation bodyAt_;
};

}  // namespace sphcast
