#include "surface/SurfaceEnergyTension.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <type_traits>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "particles/WallSurfaceDistance.h"
#include "particles/WendlandKernel.h"
#include "sph/ExposedArea.h"

namespace sphcast {

namespace {

template <int Dim>
Real flatSurfaceFactor(Real supportRadius, Real spacing, Real core) {
  const GranularityKernel<Dim> kernel(supportRadius, spacing, core);
  const Real columnSum = flatSurfaceExposureSum<Dim>(kernel, supportRadius, spacing);
  if (!(columnSum > 0)) {
    throw Error("surface tension: a flat surface has no particle with g > 0 at h/dx " +
                std::to_string(supportRadius / spacing) + " (the kernel is too narrow)");
  }
  return Real(1) / columnSum;
}

}  // namespace

Real SurfaceEnergyTension::latticeEnergyFactor(int dimension, Real supportRadius, Real spacing,
                                               Real coreRadius) {
  const Real core = coreRadius * spacing;
  return dimension == 2 ? flatSurfaceFactor<2>(supportRadius, spacing, core)
                        : flatSurfaceFactor<3>(supportRadius, spacing, core);
}

// A relaxed surface is not a lattice face: its outer particles move in and out of the row
// until the force on each vanishes, and the energy per area falls to 0.2 of the lattice face's
// (2D). What a drop feels is not that energy but the work of stretching the surface, its
// mechanical tension (the surface keeps its particles as it stretches). It depends on how the
// particles are arranged, so these are means of measurements that scatter (doc/physics.md
// §10.1). 2D: the pressure of relaxed static drops of 30, 40 and 60 particles across (0.52,
// 0.47, 0.60 of Laplace's), their periods at 30 and 40 (0.46, 0.57 of the tension Lamb's needs)
// and the stretching work of relaxed periodic slabs (0.42 to 0.56). 3D: the static drop of 20
// across (0.63), between 1.13 at 16 and 0.30 at 26 across: in 3D it falls with resolution.
Real SurfaceEnergyTension::relaxedTensionRatio(int dimension) {
  return dimension == 2 ? Real(0.52) : Real(0.63);
}

Real SurfaceEnergyTension::calibratedEnergyFactor(int dimension, Real supportRadius, Real spacing,
                                                  Real coreRadius) {
  return latticeEnergyFactor(dimension, supportRadius, spacing, coreRadius) /
         relaxedTensionRatio(dimension);
}

SurfaceEnergyTension::SurfaceEnergyTension(SurfaceTensionSettings settings, ParticleCloud& fluid,
                                           std::vector<const ParticleCloud*> walls,
                                           Neighbourhood& neighbourhood)
    : settings_(std::move(settings)),
      energyFactor_(settings_.energyFactor > 0
                        ? settings_.energyFactor
                        : calibratedEnergyFactor(settings_.dimension, settings_.supportRadius,
                                                 settings_.spacing, settings_.coreRadius)),
      wallSmoothing_(settings_.wallSmoothing > 0 ? settings_.wallSmoothing
                                                 : settings_.supportRadius),
      fluid_(fluid),
      walls_(std::move(walls)),
      neighbourhood_(neighbourhood) {
  if (!settings_.gasTension) throw Error("surface tension: no Gamma_g given");
  if (settings_.cosContactAngle && settings_.solidTension) {
    throw Error("surface tension: give the contact angle or Gamma_s, not both");
  }
  requireTemperatureFor(*settings_.gasTension, fluid_);
  if (!fluid_.hasScalarField(field::surfaceEnergy)) fluid_.addScalarField(field::surfaceEnergy);
  neighbourhood_.requestPairs(fluid_, fluid_);
  for (const ParticleCloud* wall : walls_) neighbourhood_.requestPairs(fluid_, *wall);
}

Real SurfaceEnergyTension::solidTension(Real gasTension) const {
  if (settings_.solidTension) return *settings_.solidTension;
  const Real cosine = settings_.cosContactAngle ? *settings_.cosContactAngle : Real(-1);
  return -cosine * gasTension;
}

void SurfaceEnergyTension::updateGasTension() {
  tensionAtParticles(*settings_.gasTension, fluid_, gasTension_);
  largestTension_ = largestTension(gasTension_);
}

double SurfaceEnergyTension::largestTension(const std::vector<Real>& gasTension) const {
  Real largest = 0;
  for (const Real gamma : gasTension) {
    largest = std::max({largest, gamma, std::abs(solidTension(gamma))});
  }
  return static_cast<double>(largest);
}

double SurfaceEnergyTension::currentLargestTension() const {
  if (largestTension_ >= 0) return largestTension_;
  // before the first pass (a restart): Gamma_g at the particles' T now
  const TemperatureTable& table = *settings_.gasTension;
  std::vector<Real> gamma(fluid_.size(), static_cast<Real>(table(0)));
  if (!table.isConstant()) {
    const auto& temperature = fluid_.scalarField(field::T);
    for (std::size_t i = 0; i < gamma.size(); ++i) {
      gamma[i] = static_cast<Real>(table(static_cast<double>(temperature[i])));
    }
  }
  return largestTension(gamma);
}

double SurfaceEnergyTension::lightestDensity() const {
  const auto& rho = fluid_.scalarField(field::rho);
  return rho.empty() ? 0 : static_cast<double>(*std::min_element(rho.begin(), rho.end()));
}

double SurfaceEnergyTension::stableDeltaT() const {
  const double largest = currentLargestTension();
  if (!(largest > 0)) return std::numeric_limits<double>::max();
  const double dx = static_cast<double>(settings_.spacing);
  return 0.25 * std::sqrt(lightestDensity() * dx * dx * dx / (2 * std::numbers::pi * largest));
}

std::string SurfaceEnergyTension::summary(double soundSpeed) const {
  const TemperatureTable& gamma = *settings_.gasTension;
  std::ostringstream text;
  text << "surface energy (paper eqs. (7)-(12)), R_d = " << energyFactor_
       << (settings_.energyFactor > 0 ? "" : " (calibrated on a relaxed surface)") << ", Gamma_g "
       << gamma.description()
       << (gamma.isConstant() ? " = " + std::to_string(gamma(0)) + " N/m" : " (a table in T)")
       << "\n    surface layer's compression R_d Gamma_g / (rho c^2 dx) = "
       << 100 * surfaceCompression(soundSpeed) << " % (at the particles' T now)";
  if (!walls_.empty()) {
    text << "\n    at the walls: ";
    if (settings_.solidTension) {
      text << "Gamma_s = " << *settings_.solidTension << " N/m";
    } else {
      const double cosine = settings_.cosContactAngle ? *settings_.cosContactAngle : -1.0;
      text << "contact angle " << std::acos(cosine) * 180 / std::numbers::pi << " degrees";
    }
    text << ", chi over " << wallSmoothing_ << " m";
  }
  return text.str();
}

std::string SurfaceEnergyTension::settingsWarning(double soundSpeed) const {
  const double compression = surfaceCompression(soundSpeed);
  if (!(compression > 0.03)) return {};
  return "the surface tension compresses the surface layer by " +
         std::to_string(100 * compression) +
         " % of its density (R_d Gamma_g / (rho c^2 dx)): raise soundSpeed in system/sphSchemes "
         "towards " +
         std::to_string(soundSpeed * std::sqrt(compression / 0.01)) +
         " m/s for 1 %; the calibration of R_d was measured at 0.3 to 3 %";
}

double SurfaceEnergyTension::surfaceCompression(double soundSpeed) const {
  return static_cast<double>(energyFactor_) * currentLargestTension() /
         (lightestDensity() * soundSpeed * soundSpeed * static_cast<double>(settings_.spacing));
}

// s_i, the wall distance, e_i and phi_i of every particle (the first pass).
template <int Dim>
void SurfaceEnergyTension::computeEnergy() {
  const GranularityKernel<Dim> kernel(settings_.supportRadius, settings_.spacing,
                                      settings_.coreRadius * settings_.spacing);
  const Real selfKernel = kernel.value(0);
  constexpr Real areaExponent = Real(Dim - 1) / Real(Dim);
  const Real energyFactor = energyFactor_;
  const Real eps = wallSmoothing_;
  const Real spacing = settings_.spacing;
  constexpr Real roundOff = std::is_same_v<Real, float> ? Real(1e-5) : Real(1e-9);
  const std::size_t n = fluid_.size();
  updateGasTension();
  volume_ = particleVolumes(fluid_, settings_.dimension);
  energyDerivative_.resize(n);
  explicitDensityDerivative_.resize(n);
  wallForce_.resize(n);
  const auto& x = fluid_.positions();
  auto& energy = fluid_.scalarField(field::surfaceEnergy);
  const NeighbourList& pairs = neighbourhood_.pairs(fluid_, fluid_);
  const PeriodicBox periodic = neighbourhood_.periodicBox();
  const std::vector<WallSurfaceView> walls = wallSurfaceViews(fluid_, walls_, neighbourhood_);
  const bool fixedSolidTension = settings_.solidTension.has_value();
  const Real solidTensionValue = fixedSolidTension ? *settings_.solidTension : Real(0);
  const Real cosine = settings_.cosContactAngle ? *settings_.cosContactAngle : Real(-1);
  auto passWith = [&](auto separation) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      Real s = volume_[i] * selfKernel;
      for (const std::uint32_t j : pairs.of(i)) {
        s += volume_[j] * kernel.value(separation(x[i], x[j]).norm());
      }
      const Real gas = gasTension_[i];
      const Real solid = fixedSolidTension ? solidTensionValue : -cosine * gas;
      Real chi = 1, chiSlope = 0;
      Vector normal = Vector::Zero();
      if (!walls.empty() && gas != solid) {
        const WallSurfaceDistance wall = wallSurfaceDistance(x[i], i, walls, periodic, spacing);
        if (wall.found) {
          chi = wallIndicator(wall.distance, eps);
          chiSlope = wallIndicatorSlope(wall.distance, eps);
          normal = wall.normal;
        }
      }
      const Real tension = gas * chi + solid * (Real(1) - chi);
      // inside the liquid s is 1 but for round-off, and a hair below 1 is a g of 1e-45 that
      // would keep the pair passes busy there: below 1e-9 it is 0 (g(1e-9) is 1e-27 of a face's)
      const Real deficit = Real(1) - s;
      const Real p = deficit > roundOff ? deficit : Real(0);
      const Real q = Real(1) - volume_[i] * selfKernel;
      const Real area = std::pow(volume_[i], areaExponent);
      const Real weight = energyFactor * exposureWeight(p, q);
      energy[i] = weight * tension * area;
      // dg(1 - s)/ds = -g_p
      energyDerivative_[i] = -energyFactor * exposureWeightSlope(p, q) * tension * area;
      wallForce_[i] = (-weight * area * (gas - solid) * chiSlope) * normal;
      // e_i depends on rho_i also through q_i = 1 - V_i W(0) and V_i^(1-1/d), V_i = m_i / rho_i:
      // rho_i de_i/drho_i = R_d Gamma_i V_i^(1-1/d) (g_q V_i W(0) - (1 - 1/d) g)
      explicitDensityDerivative_[i] = energyFactor * tension * area *
                                      (exposureWeightSlopeInQ(p, q) * volume_[i] * selfKernel -
                                       exposureWeight(p, q) * areaExponent);
    }
  };
  withSeparation(periodic, passWith);
  // a decomposed run's halo: its owners' phi, which the force and Psi passes read at neighbours
  neighbourhood_.syncHalo(fluid_, energyDerivative_);
}

