#include "thermal/MoldContactTransfer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"

namespace sphcast {

namespace {

template <int Dim>
Real contactLengthIn(Real supportRadius, Real spacing) {
  const WendlandC2Kernel<Dim> kernel(supportRadius);
  const int reach = static_cast<int>(std::ceil(supportRadius / spacing)) + 1;
  // One column of side A (layers at z = -(m + 1/2) dx) against the whole of side B (layers at
  // z = (n + 1/2) dx): sum V_i V_k W / dx^(d-1) with V = dx^d.
  double sum = 0;
  for (int m = 0; m <= reach; ++m) {
    for (int n = 0; n <= reach; ++n) {
      const int dz = m + n + 1;
      const int dyRange = Dim == 3 ? reach : 0;
      for (int dy = -dyRange; dy <= dyRange; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          const Real r = spacing * std::sqrt(Real(dx * dx + dy * dy + dz * dz));
          sum += kernel.value(r);
        }
      }
    }
  }
  return static_cast<Real>(sum) * std::pow(spacing, Dim + 1);
}

const Dimensions heatTransferCoefficient{{1, 0, -3, -1, 0, 0, 0}};

}  // namespace

Real MoldContactTransfer::contactLength(int dimension, Real supportRadius, Real spacing) {
  return dimension == 2 ? contactLengthIn<2>(supportRadius, spacing)
                        : contactLengthIn<3>(supportRadius, spacing);
}

std::map<std::pair<std::string, std::string>, double> MoldContactTransfer::readCoefficients(
    const HeatTransferContext& context, const Dictionary& dict) {
  dict.checkKeys({"coefficients"});
  std::map<std::pair<std::string, std::string>, double> coefficients;
  using Row = std::tuple<std::string, std::string, double>;
  const auto rows = dict.get<std::vector<Row>>("coefficients", heatTransferCoefficient);
  for (const auto& [first, second, omega] : rows) {
    for (const std::string& material : {first, second}) {
      cloudsOfMaterial(context, material, dict, "coefficients");  // throws when none has it
    }
    if (!(omega > 0) || !std::isfinite(omega)) {
      throw DictionaryError(dict.location("coefficients"),
                            "the contact coefficient of (" + first + " " + second + ") in " +
                                dict.name() + " must be positive (W/m^2/K)");
    }
    if (first == second) {
      throw DictionaryError(dict.location("coefficients"),
                            "a contact coefficient joins two materials; (" + first + " " + second +
                                ") in " + dict.name() + " names one twice");
    }
    coefficients[{first, second}] = omega;
    coefficients[{second, first}] = omega;
  }
  return coefficients;
}

MoldContactTransfer::MoldContactTransfer(const HeatTransferContext& context, const Dictionary& dict)
    : context_(context),
      coefficients_(readCoefficients(context, dict)),
      contactLength_(contactLength(context.dimension, context.supportRadius, context.spacing)) {
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < context_.clouds.size(); ++a) {
    for (std::size_t b = 0; b < context_.clouds.size(); ++b) {
      const double omega = coefficient(a, b);
      if (omega == 0) continue;
      const HeatCloud& heat = context_.clouds[a];
      context_.neighbourhood->requestPairs(*heat.cloud, *context_.clouds[b].cloud);
      const Material& material = *heat.material;
      const InternalEnergyTable& energy =
          material.requireInternalEnergy("heatTransfer moldContact");
      const TemperatureTable& rho = material.requireDensity("heatTransfer moldContact");
      const double lowestDensity =
          std::min(rho(rho.lowestTemperature()), rho(rho.highestTemperature()));
      shortest = std::min(
          shortest, 0.25 * lowestDensity * energy.smallestSpecificHeat() * contactLength_ / omega);
    }
  }
  stableDeltaT_ = shortest;
}

double MoldContactTransfer::coefficient(std::size_t a, std::size_t b) const {
  const HeatCloud& A = context_.clouds[a];
  const HeatCloud& B = context_.clouds[b];
  if (A.fixedTemperature && B.fixedTemperature) return 0;
  const auto found = coefficients_.find({A.material->name, B.material->name});
  return found == coefficients_.end() ? 0 : found->second;
}

std::string MoldContactTransfer::description() const {
  std::ostringstream line;
  line << "moldContact (eq. 14, normalised to omega A dT on a flat interface, l_W = "
       << contactLength_ << " m):";
  for (const auto& [pair, omega] : coefficients_) {
    if (pair.first < pair.second) line << " " << pair.first << "-" << pair.second << " " << omega;
  }
  line << " W/m^2/K; limit " << stableDeltaT_ << " s";
  return line.str();
}

void MoldContactTransfer::addEnergyRates() {
  if (context_.dimension == 2) {
    addRatesIn<2>();
  } else {
    addRatesIn<3>();
  }
}

template <int Dim>
void MoldContactTransfer::addRatesIn() {
  const WendlandC2Kernel<Dim> kernel(context_.supportRadius);
  const PeriodicBox periodic = context_.neighbourhood->periodicBox();
  for (std::size_t a = 0; a < context_.clouds.size(); ++a) {
    ParticleCloud& target = *context_.clouds[a].cloud;
    const auto& x = target.positions();
    const Real* T = target.scalarField(field::T).data();
    const Real* rho = target.scalarField(field::rho).data();
    Real* energyRate = target.scalarField(field::energyRate).data();
    for (std::size_t b = 0; b < context_.clouds.size(); ++b) {
      const double omega = coefficient(a, b);
      if (omega == 0) continue;
      const ParticleCloud& other = *context_.clouds[b].cloud;
      const NeighbourList& list = context_.neighbourhood->pairs(target, other);
      const Vector* otherX = other.positions().data();
      const Real* otherT = other.scalarField(field::T).data();
      const Real* otherMass = other.scalarField(field::mass).data();
      const Real* otherRho = other.scalarField(field::rho).data();
      const Real scale = static_cast<Real>(omega) / contactLength_;
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < x.size(); ++i) {
        Real sum = 0;
        for (const std::uint32_t k : list.of(i)) {
          const Real W = kernel.value(periodic.separation(x[i], otherX[k]).norm());
          sum += (otherMass[k] / otherRho[k]) * W * (T[i] - otherT[k]);
        }
        energyRate[i] -= scale * sum / rho[i];
      }
    }
  }
}

}  // namespace sphcast
