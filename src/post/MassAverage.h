#pragma once

#include <string>
#include <vector>

#include "post/FunctionObject.h"

namespace sphcast {

// type massAverage: the mass-weighted mean of scalar fields over the whole cloud,
//   <f> = sum_i m_i f_i / sum_i m_i,
// one file per field (OpenFOAM's volFieldValue with a weighted average, by mass):
//   #         Time         mean
// The solid fraction by mass, sampled every step, is the casting's solidification curve, which
// the written times give only a few points of. Keys: fields (solidFraction T ...); the cloud
// needs `mass`.
class MassAverage : public FunctionObject {
 public:
  MassAverage(const std::string& name, const Dictionary& dict,
              const FunctionObjectContext& context);

 private:
  void sample(double time) override;

  std::vector<std::string> fields_;
};

}  // namespace sphcast
