#include "sph/ExposedArea.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.h"
#include "particles/WendlandKernel.h"

namespace sphcast {

namespace {

template <int Dim>
Real calibratedFactorIn(ExposedAreaForm form, Real supportRadius, Real spacing) {
  const WendlandC2Kernel<Dim> kernel(supportRadius);
  const Real cell = std::pow(spacing, Dim);  // V = dx^d
  const int reach = static_cast<int>(std::ceil(supportRadius / spacing)) + 1;
  // |d s / dz| of layer k: sum over the half lattice of V dW/dr dz / r
  auto layerGradient = [&](int layer) {
    Real gz = 0;
    for (int dz = -reach; dz <= reach; ++dz) {
      if (layer + dz < 0) continue;
      const int dyRange = Dim == 3 ? reach : 0;
      for (int dy = -dyRange; dy <= dyRange; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          const Real r = spacing * std::sqrt(Real(dx * dx + dy * dy + dz * dz));
          gz += cell * kernel.derivativeOverDistance(r) * spacing * Real(dz);
        }
      }
    }
    return std::abs(gz);
  };
  // Layers k = 0, 1, ... below the free surface z = 0: s_k sums over the half lattice z <= 0.
  Real columnSum = 0;
  if (form == ExposedAreaForm::gradient) {
    for (int layer = 0; layer <= reach; ++layer) columnSum += layerGradient(layer) * spacing;
  } else {
    columnSum = flatSurfaceExposureSum<Dim>(kernel, supportRadius, spacing);
  }
  if (!(columnSum > 0)) {
    throw Error("exposed area: a flat surface has no exposed particle at supportRadius/spacing " +
                std::to_string(supportRadius / spacing) + " (the kernel is too narrow)");
  }
  // sum_k R_A g_k dx^(d-1) = dx^(d-1)
  return Real(1) / columnSum;
}

}  // namespace

Real ExposedArea::calibratedAreaFactor(ExposedAreaForm form, int dimension, Real supportRadius,
                                       Real spacing) {
  return dimension == 2 ? calibratedFactorIn<2>(form, supportRadius, spacing)
                        : calibratedFactorIn<3>(form, supportRadius, spacing);
}

ExposedArea::ExposedArea(ExposedAreaForm form, int dimension, Real supportRadius, Real spacing,
                         std::vector<ParticleCloud*> exposed,
                         std::vector<const ParticleCloud*> covering, Neighbourhood& neighbourhood)
    : form_(form),
      dimension_(dimension),
      supportRadius_(supportRadius),
      areaFactor_(calibratedAreaFactor(form, dimension, supportRadius, spacing)),
      exposed_(std::move(exposed)),
      covering_(std::move(covering)),
      neighbourhood_(neighbourhood) {
  for (ParticleCloud* cloud : exposed_) {
    cloud->addScalarField("exposedArea");
    cloud->addScalarField("granularity");
    for (const ParticleCloud* other : covering_) neighbourhood.requestPairs(*cloud, *other);
  }
}

void ExposedArea::compute() {
  if (dimension_ == 2) {
    computeIn<2>();
  } else {
    computeIn<3>();
  }
}

template <int Dim>
void ExposedArea::computeIn() {
  const WendlandC2Kernel<Dim> kernel(supportRadius_);
  const PeriodicBox periodic = neighbourhood_.periodicBox();
  const Real selfKernel = kernel.value(0);
  const Real areaFactor = areaFactor_;
  constexpr Real areaExponent = Real(Dim - 1) / Real(Dim);
  const bool gradientForm = form_ == ExposedAreaForm::gradient;
  coveringVolume_.resize(covering_.size());
  for (std::size_t c = 0; c < covering_.size(); ++c) {
    coveringVolume_[c] = particleVolumes(*covering_[c], dimension_);
  }
  auto passWith = [&](auto separation) {
    for (ParticleCloud* cloud : exposed_) {
      // an exposed cloud covers too (the solver's and the tests' do): its volumes are there
      const auto self = std::find(covering_.begin(), covering_.end(), cloud);
      const std::vector<Real> ownVolume =
          self == covering_.end() ? particleVolumes(*cloud, dimension_) : std::vector<Real>();
      const std::vector<Real>& volume =
          self == covering_.end()
              ? ownVolume
              : coveringVolume_[static_cast<std::size_t>(self - covering_.begin())];
      const auto& x = cloud->positions();
      auto& granularity = cloud->scalarField("granularity");
      auto& area = cloud->scalarField("exposedArea");
      std::vector<const NeighbourList*> lists;
      for (const ParticleCloud* other : covering_) {
        lists.push_back(&neighbourhood_.pairs(*cloud, *other));
      }
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < x.size(); ++i) {
        Real s = volume[i] * selfKernel;
        Vector gradient = Vector::Zero();
        for (std::size_t c = 0; c < covering_.size(); ++c) {
          const Vector* otherX = covering_[c]->positions().data();
          const Real* otherVolume = coveringVolume_[c].data();
          for (const std::uint32_t j : lists[c]->of(i)) {
            const Vector xij = separation(x[i], otherX[j]);
            const Real r = xij.norm();
            s += otherVolume[j] * kernel.value(r);
            gradient += (otherVolume[j] * kernel.derivativeOverDistance(r)) * xij;
          }
        }
        granularity[i] = s;
        if (gradientForm) {
          area[i] = areaFactor * volume[i] * gradient.norm();
        } else {
          const Real q = Real(1) - volume[i] * selfKernel;
          area[i] = areaFactor * exposureWeight(Real(1) - s, q) * std::pow(volume[i], areaExponent);
        }
      }
    }
  };
  withSeparation(periodic, passWith);
}

}  // namespace sphcast