// Psi_j = dE/drho_j = -(V_j / rho_j) (phi_j W_s(0) + sum_i phi_i W_s,ij) + the explicit part
// (s_i holds V_j = m_j / rho_j of every neighbour j, and of i itself).
template <int Dim>
void SurfaceEnergyTension::computeDensityDerivative() {
  const GranularityKernel<Dim> kernel(settings_.supportRadius, settings_.spacing,
                                      settings_.coreRadius * settings_.spacing);
  const Real selfKernel = kernel.value(0);
  const std::size_t n = fluid_.size();
  densityDerivative_.resize(n);
  const auto& x = fluid_.positions();
  const auto& rho = fluid_.scalarField(field::rho);
  const NeighbourList& pairs = neighbourhood_.pairs(fluid_, fluid_);
  const PeriodicBox periodic = neighbourhood_.periodicBox();
  const Real* phi = energyDerivative_.data();
  auto passWith = [&](auto separation) {
#pragma omp parallel for schedule(static)
    for (std::size_t j = 0; j < n; ++j) {
      Real sum = phi[j] * selfKernel;
      for (const std::uint32_t i : pairs.of(j)) {
        if (phi[i] == Real(0)) continue;
        sum += phi[i] * kernel.value(separation(x[j], x[i]).norm());
      }
      densityDerivative_[j] = -volume_[j] / rho[j] * sum + explicitDensityDerivative_[j] / rho[j];
    }
  };
  withSeparation(periodic, passWith);
  neighbourhood_.syncHalo(fluid_, densityDerivative_);  // the force pass reads Psi_j
}

