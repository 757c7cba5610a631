#include "particles/Domain.h"

namespace sphcast {

Domain boundingBox(const std::vector<const ParticleCloud*>& clouds) {
  Domain box{Vector::Constant(std::numeric_limits<Real>::max()),
             Vector::Constant(std::numeric_limits<Real>::lowest())};
  for (const ParticleCloud* cloud : clouds) {
    const auto& x = cloud->positions();
    for (std::size_t i = 0; i < cloud->ownedSize(); ++i) {
      box.lower = box.lower.cwiseMin(x[i]);
      box.upper = box.upper.cwiseMax(x[i]);
    }
  }
  return box;
}

Domain withMargin(Domain box) {
  const Vector margin = Real(0.5) * (box.upper - box.lower);
  box.lower -= margin;
  box.upper += margin;
  return box;
}

Domain defaultDomain(const std::vector<const ParticleCloud*>& clouds) {
  return withMargin(boundingBox(clouds));
}

}  // namespace sphcast
