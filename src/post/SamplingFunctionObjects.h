#pragma once

#include <string>
#include <vector>

#include "post/FunctionObject.h"

namespace sphcast {

// type probes: fields of the cloud at fixed points by Shepard interpolation (FluidSampling.h),
// one file per field, as OpenFOAM's probes:
//   # Probe 0 (2.3955 0.5 0.021)
//   #        Probe      0
//   #         Time
//   0.001    1234.5
// Keys: fields (p U ...), probeLocations ((x y z) ...), supportRadius (optional, m: the flow's
// h by default). "nan" where no fluid particle is within the support radius.
class Probes : public FunctionObject {
 public:
  Probes(const std::string& name, const Dictionary& dict, const FunctionObjectContext& context);

 private:
  void sample(double time) override;

  std::vector<std::string> fields_;
  std::vector<Vector> locations_;
  Real supportRadius_ = 0;
  std::string header_;
};

// type surfaceHeights: the free-surface level (FluidSampling.h: surfaceHeight) above given
// points, measured along -g, in one file `height`, one column per location.
// Keys: locations ((x y z) ...), radius (optional, m: of the column, the flow's h by default).
class SurfaceHeights : public FunctionObject {
 public:
  SurfaceHeights(const std::string& name, const Dictionary& dict,
                 const FunctionObjectContext& context);

 private:
  void sample(double time) override;

  std::vector<Vector> locations_;
  Vector up_;
  Real radius_ = 0;
  std::string header_;
};

// type front: the leading edge of the fluid along a direction (FluidSampling.h: fluidFront),
// in one file `front`. Keys: direction (x y z) (normalised).
class FluidFront : public FunctionObject {
 public:
  FluidFront(const std::string& name, const Dictionary& dict, const FunctionObjectContext& context);

 private:
  void sample(double time) override;

  Vector direction_;
  std::string header_;
};

}  // namespace sphcast
