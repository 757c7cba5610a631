#include "thermal/HeatConduction.h"

#include <algorithm>
#include <cmath>
#include <sstream>

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
      if (conducts(a, b)) {
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

std::string HeatConduction::description() const {
  std::ostringstream line;
  line << "conduction (eq. 13, Cleary & Monaghan form, harmonic-mean kappa): diffusion limit "
       << stableDeltaT_ << " s";
  return line.str();
}

void HeatConduction::addEnergyRates() {
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
  struct Source {
    const Vector* x;
    const Real* T;
    const Real* kappa;
    const Real* volume;
  };
  // V = m / rho once per particle, not once per pair
  volumes_.resize(context_.clouds.size());
  std::vector<Source> sources;
  for (std::size_t c = 0; c < context_.clouds.size(); ++c) {
    const ParticleCloud& cloud = *context_.clouds[c].cloud;
    const auto& mass = cloud.scalarField("mass");
    const auto& rho = cloud.scalarField("rho");
    std::vector<Real>& volume = volumes_[c];
    volume.resize(cloud.size());
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < volume.size(); ++i) volume[i] = mass[i] / rho[i];
    sources.push_back({cloud.positions().data(), cloud.scalarField("T").data(),
                       cloud.scalarField("conductivity").data(), volume.data()});
  }
  auto passWith = [&](auto separation) {
    for (std::size_t a = 0; a < context_.clouds.size(); ++a) {
      ParticleCloud& target = *context_.clouds[a].cloud;
      Real* energyRate = target.scalarField("energyRate").data();
      const Real* rho = target.scalarField("rho").data();
      std::vector<std::pair<const NeighbourList*, const Source*>> lists;
      for (std::size_t b = 0; b < context_.clouds.size(); ++b) {
        if (!conducts(a, b)) continue;
        lists.emplace_back(&context_.neighbourhood->pairs(target, *context_.clouds[b].cloud),
                           &sources[b]);
      }
      const Source self = sources[a];
      const std::size_t count = target.size();
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < count; ++i) {
        const Vector xi = self.x[i];
        const Real Ti = self.T[i];
        const Real kappaI = self.kappa[i];
        Real sum = 0;
        for (const auto& [list, source] : lists) {
          for (const std::uint32_t j : list->of(i)) {
            const Vector xij = separation(xi, source->x[j]);
            const Real rSquared = xij.squaredNorm();
            const Real kappaJ = source->kappa[j];
            // V_j 4 kappa_i kappa_j / (kappa_i + kappa_j) (T_i - T_j) (x_ij . grad_i W) /
            // (r^2 + eta^2) with x_ij . grad_i W = r^2 (dW/dr) / r, one division per pair
            const Real numerator = source->volume[j] * Real(4) * kappaI * kappaJ *
                                   (Ti - source->T[j]) *
                                   kernel.derivativeOverDistance(std::sqrt(rSquared)) * rSquared;
            sum += numerator / ((kappaI + kappaJ) * (rSquared + etaSquared));
          }
        }
        energyRate[i] += sum / rho[i];
      }
    }
  };
  withSeparation(periodic, passWith);
}

}  // namespace sphcast
