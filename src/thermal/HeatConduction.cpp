#include "thermal/HeatConduction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "boundaries/ThermalWall.h"
#include "core/Error.h"
#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"

namespace sphcast {

double HeatConduction::largestDiffusivity(const Material& material) {
  const TemperatureTable& kappa = material.requireConductivity("heatTransfer conduction");
  const TemperatureTable& rho = material.requireDensity("heatTransfer conduction");
  const InternalEnergyTable& energy = material.requireInternalEnergy("heatTransfer conduction");
  // Every table is piecewise linear (u) or clamped (kappa, rho), so the extremes of
  // kappa / (rho du/dT) lie within the union of their ranges: sample it finely, plus both sides
  // of every row (du/dT jumps there).
  double lowest = std::min(
      {kappa.lowestTemperature(), rho.lowestTemperature(), energy.nodeTemperatures().front()});
  double highest = std::max(
      {kappa.highestTemperature(), rho.highestTemperature(), energy.nodeTemperatures().back()});
  if (!(highest > lowest)) highest = lowest + 1;
  double largest = 0;
  constexpr int samples = 4000;
  for (int s = -1; s <= samples + 1; ++s) {
    const double T = lowest + (highest - lowest) * s / samples;
    const double alpha = kappa(T) / (rho(T) * energy.specificHeat(static_cast<Real>(T)));
    largest = std::max(largest, alpha);
  }
  return largest;
}

HeatConduction::HeatConduction(const HeatTransferContext& context,
                               std::set<std::pair<std::string, std::string>> contactPairs)
    : context_(context), contactPairs_(std::move(contactPairs)) {
  double alpha = 0;
  const std::size_t count = context_.clouds.size();
  for (std::size_t a = 0; a < count; ++a) {
    alpha = std::max(alpha, largestDiffusivity(*context_.clouds[a].material));
    for (std::size_t b = 0; b < count; ++b) {
      if (conducts(a, b) && !(a == b && graded(a))) {
        context_.neighbourhood->requestPairs(*context_.clouds[a].cloud, *context_.clouds[b].cloud);
      }
    }
  }
  const double dx = context_.spacing;
  stableDeltaT_ = context_.maxDi * dx * dx / alpha;
}

// Pairs (a, b) that exchange heat by conduction: not a contact pair, and not two clouds both
// held at a fixed temperature (nothing to compute).
bool HeatConduction::conducts(std::size_t a, std::size_t b) const {
  const HeatCloud& A = context_.clouds[a];
  const HeatCloud& B = context_.clouds[b];
  if (A.fixedTemperature && B.fixedTemperature) return false;
  return !contactPairs_.contains({A.material->name, B.material->name});
}

// A mold particleized at graded spacing: its pairs with itself are GradedConduction's.
bool HeatConduction::graded(std::size_t a) const {
  return context_.clouds[a].cloud->hasScalarField(field::localSpacing);
}

std::string HeatConduction::description() const {
  std::ostringstream line;
  line << "conduction (eq. 13, Cleary & Monaghan form; within a material through phi = int "
          "kappa dT, between materials the harmonic-mean kappa; held surfaces at the mold's "
          "wall): diffusion limit "
       << stableDeltaT_ << " s";
  return line.str();
}

// The graded molds' pairs (GradedConduction): made at the start, and again where a decomposed
// run moved a graded cloud's particles between ranks (the same decision on every rank: the
// build is collective); their lines for the log.
std::string HeatConduction::buildGradedPairs() {
  std::ostringstream line;
  graded_.resize(context_.clouds.size());
  gradedLayouts_.resize(context_.clouds.size(), 0);
  const bool decomposed = context_.neighbourhood->decomposed();
  for (std::size_t a = 0; a < context_.clouds.size(); ++a) {
    if (!graded(a) || !conducts(a, a)) continue;
    const ParticleCloud& cloud = *context_.clouds[a].cloud;
    bool stale = !graded_[a] || gradedLayouts_[a] != cloud.layoutVersion();
    if (decomposed) stale = context_.neighbourhood->maxOverRanks(stale ? 1.0 : 0.0) > 0;
    if (!stale) continue;
    graded_[a] = std::make_unique<GradedConduction>(
        cloud, context_.dimension, context_.supportRadius, context_.spacing,
        context_.neighbourhood->periodicBox(), true, decomposed ? context_.neighbourhood : nullptr);
    gradedLayouts_[a] = cloud.layoutVersion();
    if (!line.str().empty()) line << "; ";
    line << graded_[a]->description();
  }
  return line.str();
}

std::string HeatConduction::start() {
  std::ostringstream line;
  line << buildGradedPairs();
  for (std::size_t a = 0; a < context_.clouds.size(); ++a) {
    const HeatCloud& heat = context_.clouds[a];
    const ParticleCloud& cloud = *heat.cloud;
    if (!heat.holdsAny() || cloud.hasVectorField(field::normal) ||
        cloud.hasScalarField(field::wallDistance))
      continue;
    std::size_t placed = context_.dimension == 2 ? placeHeldSurface<2>(a) : placeHeldSurface<3>(a);
    if (context_.comm.size() > 1) {
      // a decomposed run's halo placed its own from an incomplete neighbourhood: its owners',
      // and the count of every rank's own particles given a surface
      context_.neighbourhood->syncHalo(*heat.cloud, {"normal", "wallDistance"});
      const auto& normal = cloud.vectorField(field::normal);
      std::int64_t owned = 0;
      for (std::size_t k = 0; k < cloud.ownedSize(); ++k) owned += normal[k].isZero() ? 0 : 1;
      placed = static_cast<std::size_t>(context_.comm.sum(owned));
    }
    if (!line.str().empty()) line << "; ";
    line << "held surface of cloud '" << cloud.name() << "' placed midway to the free particles"
         << " for " << placed << " of its "
         << context_.comm.sum(static_cast<std::int64_t>(cloud.ownedSize()))
         << " particles (normal, wallDistance)";
  }
  return line.str();
}

// The surface of held cloud `a` from the start state, for each held particle k with free
// particles j of the clouds it conducts with within h: its normal n_k the direction of
// sum_j (x_j - x_k) W_kj, its depth d_k = min_j (x_j - x_k) . n_k - dx/2, the surface half a
// spacing in front of the free particles nearest along n_k (where the lattices of a held box and
// the metal beside it meet, exactly their common face). A particle with no free neighbour gets
// n = 0, d = 0: its surface on its centre. Returns the count of particles given a surface.
template <int Dim>
std::size_t HeatConduction::placeHeldSurface(std::size_t a) {
  const WendlandC2Kernel<Dim> kernel(context_.supportRadius);
  const PeriodicBox periodic = context_.neighbourhood->periodicBox();
  const Real halfSpacing = Real(0.5) * context_.spacing;
  ParticleCloud& cloud = *context_.clouds[a].cloud;
  const Real* held = heldTemperatures(context_.clouds[a]);
  struct Free {
    const NeighbourList* list;
    const Vector* x;
    const Real* held;  // null: none held
  };
  std::vector<Free> frees;
  for (std::size_t b = 0; b < context_.clouds.size(); ++b) {
    const HeatCloud& other = context_.clouds[b];
    if (b == a || other.fixedTemperature || !conducts(a, b)) continue;
    frees.push_back({&context_.neighbourhood->pairs(cloud, *other.cloud),
                     other.cloud->positions().data(), heldTemperatures(other)});
  }
  auto& normal = cloud.addVectorField(field::normal);
  auto& depth = cloud.addScalarField(field::wallDistance);
  const Vector* x = cloud.positions().data();
  std::size_t placed = 0;
  withSeparation(periodic, [&](auto separation) {
#pragma omp parallel for schedule(static) reduction(+ : placed)
    for (std::size_t k = 0; k < cloud.size(); ++k) {
      if (held[k] == Real(0)) continue;
      Vector direction = Vector::Zero();
      for (const Free& free : frees) {
        for (const std::uint32_t j : free.list->of(k)) {
          if (free.held && free.held[j] > Real(0)) continue;
          const Vector xjk = separation(free.x[j], x[k]);
          direction += kernel.value(xjk.norm()) * xjk;
        }
      }
      if (!(direction.norm() > Real(0))) continue;
      const Vector n = direction.normalized();
      Real nearest = std::numeric_limits<Real>::max();
      for (const Free& free : frees) {
        for (const std::uint32_t j : free.list->of(k)) {
          if (free.held && free.held[j] > Real(0)) continue;
          const Real along = separation(free.x[j], x[k]).dot(n);
          if (along > Real(0)) nearest = std::min(nearest, along);
        }
      }
      if (nearest == std::numeric_limits<Real>::max()) continue;
      normal[k] = n;
      depth[k] = std::max(nearest - halfSpacing, Real(0));
      ++placed;
    }
  });
  return placed;
}

void HeatConduction::addEnergyRates() {
  buildGradedPairs();  // where a graded cloud's particles changed places (a decomposed run's)
  if (context_.dimension == 2) {
    addRatesIn<2>();
  } else {
    addRatesIn<3>();
  }
}

template <int Dim>
void HeatConduction::addRatesIn() {
  const WendlandC2Kernel<Dim> kernel(context_.supportRadius);
  const PeriodicBox periodic = context_.neighbourhood->periodicBox();
  const Real etaSquared = Real(0.01) * context_.spacing * context_.spacing;
  const Real closest = Real(0.25) * context_.spacing;  // the least d_f of ghostConductance
  struct Source {
    const Vector* x;
    const Real* T;
    const Real* kappa;
    const Real* volume;
    // A mold with a surface (particleizeMold's normal and wallDistance, or placeHeldSurface's):
    // null without. heldOnSurface: the held temperature (0: free) where it holds any; null
    // otherwise (a held particle without a surface carries it on its centre).
    const Vector* normal;
    const Real* depth;
    const Real* heldOnSurface;
    const Real* kirchhoff;  // phi(T) = int kappa dT of the cloud's material
  };
  // V = m / rho once per particle, not once per pair
  volumes_.resize(context_.clouds.size());
  kirchhoff_.resize(context_.clouds.size());
  std::vector<Source> sources;
  for (std::size_t c = 0; c < context_.clouds.size(); ++c) {
    const HeatCloud& heat = context_.clouds[c];
    const ParticleCloud& cloud = *heat.cloud;
    const auto& mass = cloud.scalarField(field::mass);
    const auto& rho = cloud.scalarField(field::rho);
    std::vector<Real>& volume = volumes_[c];
    volume.resize(cloud.size());
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < volume.size(); ++i) volume[i] = mass[i] / rho[i];
    const TemperatureTable& kappa = heat.material->requireConductivity("heatTransfer conduction");
    const auto& T = cloud.scalarField(field::T);
    std::vector<Real>& phi = kirchhoff_[c];
    phi.resize(cloud.size());
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < phi.size(); ++i) {
      phi[i] = static_cast<Real>(kappa.integral(static_cast<double>(T[i])));
    }
    const bool surface =
        cloud.hasVectorField(field::normal) && cloud.hasScalarField(field::wallDistance);
    sources.push_back({cloud.positions().data(), cloud.scalarField(field::T).data(),
                       cloud.scalarField(field::conductivity).data(), volume.data(),
                       surface ? cloud.vectorField(field::normal).data() : nullptr,
                       surface ? cloud.scalarField(field::wallDistance).data() : nullptr,
                       surface && heat.holdsAny() ? heldTemperatures(heat) : nullptr, phi.data()});
  }
  auto passWith = [&](auto separation) {
    for (std::size_t a = 0; a < context_.clouds.size(); ++a) {
      ParticleCloud& target = *context_.clouds[a].cloud;
      Real* energyRate = target.scalarField(field::energyRate).data();
      const Real* rho = target.scalarField(field::rho).data();
      struct List {
        const NeighbourList* pairs;
        const Source* source;
        bool acrossASurface;  // another cloud, and either has a surface
        bool oneMaterial;     // the two clouds' material is the same
      };
      std::vector<List> lists;
      for (std::size_t b = 0; b < context_.clouds.size(); ++b) {
        if (!conducts(a, b) || (a == b && graded_[a])) continue;
        lists.push_back({&context_.neighbourhood->pairs(target, *context_.clouds[b].cloud),
                         &sources[b], b != a && (sources[a].normal || sources[b].normal),
                         context_.clouds[a].material == context_.clouds[b].material});
      }
      const Source self = sources[a];
      const std::size_t count = target.size();
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < count; ++i) {
        const Vector xi = self.x[i];
        const Real Ti = self.T[i];
        const Real kappaI = self.kappa[i];
        const bool iHeldOnSurface = self.heldOnSurface && self.heldOnSurface[i] > Real(0);
        Real sum = 0;
        for (const auto& [list, source, acrossASurface, oneMaterial] : lists) {
          if (!acrossASurface && oneMaterial) {
            // within one material (no surface between): 2 V_j (phi_i - phi_j) (x_ij . grad_i W)
            // / (r^2 + eta^2), x_ij . grad_i W = r^2 (dW/dr) / r, one division per pair
            const Real phiI = self.kirchhoff[i];
            for (const std::uint32_t j : list->of(i)) {
              const Vector xij = separation(xi, source->x[j]);
              const Real rSquared = xij.squaredNorm();
              const Real numerator = source->volume[j] * Real(2) * (phiI - source->kirchhoff[j]) *
                                     kernel.derivativeOverDistance(std::sqrt(rSquared)) * rSquared;
              sum += numerator / (rSquared + etaSquared);
            }
            continue;
          }
          // V_j 4 kappa_i kappa_j / (kappa_i + kappa_j) (T_i - T_j) (x_ij . grad_i W) /
          // (r^2 + eta^2) with x_ij . grad_i W = r^2 (dW/dr) / r, one division per pair
          if (!acrossASurface) {  // two materials, no surface: the harmonic mean
            for (const std::uint32_t j : list->of(i)) {
              const Vector xij = separation(xi, source->x[j]);
              const Real rSquared = xij.squaredNorm();
              const Real kappaJ = source->kappa[j];
              const Real numerator = source->volume[j] * Real(4) * kappaI * kappaJ *
                                     (Ti - source->T[j]) *
                                     kernel.derivativeOverDistance(std::sqrt(rSquared)) * rSquared;
              sum += numerator / ((kappaI + kappaJ) * (rSquared + etaSquared));
            }
            continue;
          }
          for (const std::uint32_t j : list->of(i)) {
            const Vector xij = separation(xi, source->x[j]);
            const Real rSquared = xij.squaredNorm();
            const Real kappaJ = source->kappa[j];
            const Real numerator = source->volume[j] * (Ti - source->T[j]) *
                                   kernel.derivativeOverDistance(std::sqrt(rSquared)) * rSquared;
            const bool jHeldOnSurface = source->heldOnSurface && source->heldOnSurface[j] > 0;
            Real conductance;  // the pair's 4 kappa_i kappa_j / (kappa_i + kappa_j)
            if (jHeldOnSurface && !iHeldOnSurface) {  // j stands for the held surface before i
              conductance = ghostConductance(kappaI, xij.dot(source->normal[j]) - source->depth[j],
                                             source->depth[j], closest);
            } else if (iHeldOnSurface && !jHeldOnSurface) {  // the same pair from the held side
              conductance = ghostConductance(kappaJ, -xij.dot(self.normal[i]) - self.depth[i],
                                             self.depth[i], closest);
            } else if (source->normal && !self.normal) {  // j a conducting mold's
              conductance =
                  seriesConductance(kappaI, kappaJ, xij.dot(source->normal[j]) - source->depth[j],
                                    source->depth[j], closest);
            } else if (self.normal && !source->normal) {  // i a conducting mold's
              conductance = seriesConductance(
                  kappaJ, kappaI, -xij.dot(self.normal[i]) - self.depth[i], self.depth[i], closest);
            } else {
              conductance = Real(4) * kappaI * kappaJ / (kappaI + kappaJ);
            }
            sum += numerator * conductance / (rSquared + etaSquared);
          }
        }
        energyRate[i] += sum / rho[i];
      }
    }
  };
  withSeparation(periodic, passWith);
  for (std::size_t a = 0; a < context_.clouds.size(); ++a) {
    if (!graded_[a]) continue;
    ParticleCloud& cloud = *context_.clouds[a].cloud;
    graded_[a]->addEnergyRates(kirchhoff_[a].data(), cloud.scalarField(field::mass).data(),
                               cloud.scalarField(field::energyRate).data());
  }
}

}  // namespace sphcast