std::vector<Real> SurfaceEnergyTension::densityDerivative() {
  if (settings_.dimension == 2) {
    computeEnergy<2>();
    computeDensityDerivative<2>();
  } else {
    computeEnergy<3>();
    computeDensityDerivative<3>();
  }
  return densityDerivative_;
}

// f_k = -sum_j (phi_k V_j + phi_j V_k) grad_k W_s,kj + the wall's pull (the second pass); with
// densityCoupling also the pressure p_j = rho_j^2 Psi_j / m_j in the form of the momentum
// equation, -sum_j (Psi_k m_j + Psi_j m_k) grad_k W_kj, with the flow's kernel W.
template <int Dim>
void SurfaceEnergyTension::addForces() {
  const GranularityKernel<Dim> kernel(settings_.supportRadius, settings_.spacing,
                                      settings_.coreRadius * settings_.spacing);
  const std::size_t n = fluid_.size();
  const auto& x = fluid_.positions();
  const auto& mass = fluid_.scalarField(field::mass);
  auto& acceleration = fluid_.vectorField(field::acceleration);
  const NeighbourList& pairs = neighbourhood_.pairs(fluid_, fluid_);
  const PeriodicBox periodic = neighbourhood_.periodicBox();
  const bool surfaceOnly = settings_.surfaceParticlesOnly;
  const Real* phi = energyDerivative_.data();
  const Real* volume = volume_.data();
  const bool coupling = settings_.densityCoupling;
  if (coupling) computeDensityDerivative<Dim>();
  const Real* psi = coupling ? densityDerivative_.data() : nullptr;
  const WendlandC2Kernel<Dim> flowKernel(settings_.supportRadius);
  auto passWith = [&](auto separation) {
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      Vector force = wallForce_[k];
      const Real phiK = phi[k];
      const Real volumeK = volume[k];
      const Real psiK = coupling ? psi[k] : Real(0);
      for (const std::uint32_t j : pairs.of(k)) {
        const Real psiJ = coupling ? psi[j] : Real(0);
        // inside the fluid both ends have g = 0: no force, no kernel to evaluate
        if (surfaceOnly && phiK == Real(0) && phi[j] == Real(0) && psiK == Real(0) &&
            psiJ == Real(0)) {
          continue;
        }
        const Vector xkj = separation(x[k], x[j]);
        const Real r = xkj.norm();
        Real coefficient = (phiK * volume[j] + phi[j] * volumeK) * kernel.derivativeOverDistance(r);
        if (coupling) {
          coefficient += (psiK * mass[j] + psiJ * mass[k]) * flowKernel.derivativeOverDistance(r);
        }
        force -= coefficient * xkj;
      }
      acceleration[k] += force / mass[k];
    }
  };
  withSeparation(periodic, passWith);
}

void SurfaceEnergyTension::addAcceleration() {
  const auto start = std::chrono::steady_clock::now();
  if (settings_.dimension == 2) {
    computeEnergy<2>();
    addForces<2>();
  } else {
    computeEnergy<3>();
    addForces<3>();
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double SurfaceEnergyTension::energy() {
  if (settings_.dimension == 2) {
    computeEnergy<2>();
  } else {
    computeEnergy<3>();
  }
  double sum = 0;  // the owned particles' (a decomposed run's rank's share)
  const auto& energy = fluid_.scalarField(field::surfaceEnergy);
  for (std::size_t i = 0; i < fluid_.ownedSize(); ++i) sum += static_cast<double>(energy[i]);
  return sum;
}

}  // namespace sphcast
