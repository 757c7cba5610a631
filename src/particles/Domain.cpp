#include "particles/Domain.h"

namespace sphcast {

Domain defaultDomain(const std::vector<const ParticleCloud*>& clouds) {
  Domain box{Vector::Constant(std::numeric_limits<Real>::max()),
             Vector::Constant(std::numeric_limits<Real>::lowest())};
  for (const ParticleCloud* cloud : clouds) {
    for (const Vector& x : cloud->positions()) {
      box.lower = box.lower.cwiseMin(x);
      box.upper = box.upper.cwiseMax(x);
    }
  }
  const Vector margin = Real(0.5) * (box.upper - box.lower);
  box.lower -= margin;
  box.upper += margin;
  return box;
}

}  // namespace sphcast
