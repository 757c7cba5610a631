#include "sph/ExposedArea.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"

namespace sphcast {

namespace {

// Calls visit(dz, r) for every site of a cubic lattice of spacing dx within `reach` sites of the
// origin (x and y; z too in 3D, the z axis normal to a flat surface in both dimensions) whose
// z offset is at least lowestDz: -reach for the full lattice, -k for layer k under a free
// surface (the sites above it are empty).
template <int Dim, class Visit>
void visitLattice(Real spacing, int reach, int lowestDz, Visit&& visit) {
  const int dyRange = Dim == 3 ? reach : 0;
  for (int dz = std::max(-reach, lowestDz); dz <= reach; ++dz) {
    for (int dy = -dyRange; dy <= dyRange; ++dy) {
      for (int dx = -reach; dx <= reach; ++dx) {
        visit(dz, spacing * std::sqrt(Real(dx * dx + dy * dy + dz * dz)));
      }
    }
  }
}

// One neighbour's share of the fullness before normalising: -V r dW/dr / d.
template <int Dim>
Real momentOf(const WendlandC2Kernel<Dim>& kernel, Real cell, Real r) {
  return -cell * kernel.derivativeOverDistance(r) * r * r / Real(Dim);
}

template <int Dim>
Real calibratedFactorIn(ExposedAreaForm form, Real supportRadius, Real spacing) {
  const WendlandC2Kernel<Dim> kernel(supportRadius);
  const Real cell = std::pow(spacing, Dim);  // V = dx^d
  const int reach = static_cast<int>(std::ceil(supportRadius / spacing)) + 1;
  // |d s / dz| of layer k: sum over the half lattice of V dW/dr dz / r
  auto layerGradient = [&](int layer) {
    Real gz = 0;
    visitLattice<Dim>(spacing, reach, -layer, [&](int dz, Real r) {
      gz += cell * kernel.derivativeOverDistance(r) * spacing * Real(dz);
    });
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

// c_full = -(1/d) sum_j V_j r dW/dr over a full cubic lattice (about 1).
template <int Dim>
Real fullLatticeMomentIn(Real supportRadius, Real spacing) {
  const WendlandC2Kernel<Dim> kernel(supportRadius);
  const Real cell = std::pow(spacing, Dim);
  const int reach = static_cast<int>(std::ceil(supportRadius / spacing)) + 1;
  Real sum = 0;
  visitLattice<Dim>(spacing, reach, -reach, [&](int, Real r) { sum += momentOf(kernel, cell, r); });
  return sum;
}

// The fullness c_i = -(1/d) sum_j V_j r_ij dW/dr(r_ij) / c_full (the trace of the first-moment
// matrix sum_j V_j x_ji grad_i W_ij over d, 1 in a full support) and its Shepard mean
// cbar_i = sum_j V_j W_ij c_j / sum_j V_j W_ij, over the layers k = 0, 1, ... of a semi-infinite
// cubic lattice under a flat free surface: cbar of the deepest layer whose gradient (the area)
// is not zero.
template <int Dim>
Real deepestLayerFullnessIn(Real supportRadius, Real spacing) {
  const WendlandC2Kernel<Dim> kernel(supportRadius);
  const Real cell = std::pow(spacing, Dim);
  const int reach = static_cast<int>(std::ceil(supportRadius / spacing)) + 1;
  const Real full = fullLatticeMomentIn<Dim>(supportRadius, spacing);
  const int layers = 3 * reach;
  std::vector<Real> fullness(layers), gradient(layers);
  for (int layer = 0; layer < layers; ++layer) {
    Real c = 0, gz = 0;
    visitLattice<Dim>(spacing, reach, -layer, [&](int dz, Real r) {
      c += momentOf(kernel, cell, r);
      gz += cell * kernel.derivativeOverDistance(r) * spacing * Real(dz);
    });
    fullness[layer] = c / full;
    gradient[layer] = std::abs(gz);
  }
  Real deepest = 0;
  for (int layer = 0; layer + reach < layers; ++layer) {
    if (!(gradient[layer] > Real(1e-12) * gradient[0])) break;
    Real weighted = 0, sum = 0;
    visitLattice<Dim>(spacing, reach, -layer, [&](int dz, Real r) {
      const Real w = cell * kernel.value(r);
      weighted += w * fullness[static_cast<std::size_t>(layer + dz)];
      sum += w;
    });
    deepest = weighted / sum;
  }
  return deepest;
}

}  // namespace

Real ExposedArea::deepestAreaLayerFullness(int dimension, Real supportRadius, Real spacing) {
  return dimension == 2 ? deepestLayerFullnessIn<2>(supportRadius, spacing)
                        : deepestLayerFullnessIn<3>(supportRadius, spacing);
}

Real ExposedArea::calibratedAreaFactor(ExposedAreaForm form, int dimension, Real supportRadius,
                                       Real spacing) {
  return dimension == 2 ? calibratedFactorIn<2>(form, supportRadius, spacing)
                        : calibratedFactorIn<3>(form, supportRadius, spacing);
}

ExposedArea::ExposedArea(ExposedAreaForm form, int dimension, Real supportRadius, Real spacing,
                         std::vector<ParticleCloud*> exposed,
                         std::vector<const ParticleCloud*> covering, Neighbourhood& neighbourhood,
                         std::vector<const ParticleCloud*> lattices)
    : form_(form),
      dimension_(dimension),
      supportRadius_(supportRadius),
      areaFactor_(calibratedAreaFactor(form, dimension, supportRadius, spacing)),
      exposed_(std::move(exposed)),
      covering_(std::move(covering)),
      lattices_(std::move(lattices)),
      spacing_(spacing),
      neighbourhood_(neighbourhood) {
  if (form_ == ExposedAreaForm::gradient) {
    // the gate's ramp, from the flat lattice's deepest layer with area: 0.920 .. 0.970 at
    // h = 3 dx in 3D (the thresholds measured best there, below)
    const Real deepest = deepestAreaLayerFullness(dimension, supportRadius, spacing);
    gateFrom_ = deepest + Real(0.26) * (Real(1) - deepest);
    gateTo_ = deepest + Real(0.72) * (Real(1) - deepest);
    fullLatticeMoment_ = dimension == 2 ? fullLatticeMomentIn<2>(supportRadius, spacing)
                                        : fullLatticeMomentIn<3>(supportRadius, spacing);
  }
  for (ParticleCloud* cloud : exposed_) {
    cloud->addScalarField(field::exposedArea);
    cloud->addScalarField(field::granularity);
    for (const ParticleCloud* other : covering_) neighbourhood.requestPairs(*cloud, *other);
  }
}

// The pairs of each graded exposed cloud's coarser particles within it, this rank's own rows
// (their halo reaches the coarsest support, DomainDecomposition::Cloud::haloRadius): found at the
// first pass, and again where a decomposed run moved the cloud's particles.
void ExposedArea::findCoarsePairs() {
  coarsePairs_.resize(exposed_.size());
  coarseLayouts_.resize(exposed_.size(), 0);
  for (std::size_t e = 0; e < exposed_.size(); ++e) {
    const ParticleCloud& cloud = *exposed_[e];
    if (!cloud.hasScalarField(field::localSpacing)) continue;
    if (std::find(covering_.begin(), covering_.end(), &cloud) == covering_.end()) continue;
    if (coarsePairs_[e] && coarseLayouts_[e] == cloud.layoutVersion()) continue;
    const auto& localSpacing = cloud.scalarField(field::localSpacing);
    std::vector<std::uint8_t> coarse(cloud.size(), 0);
    for (std::size_t i = 0; i < cloud.ownedSize(); ++i) {
      coarse[i] = localSpacing[i] > Real(1.001) * spacing_ ? 1 : 0;
    }
    const auto& placed = cloud.hasVectorField(field::restPosition)
                             ? cloud.vectorField(field::restPosition)
                             : cloud.positions();
    coarsePairs_[e] = std::make_unique<GradedPairs>(
        findGradedPairs(placed, localSpacing, supportRadius_ / spacing_,
                        neighbourhood_.periodicBox(), &coarse, PairSupport::row));
    coarseLayouts_[e] = cloud.layoutVersion();
  }
}

// Per covering cloud, which particles changed position or volume since the last pass, bit for
// bit (held frozen metal and a mold at rest keep theirs exactly), and the present ones kept.
void ExposedArea::markChanged() {
  coveringState_.resize(covering_.size());
  for (std::size_t c = 0; c < covering_.size(); ++c) {
    const std::vector<Vector>& x = covering_[c]->positions();
    const std::vector<Real>& volume = coveringVolume_[c];
    CoveringState& state = coveringState_[c];
    const std::size_t count = x.size();
    if (state.positions.size() != count || state.volumes.size() != count) {
      state.positions = x;
      state.volumes = volume;
      state.changed.assign(count, 1);
      state.anyChanged = true;
      continue;
    }
    state.changed.resize(count);
    Vector* lastX = state.positions.data();
    Real* lastVolume = state.volumes.data();
    std::uint8_t* changed = state.changed.data();
    int any = 0;
#pragma omp parallel for schedule(static) reduction(| : any)
    for (std::size_t i = 0; i < count; ++i) {
      const bool moved = x[i] != lastX[i] || !(volume[i] == lastVolume[i]);
      changed[i] = moved ? 1 : 0;
      if (moved) {
        lastX[i] = x[i];
        lastVolume[i] = volume[i];
        any = 1;
      }
    }
    state.anyChanged = any != 0;
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
  // Per exposed cloud: its volumes (an exposed cloud covers too, the solver's and the tests' do:
  // its volumes are there) and its pair lists with every covering cloud.
  struct Exposed {
    std::vector<Real> ownVolume;  // only if it does not cover
    const std::vector<Real>* volume;
    std::vector<const NeighbourList*> lists;
  };
  std::vector<Exposed> exposed(exposed_.size());
  findCoarsePairs();
  for (std::size_t e = 0; e < exposed_.size(); ++e) {
    const auto self = std::find(covering_.begin(), covering_.end(), exposed_[e]);
    if (self == covering_.end()) {
      exposed[e].ownVolume = particleVolumes(*exposed_[e], dimension_);
      exposed[e].volume = &exposed[e].ownVolume;
    } else {
      exposed[e].volume = &coveringVolume_[static_cast<std::size_t>(self - covering_.begin())];
    }
    for (const ParticleCloud* other : covering_) {
      exposed[e].lists.push_back(&neighbourhood_.pairs(*exposed_[e], *other));
    }
  }
  // The gradient form's gate (see the header): first each particle's |grad s|, s and fullness
  // c, then the Shepard mean of c and the area. A particle of a covering cloud whose area is
  // not wanted counts as full (c = 1).
  fullness_.resize(exposed_.size());
  std::vector<const Real*> coveringFullness(covering_.size(), nullptr);
  for (std::size_t c = 0; c < covering_.size(); ++c) {
    const auto other = std::find(exposed_.begin(), exposed_.end(), covering_[c]);
    if (gradientForm && other != exposed_.end()) {
      auto& values = fullness_[static_cast<std::size_t>(other - exposed_.begin())];
      values.resize(covering_[c]->size());
      coveringFullness[c] = values.data();
    }
  }
  const Real momentScale = Real(-1) / (Real(Dim) * fullLatticeMoment_);
  gradientArea_.resize(exposed_.size());
  std::vector<std::vector<Real>>& gradientArea = gradientArea_;
  // Which exposed clouds may keep rows: walls (their area is their row's own sums), covering
  // (their changes are tracked), with few enough covering clouds for a row's bit mask.
  latticeRows_.resize(exposed_.size());
  std::vector<int> selfCovering(exposed_.size(), -1);
  bool anyKept = false;
  for (std::size_t e = 0; e < exposed_.size(); ++e) {
    const auto self = std::find(covering_.begin(), covering_.end(), exposed_[e]);
    const bool lattice =
        std::find(lattices_.begin(), lattices_.end(), exposed_[e]) != lattices_.end();
    if (lattice && self != covering_.end() && covering_.size() <= 32) {
      selfCovering[e] = static_cast<int>(self - covering_.begin());
      anyKept = true;
    } else {
      latticeRows_[e].valid = false;
    }
  }
  if (anyKept) markChanged();
  auto passWith = [&](auto separation) {
    for (std::size_t e = 0; e < exposed_.size(); ++e) {
      ParticleCloud* cloud = exposed_[e];
      const std::vector<Real>& volume = *exposed[e].volume;
      const auto& lists = exposed[e].lists;
      const auto& x = cloud->positions();
      auto& granularity = cloud->scalarField(field::granularity);
      auto& area = cloud->scalarField(field::exposedArea);
      if (gradientForm) {
        gradientArea[e].resize(x.size());
        fullness_[e].resize(x.size());
      }
      const GradedPairs* coarse = coarsePairs_[e].get();
      const Real* localSpacing = coarse ? cloud->scalarField(field::localSpacing).data() : nullptr;
      const Real* depth = coarse && cloud->hasScalarField(field::wallDistance)
                              ? cloud->scalarField(field::wallDistance).data()
                              : nullptr;
      // A kept lattice's rows: a row stays when neither it nor any particle it sums changed,
      // and no list it reads was rebuilt or filtered with it in it, then or now (its pairs
      // then are its pairs now, in the same order: the same bits as a new sum).
      LatticeRows& rows = latticeRows_[e];
      const bool keeping = selfCovering[e] >= 0;
      const bool cached = keeping && rows.valid && rows.size == x.size();
      std::vector<std::uint8_t> listChanged(covering_.size(), 1);
      for (std::size_t c = 0; c < covering_.size() && cached; ++c) {
        listChanged[c] = lists[c]->changes() != rows.listChanges[c] ? 1 : 0;
      }
      if (keeping) rows.neighbourIn.resize(x.size(), 0);
      const CoveringState* selfState =
          keeping ? &coveringState_[static_cast<std::size_t>(selfCovering[e])] : nullptr;
      auto rowStays = [&](std::size_t i, bool coarseRow) {
        if (!cached || selfState->changed[i] || (coarseRow && selfState->anyChanged)) return false;
        for (std::size_t c = 0; c < covering_.size(); ++c) {
          const auto row = lists[c]->of(i);
          if (listChanged[c]) {
            if (!row.empty() || (rows.neighbourIn[i] >> c & 1u)) return false;
            continue;
          }
          if (!coveringState_[c].anyChanged) continue;
          const std::uint8_t* changed = coveringState_[c].changed.data();
          for (const std::uint32_t j : row) {
            if (changed[j]) return false;
          }
        }
        return true;
      };
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < x.size(); ++i) {
        if (keeping) {
          const bool stays = rowStays(i, coarse && coarse->rowStart[i + 1] > coarse->rowStart[i]);
          std::uint32_t neighbourIn = 0;
          for (std::size_t c = 0; c < covering_.size(); ++c) {
            if (!lists[c]->of(i).empty()) neighbourIn |= 1u << c;
          }
          rows.neighbourIn[i] = neighbourIn;
          if (stays) continue;
        }
        Real s = volume[i] * selfKernel;
        Real moment = 0;
        Vector gradient = Vector::Zero();
        // a neighbour of volume Vj at xij (x_i - x_j) under `with`'s kernel
        const auto add = [&](const auto& with, Real Vj, const Vector& xij) {
          const Real r = xij.norm();
          const Real derivativeOverDistance = with.derivativeOverDistance(r);
          s += Vj * with.value(r);
          gradient += (Vj * derivativeOverDistance) * xij;
          moment += Vj * derivativeOverDistance * r * r;
        };
        const bool coarseRow = coarse && coarse->rowStart[i + 1] > coarse->rowStart[i];
        Real ownKernelAtZero = selfKernel;
        if (coarseRow) {  // within its own cloud, with its own kernel h_i
          const WendlandC2Kernel<Dim> own(supportRadius_ / spacing_ * localSpacing[i]);
          ownKernelAtZero = own.value(0);
          s = volume[i] * ownKernelAtZero;
          for (std::size_t slot = coarse->rowStart[i]; slot < coarse->rowStart[i + 1]; ++slot) {
            const std::uint32_t j = coarse->neighbours[slot];
            add(own, volume[j], separation(x[i], x[j]));
          }
        }
        for (std::size_t c = 0; c < covering_.size(); ++c) {
          if (coarseRow && covering_[c] == cloud) continue;
          const Vector* otherX = covering_[c]->positions().data();
          const Real* otherVolume = coveringVolume_[c].data();
          for (const std::uint32_t j : lists[c]->of(i)) {
            add(kernel, otherVolume[j], separation(x[i], otherX[j]));
          }
        }
        granularity[i] = s;
        if (gradientForm) {
          gradientArea[e][i] = areaFactor * volume[i] * gradient.norm();
          // deeper than its support in the mold: no surface (where spacings change, the kernel
          // sums of unlike particles leave a gradient inside, 0.73 of a face's area in a block)
          if (coarse && depth && depth[i] >= supportRadius_ / spacing_ * localSpacing[i]) {
            gradientArea[e][i] = 0;
          }
          fullness_[e][i] = momentScale * moment;
        } else {
          const Real q = Real(1) - volume[i] * ownKernelAtZero;
          area[i] = areaFactor * exposureWeight(Real(1) - s, q) * std::pow(volume[i], areaExponent);
        }
      }
      if (keeping) {
        rows.valid = true;
        rows.size = x.size();
        rows.listChanges.resize(covering_.size());
        for (std::size_t c = 0; c < covering_.size(); ++c) {
          rows.listChanges[c] = lists[c]->changes();
        }
      }
    }
    if (!gradientForm) return;
    // a decomposed run's halo: its owners' fullness, which the mean below reads at neighbours
    for (std::size_t e = 0; e < exposed_.size(); ++e) {
      neighbourhood_.syncHalo(*exposed_[e], fullness_[e]);
    }
    for (std::size_t e = 0; e < exposed_.size(); ++e) {
      ParticleCloud* cloud = exposed_[e];
      if (std::find(lattices_.begin(), lattices_.end(), cloud) != lattices_.end()) {
        auto& area = cloud->scalarField(field::exposedArea);
        std::copy(gradientArea[e].begin(), gradientArea[e].end(), area.begin());
        continue;
      }
      const std::vector<Real>& volume = *exposed[e].volume;
      const auto& lists = exposed[e].lists;
      const auto& x = cloud->positions();
      const auto& granularity = cloud->scalarField(field::granularity);
      auto& area = cloud->scalarField(field::exposedArea);
      const GradedPairs* coarse = coarsePairs_[e].get();
      const Real* localSpacing = coarse ? cloud->scalarField(field::localSpacing).data() : nullptr;
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < x.size(); ++i) {
        Real weighted = volume[i] * selfKernel * fullness_[e][i];
        const bool coarseRow = coarse && coarse->rowStart[i + 1] > coarse->rowStart[i];
        if (coarseRow) {  // within its own cloud, with its own kernel (as in the first pass)
          const WendlandC2Kernel<Dim> own(supportRadius_ / spacing_ * localSpacing[i]);
          weighted = volume[i] * own.value(0) * fullness_[e][i];
          for (std::size_t slot = coarse->rowStart[i]; slot < coarse->rowStart[i + 1]; ++slot) {
            const std::uint32_t j = coarse->neighbours[slot];
            weighted += volume[j] * own.value(separation(x[i], x[j]).norm()) * fullness_[e][j];
          }
        }
        for (std::size_t c = 0; c < covering_.size(); ++c) {
          if (coarseRow && covering_[c] == cloud) continue;
          const Vector* otherX = covering_[c]->positions().data();
          const Real* otherVolume = coveringVolume_[c].data();
          const Real* otherFullness = coveringFullness[c];
          for (const std::uint32_t j : lists[c]->of(i)) {
            const Real w = otherVolume[j] * kernel.value(separation(x[i], otherX[j]).norm());
            weighted += otherFullness ? w * otherFullness[j] : w;
          }
        }
        area[i] = gradientArea[e][i] * interiorGate(weighted / granularity[i], gateFrom_, gateTo_);
      }
    }
  };
  withSeparation(periodic, passWith);
}

}  // namespace sphcast
