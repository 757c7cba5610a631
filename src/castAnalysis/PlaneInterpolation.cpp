#include "castAnalysis/PlaneInterpolation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"
#include "sph/ParticleVolumes.h"

namespace sphcast {

PlaneInterpolation::PlaneInterpolation(const PlaneGrid& grid, int dimension)
    : grid_(grid),
      dimension_(dimension),
      owner_(std::size_t(grid.width) * std::size_t(grid.height), -1),
      value_(owner_.size(), std::numeric_limits<double>::quiet_NaN()),
      fill_(owner_.size(), 0.0),
      total_(owner_.size(), 0.0) {}

void PlaneInterpolation::add(const ParticleCloud& cloud, int index, const std::string& field,
                             Real supportRadius) {
  const std::vector<Real> volume = particleVolumes(cloud, dimension_);
  const std::vector<Real>* values =
      cloud.hasScalarField(field) ? &cloud.scalarField(field) : nullptr;
  const std::vector<Real>* localSpacing = cloud.hasScalarField(field::localSpacing)
                                              ? &cloud.scalarField(field::localSpacing)
                                              : nullptr;
  const auto spacing = cloud.attributes().find("spacing");
  const Real cloudSpacing = spacing != cloud.attributes().end() ? Real(spacing->second) : 0;
  std::vector<double> sum(owner_.size(), 0.0), weighted(values ? owner_.size() : 0, 0.0);
  for (std::size_t j = 0; j < cloud.size(); ++j) {
    const Real h = localSpacing != nullptr && cloudSpacing > 0
                       ? supportRadius * (*localSpacing)[j] / cloudSpacing
                       : supportRadius;
    const Vector d = cloud.positions()[j] - grid_.origin;
    const Real depth = dimension_ == 2 ? Real(0) : d.dot(grid_.normal);
    if (std::abs(depth) >= h) continue;
    const Real u = d.dot(grid_.right) / grid_.pixel, v = d.dot(grid_.up) / grid_.pixel;
    const Real reach = std::sqrt(h * h - depth * depth) / grid_.pixel;
    const int x0 = std::max(0, int(std::ceil(u - reach))),
              x1 = std::min(grid_.width - 1, int(std::floor(u + reach)));
    const int y0 = std::max(0, int(std::ceil(v - reach))),
              y1 = std::min(grid_.height - 1, int(std::floor(v + reach)));
    const WendlandC2Kernel<3> kernel3(h);
    const WendlandC2Kernel<2> kernel2(h);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const Real du = (Real(x) - u) * grid_.pixel, dv = (Real(y) - v) * grid_.pixel;
        const Real r = std::sqrt(du * du + dv * dv + depth * depth);
        const double w =
            double(volume[j] * (dimension_ == 2 ? kernel2.value(r) : kernel3.value(r)));
        sum[at(x, y)] += w;
        if (values != nullptr) weighted[at(x, y)] += w * double((*values)[j]);
      }
    }
  }
  for (std::size_t p = 0; p < sum.size(); ++p) {
    total_[p] += sum[p];
    if (sum[p] <= fill_[p]) continue;
    owner_[p] = index;
    fill_[p] = sum[p];
    value_[p] = values != nullptr ? weighted[p] / sum[p] : std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace sphcast
