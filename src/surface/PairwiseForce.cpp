#include "surface/PairwiseForce.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"
#include "sph/ParticleVolumes.h"

namespace sphcast {

namespace {

using PairConstants = PairwiseForce::PairConstants;

// psi(r) = cos(3 pi r / (2 h)) for r < h
Real pairShape(Real r, Real h) { return std::cos(Real(1.5 * std::numbers::pi) * r / h); }

// The pair function's constants on the lattice of spacing dx (the arrangement a settled liquid
// keeps near, as the colour's bulk sum in ContinuumSurfaceForce), per unit strength s, V = dx^d:
// - the cohesion's virial pressure, p_c = (1 / (2 d)) sum_j V_j r_j psi(r_j) (negative), and
//   the pressure P = -p_c / ((1 / d) sum_j V_j r_j (-W'(r_j))) whose SPH force, a pair force
//   2 P V_j (-W'(r)), makes the bulk's virial 0;
// - the tension of the whole pair function by Kirkwood and Buff: the work to part the lattice
//   along a plane between two layers, per area, halved (two surfaces):
//     sigma / s = -(1 / (2 dx^(d-1))) sum_(i below) sum_(j above) V_i V_j u(r_ij),
//     u(r) = int_r^h psi dt + 2 P W(r) (the pair's potential, 0 at h).
// The continuum's integrals give 20 (2D) and 22 % (3D) less tension: the held pressure's part
// cancels about 60 % of the cohesion's, and the rest follows the arrangement.
template <int Dim>
PairConstants latticePairConstants(Real h, Real dx) {
  const WendlandC2Kernel<Dim> kernel(h);
  const int reach = static_cast<int>(std::ceil(h / dx)) + 1;
  const int zReach = Dim == 3 ? reach : 0;
  const double volume = std::pow(static_cast<double>(dx), Dim);
  const double k = 1.5 * std::numbers::pi / h;
  double virial = 0, pressureVirial = 0;
  for (int c = -zReach; c <= zReach; ++c) {
    for (int b = -reach; b <= reach; ++b) {
      for (int a = -reach; a <= reach; ++a) {
        const double r = dx * std::sqrt(double(a * a + b * b + c * c));
        if (!(r > 0) || !(r < h)) continue;
        virial += volume * r * std::cos(k * r);
        pressureVirial += volume * r * -kernel.derivative(static_cast<Real>(r));
      }
    }
  }
  PairConstants constants;
  constants.cohesionPressure = virial / (2 * Dim);
  constants.heldPressure = -constants.cohesionPressure / (pressureVirial / Dim);
  // layers below (centres at -(m + 1/2) dx) against layers above, one particle a layer below
  // (the work per area is per column of area dx^(d-1))
  double work = 0;
  for (int below = 0; below < reach; ++below) {
    for (int above = 0; above < reach; ++above) {
      const double z = (below + above + 1) * static_cast<double>(dx);
      for (int c = -zReach; c <= zReach; ++c) {
        for (int a = -reach; a <= reach; ++a) {
          const double r = std::sqrt(z * z + dx * dx * double(a * a + c * c));
          if (!(r < h)) continue;
          const double potential = (-1 - std::sin(k * r)) / k +
                                   2 * constants.heldPressure * kernel.value(static_cast<Real>(r));
          work += volume * volume * potential;
        }
      }
    }
  }
  constants.tension = -work / (2 * std::pow(static_cast<double>(dx), Dim - 1));
  return constants;
}

}  // namespace

PairwiseForce::PairwiseForce(SurfaceTensionSettings settings, ParticleCloud& fluid,
                             std::vector<const ParticleCloud*> walls, Neighbourhood& neighbourhood)
    : settings_(std::move(settings)),
      wallShare_((Real(1) + (settings_.cosContactAngle ? *settings_.cosContactAngle : Real(-1))) /
                 Real(2)),
      constants_(settings_.dimension == 2
                     ? latticePairConstants<2>(settings_.supportRadius, settings_.spacing)
                     : latticePairConstants<3>(settings_.supportRadius, settings_.spacing)),
      fluid_(fluid),
      walls_(std::move(walls)),
      neighbourhood_(neighbourhood) {
  if (!settings_.gasTension) throw Error("surface tension: no sigma given");
  if (settings_.solidTension) {
    throw Error("surface tension: the pairwise force takes the contact angle, not Gamma_s");
  }
  requireTemperatureFor(*settings_.gasTension, fluid_);
  neighbourhood_.requestPairs(fluid_, fluid_);
  for (const ParticleCloud* wall : walls_) neighbourhood_.requestPairs(fluid_, *wall);
}

std::string PairwiseForce::summary(double soundSpeed) const {
  (void)soundSpeed;
  const TemperatureTable& sigma = *settings_.gasTension;
  std::ostringstream text;
  text << "pairwise force (Tartakovsky & Panchenko 2016), sigma " << sigma.description()
       << (sigma.isConstant() ? " = " + std::to_string(sigma(0)) + " N/m" : " (a table in T)")
       << ", strength s = " << constants_.strengthPerTension() << " sigma/m^"
       << settings_.dimension + 1 << " (Kirkwood-Buff on the lattice), its cohesion's pressure "
       << constants_.cohesionPressure * constants_.strengthPerTension()
       << " sigma 1/m held by the model";
  if (!walls_.empty()) {
    text << "\n    at the walls: contact angle "
         << std::acos(Real(2) * wallShare_ - Real(1)) * 180 / std::numbers::pi
         << " degrees, the walls attracting with " << wallShare_ << " of the liquid's strength";
  }
  return text.str();
}

double PairwiseForce::stableDeltaT() const {
  return capillaryStepLimit(*settings_.gasTension, tension_, fluid_, settings_.spacing);
}

template <int Dim>
void PairwiseForce::addForce() {
  const WendlandC2Kernel<Dim> kernel(settings_.supportRadius);
  const std::size_t n = fluid_.size();
  volume_ = particleVolumes(fluid_, Dim);
  const std::vector<std::vector<Real>>& wallVolume = wallVolumes_.of(walls_, Dim);
  const auto& x = fluid_.positions();
  const auto& rho = fluid_.scalarField(field::rho);
  auto& acceleration = fluid_.vectorField(field::acceleration);
  const NeighbourList& pairs = neighbourhood_.pairs(fluid_, fluid_);
  std::vector<const NeighbourList*> wallPairs;
  for (const ParticleCloud* wall : walls_) {
    wallPairs.push_back(&neighbourhood_.pairs(fluid_, *wall));
  }
  const PeriodicBox periodic = neighbourhood_.periodicBox();
  const Real h = settings_.supportRadius;
  const Real perTension = static_cast<Real>(constants_.strengthPerTension());
  // 2 P / s: the held pressure's pair force, 2 P V_j (-W'), per unit strength
  const Real held = static_cast<Real>(2 * constants_.heldPressure);
  auto pass = [&](auto separation) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const Real si = perTension * tension_[i];
      Vector force = Vector::Zero();
      Vector missing = Vector::Zero();  // g'_i
      for (const std::uint32_t j : pairs.of(i)) {
        const Vector xij = separation(x[i], x[j]);
        const Real r = xij.norm();
        if (!(r > 0)) continue;
        const Real sij = Real(0.5) * (si + perTension * tension_[j]);
        force += (sij * volume_[j] * pairShape(r, h) / r) * xij;
        // the held pressure's: s_ij V_j (-grad_i W_ij), times 2 P / s below
        missing -= (sij * volume_[j] * kernel.derivativeOverDistance(r)) * xij;
      }
      for (std::size_t w = 0; w < walls_.size(); ++w) {
        const auto& y = walls_[w]->positions();
        const auto& v = wallVolume[w];
        for (const std::uint32_t k : wallPairs[w]->of(i)) {
          const Vector xik = separation(x[i], y[k]);
          const Real r = xik.norm();
          if (!(r > 0)) continue;
          force += (wallShare_ * si * v[k] * pairShape(r, h) / r) * xik;
          missing -= (wallShare_ * si * v[k] * kernel.derivativeOverDistance(r)) * xik;
        }
      }
      acceleration[i] += (force + held * missing) / rho[i];
    }
  };
  withSeparation(periodic, pass);
}

void PairwiseForce::addAcceleration() {
  const auto start = std::chrono::steady_clock::now();
  tensionAtParticles(*settings_.gasTension, fluid_, tension_);
  if (settings_.dimension == 2) {
    addForce<2>();
  } else {
    addForce<3>();
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace sphcast
