#pragma once

#include <string>
#include <vector>

#include "castAnalysis/CastAnalysis.h"

namespace sphcast {

// type thermocouples: cooling curves at named points of the casting, as a foundry records them.
//
//   TC
//   {
//       type       thermocouples;
//       cloud      metal;                  // a heatTransfer cloud with liquidus and solidus
//       locations  { centre (0 0 0.03); wall (0.04 0 0.03); }
//       supportRadius 0.0045;              // optional: h of system/sphSchemes by default
//   }
//
// reads T at the locations from the written times (Shepard interpolation with the kernel,
// post/FluidSampling.h). Written times are usually too far apart to show the curve's breaks;
// for that the run samples every step with a `probes` function object of controlDict
// (fields (T)), and the entry reads its rows instead of locations:
//
//       probes     TCprobes;               // the function object's name; probes k named probe<k>
//
// Writes postProcessing/<name>/temperature.csv (time, one column per thermocouple),
// coolingCurves.png with the liquidus and solidus drawn, and breaks.csv: per thermocouple the
// times it reached the liquidus and the solidus, the local freezing time between them, and the
// slope breaks of its curve (CoolingCurve.h) with their temperatures.
// A location with no particle of the cloud within h at the first time is an error at its key.
class Thermocouples : public CastAnalysis {
 public:
  Thermocouples(const std::string& name, const Dictionary& dict, const AnalysisContext& context);

  void add(const WrittenTime& time) override;
  ReportSection finish() override;

 private:
  std::string cloud_;
  std::string probes_;  // function object to read, or empty
  std::vector<std::string> names_;
  std::vector<Vector> locations_;
  Real supportRadius_ = 0;
  double liquidus_ = 0, solidus_ = 0;
  std::vector<double> times_;
  std::vector<std::vector<double>> temperatures_;  // per thermocouple
  bool checked_ = false;
};

}  // namespace sphcast
