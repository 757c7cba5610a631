#include "rheology/ElastoViscoplastic.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"

namespace sphcast {
namespace {

constexpr const char* stressDiagonal = "stressDiagonal";  // tau_xx, tau_yy, tau_zz, Pa
constexpr const char* stressShear = "stressShear";        // tau_xy, tau_yz, tau_zx, Pa

ElastoViscoplasticSettings readSettings(const Dictionary& rheology) {
  rheology.checkKeys({"model", "elastoViscoplasticCoeffs"});
  if (!rheology.found("elastoViscoplasticCoeffs")) {
    throw DictionaryError(rheology.location(),
                          "rheology elastoViscoplastic needs elastoViscoplasticCoeffs { tau0 "
                          "(Pa); k (Pa s^n); n; G (Pa, the shear modulus below tau0); etaS (Pa "
                          "s, a Newtonian part, may be 0); } in " +
                              rheology.name());
  }
  const Dictionary& coeffs = rheology.subDict("elastoViscoplasticCoeffs");
  coeffs.checkKeys({"tau0", "k", "n", "G", "etaS"});
  ElastoViscoplasticSettings settings;
  settings.yieldStress = lawCoefficient(coeffs, "tau0", true);
  settings.consistency = lawCoefficient(coeffs, "k", true);
  settings.exponent = lawCoefficient(coeffs, "n", false);
  settings.shearModulus = lawCoefficient(coeffs, "G", false);
  settings.solventViscosity = lawCoefficient(coeffs, "etaS", true);
  return settings;
}

// The symmetric stress from its two stored vectors, and back.
Matrix stressOf(const Vector& diagonal, const Vector& shear) {
  Matrix tau;
  tau << diagonal.x(), shear.x(), shear.z(),  //
      shear.x(), diagonal.y(), shear.y(),     //
      shear.z(), shear.y(), diagonal.z();
  return tau;
}

// |tau| = sqrt(tau:tau / 2), the stress that simple shear tau_xy = s gives as s.
Real magnitude(const Matrix& tau) { return std::sqrt(Real(0.5) * tau.cwiseAbs2().sum()); }

}  // namespace

ElastoViscoplastic::ElastoViscoplastic(const RheologyContext& context, const Dictionary& settings)
    : ElastoViscoplastic(context, readSettings(settings)) {}

ElastoViscoplastic::ElastoViscoplastic(const RheologyContext& context,
                                       ElastoViscoplasticSettings settings)
    : fluid_(context.fluid),
      neighbourhood_(context.neighbourhood),
      walls_(context.walls),
      dimension_(context.dimension),
      supportRadius_(context.supportRadius),
      settings_(settings) {
  for (const char* name : {stressDiagonal, stressShear}) {
    if (!fluid_.hasVectorField(name)) {
      fluid_.addVectorField(name).assign(fluid_.size(), Vector::Zero());
    }
  }
  if (!fluid_.hasScalarField(field::shearRate)) {
    fluid_.addScalarField(field::shearRate).assign(fluid_.size(), Real(0));
  }
}

std::vector<std::string> ElastoViscoplastic::fields() const {
  return {stressDiagonal, stressShear, field::shearRate};
}

std::string ElastoViscoplastic::description() const {
  std::ostringstream text;
  text << "elasto-viscoplastic (Saramito 2007, Jaumann rate): elastic below tau0 = "
       << settings_.yieldStress << " Pa with G = " << settings_.shearModulus
       << " Pa, Herschel-Bulkley flow above, k = " << settings_.consistency
       << " Pa s^n, n = " << settings_.exponent << "; etaS = " << settings_.solventViscosity
       << " Pa s";
  return text.str();
}

Real ElastoViscoplastic::plasticMagnitude(Real trialMagnitude, double dt) const {
  const Real tau0 = settings_.yieldStress;
  if (!(trialMagnitude > tau0)) return trialMagnitude;
  const Real k = settings_.consistency, n = settings_.exponent;
  const Real stiffness = static_cast<Real>(dt) * settings_.shearModulus;
  if (!(k > 0)) return tau0;  // perfectly plastic: back onto the yield surface
  if (n == 1) return (trialMagnitude + stiffness * tau0 / k) / (1 + stiffness / k);
  // s + dt G ((s - tau0) / k)^(1/n) = trial: increasing in s on [tau0, trial]; bisection to
  // round-off (the function's slope is unbounded at tau0 for n < 1, where Newton stalls).
  Real low = tau0, high = trialMagnitude;
  for (int iteration = 0;
       iteration < 200 && high - low > 4 * std::numeric_limits<Real>::epsilon() * high;
       ++iteration) {
    const Real s = Real(0.5) * (low + high);
    const Real residual = s + stiffness * std::pow((s - tau0) / k, 1 / n) - trialMagnitude;
    (residual > 0 ? high : low) = s;
  }
  return Real(0.5) * (low + high);
}

void ElastoViscoplastic::update(double dt) {
  const auto start = std::chrono::steady_clock::now();
  computeVelocityGradients(fluid_, neighbourhood_, walls_, dimension_, supportRadius_, gradient_);
  auto& diagonal = fluid_.vectorField(stressDiagonal);
  auto& shear = fluid_.vectorField(stressShear);
  auto& shearRate = fluid_.scalarField(field::shearRate);
  auto& mu = fluid_.scalarField(field::viscosity);
  const Real* frozen =
      fluid_.hasScalarField(field::frozen) ? fluid_.scalarField(field::frozen).data() : nullptr;
  const Real step = static_cast<Real>(dt);
  const Real twoG = 2 * settings_.shearModulus;
  // the identity of the run's dimensions: a 2D run's tau_zz stays zero
  Matrix planeIdentity = Matrix::Identity();
  if (dimension_ == 2) planeIdentity(2, 2) = 0;
  const std::size_t owned = fluid_.ownedSize();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < owned; ++i) {
    const Matrix& L = gradient_[i];
    const Matrix strain = Real(0.5) * (L + L.transpose());
    shearRate[i] = shearRateOf(L);
    mu[i] = settings_.solventViscosity;
    if (frozen && frozen[i] != 0) continue;  // held rigid by the solidification
    const Matrix spin = Real(0.5) * (L - L.transpose());
    const Matrix deviatoric = strain - (strain.trace() / Real(dimension_)) * planeIdentity;
    const Matrix tau = stressOf(diagonal[i], shear[i]);
    Matrix trial = tau + step * (twoG * deviatoric + spin * tau - tau * spin);
    const Real trialMagnitude = magnitude(trial);
    if (trialMagnitude > settings_.yieldStress) {
      trial *= plasticMagnitude(trialMagnitude, dt) / trialMagnitude;
    }
    diagonal[i] = trial.diagonal();
    shear[i] = Vector(trial(0, 1), trial(1, 2), trial(2, 0));
  }
  // the pair terms read the neighbours' stress and mu
  neighbourhood_.syncHalo(fluid_, diagonal);
  neighbourhood_.syncHalo(fluid_, shear);
  neighbourhood_.syncHalo(fluid_, mu);
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

namespace {

template <int Dim>
void addStressDivergence(ParticleCloud& fluid, const Neighbourhood& neighbourhood,
                         const std::vector<ShearWall>& walls, Real supportRadius) {
  const WendlandC2Kernel<Dim> kernel(supportRadius);
  const PeriodicBox periodic = neighbourhood.periodicBox();
  const NeighbourList& pairs = neighbourhood.pairs(fluid, fluid);
  const auto& x = fluid.positions();
  const auto& rho = fluid.scalarField(field::rho);
  const auto& mass = fluid.scalarField(field::mass);
  const auto& diagonal = fluid.vectorField(stressDiagonal);
  const auto& shear = fluid.vectorField(stressShear);
  auto& acceleration = fluid.vectorField(field::acceleration);
  std::vector<const NeighbourList*> wallPairs;
  for (const ShearWall& wall : walls) wallPairs.push_back(&neighbourhood.pairs(fluid, *wall.cloud));
  const std::size_t owned = fluid.ownedSize();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < owned; ++i) {
    const Matrix tau = stressOf(diagonal[i], shear[i]);
    Vector force = Vector::Zero();  // sum_j V_j (tau_i + tau_j) grad_i W_ij
    for (const std::uint32_t j : pairs.of(i)) {
      const Vector xij = periodic.separation(x[i], x[j]);
      const Real r = xij.norm();
      if (!(r > 0)) continue;
      force +=
          (mass[j] / rho[j]) * ((tau + stressOf(diagonal[j], shear[j])) * kernel.gradient(xij, r));
    }
    for (std::size_t w = 0; w < walls.size(); ++w) {
      const ShearWall& wall = walls[w];
      const auto& y = wall.cloud->positions();
      const auto& volume = wall.cloud->scalarField(field::volume);
      const auto& normal = wall.cloud->vectorField(field::normal);
      const bool slip = wall.condition.slip();
      for (const std::uint32_t k : wallPairs[w]->of(i)) {
        const Vector xik = periodic.separation(x[i], y[k]);
        const Real r = xik.norm();
        if (!(r > 0)) continue;
        Matrix image = tau;
        if (slip) {
          const Vector n = normal[k].normalized();  // a corner's normal may be unscaled
          const Matrix mirror = Matrix::Identity() - 2 * n * n.transpose();
          image = mirror * tau * mirror;
        }
        force += volume[k] * ((tau + image) * kernel.gradient(xik, r));
      }
    }
    acceleration[i] += force / rho[i];
  }
}

}  // namespace

void ElastoViscoplastic::addAcceleration() {
  const auto start = std::chrono::steady_clock::now();
  if (dimension_ == 2) {
    addStressDivergence<2>(fluid_, neighbourhood_, walls_, supportRadius_);
  } else {
    addStressDivergence<3>(fluid_, neighbourhood_, walls_, supportRadius_);
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double ElastoViscoplastic::stableDeltaT() const {
  const auto& rho = fluid_.scalarField(field::rho);
  Real lightest = std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < fluid_.ownedSize(); ++i) lightest = std::min(lightest, rho[i]);
  if (!(lightest < std::numeric_limits<Real>::infinity())) {
    return std::numeric_limits<double>::infinity();
  }
  const double spacing = fluid_.attributes().at("spacing");
  const double waveSpeed = std::sqrt(4.0 / 3.0 * settings_.shearModulus / lightest);
  return -neighbourhood_.maxOverRanks(-0.25 * spacing / waveSpeed);  // every rank alike
}

}  // namespace sphcast
