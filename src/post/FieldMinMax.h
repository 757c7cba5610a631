#pragma once

#include <string>
#include <vector>

#include "post/FunctionObject.h"

namespace sphcast {

// type fieldMinMax: the smallest and largest value of fields over the whole cloud, as
// OpenFOAM's fieldMinMax (vectors by magnitude), one file per field:
//   #         Time          min          max   xMin yMin zMin   xMax yMax zMax
//   0.08      2392.1       2408.3       ...
// where (xMin yMin zMin) is the position of the particle holding the minimum. Keys: fields
// (rho p U ...).
class FieldMinMax : public FunctionObject {
 public:
  FieldMinMax(const std::string& name, const Dictionary& dict,
              const FunctionObjectContext& context);

 private:
  void sample(double time) override;

  std::vector<std::string> fields_;
};

}  // namespace sphcast
