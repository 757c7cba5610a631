#include "sph/FillTime.h"

#include <algorithm>

namespace sphcast {

FillTime::FillTime(ParticleCloud& fluid, std::vector<const ParticleCloud*> walls)
    : fluid_(fluid), walls_(std::move(walls)) {
  const auto spacing = fluid_.attributes().find("spacing");
  contact_ = Real(1.75) * (spacing != fluid_.attributes().end() ? Real(spacing->second) : Real(0));
  if (!fluid_.hasScalarField(field)) {
    auto& times = fluid_.addScalarField(field);
    std::fill(times.begin(), times.end(), Real(-1));
  }
}

void FillTime::record(const Neighbourhood& neighbourhood, double time) {
  auto& fill = fluid_.scalarField(field);
  const auto& x = fluid_.positions();
  const PeriodicBox& periodic = neighbourhood.periodicBox();
  const Real contactSquared = contact_ * contact_;
  for (const ParticleCloud* wall : walls_) {
    const NeighbourList& pairs = neighbourhood.pairs(fluid_, *wall);
    const auto& y = wall->positions();
    const auto count = static_cast<std::ptrdiff_t>(fluid_.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
      const auto i = static_cast<std::size_t>(n);
      if (fill[i] >= 0) continue;
      for (const std::uint32_t j : pairs.of(i)) {
        if (periodic.separation(x[i], y[j]).squaredNorm() < contactSquared) {
          fill[i] = static_cast<Real>(time);
          break;
        }
      }
    }
  }
}

}  // namespace sphcast
