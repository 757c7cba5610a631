#include "solidification/Solidification.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <sstream>
#include <vector>

#include "core/Error.h"
#include "particles/FieldNames.h"

namespace sphcast {

Solidification::Solidification(SolidificationSettings settings, const Material& material,
                               ParticleCloud& metal)
    : settings_(settings), material_(material), metal_(metal) {
  const char* neededBy = "solidification";
  const FreezingRange& range = material_.requireFreezingRange(neededBy);
  const InternalEnergyTable& energy = material_.requireInternalEnergy(neededBy);
  material_.requireDensity(neededBy);
  material_.requireViscosity(neededBy);
  liquidusEnergy_ = energy.energy(static_cast<Real>(range.liquidus));
  solidusEnergy_ = energy.energy(static_cast<Real>(range.solidus));
  freezingRangeEnergy_ = liquidusEnergy_ - solidusEnergy_;
  const auto tc =
      static_cast<Real>(criticalTemperature(range, settings_.criticalTemperatureFraction));
  criticalEnergy_ = energy.energy(tc);
  criticalSpecificHeat_ = energy.specificHeat(tc);
  if (!metal_.hasScalarField(field::T)) {
    throw Error("solidification needs the temperature T of cloud '" + metal_.name() +
                "': heatTransfer must carry it (its clouds)");
  }
  for (const std::string& name : fields()) {
    if (metal_.hasScalarField(name)) continue;
    auto& field = metal_.addScalarField(name);
    const auto& history = historyFields();
    if (std::find(history.begin(), history.end(), name) != history.end()) {
      std::fill(field.begin(), field.end(), Real(-1));
    }
  }
}

const std::vector<std::string>& Solidification::fields() {
  static const std::vector<std::string> names{
      field::solidFraction, field::frozen,       field::restDensity,
      field::viscosity,     field::liquidusTime, field::criticalTime,
      field::coolingRate,   field::solidusTime,  field::criticalGradient};
  return names;
}

const std::vector<std::string>& Solidification::historyFields() {
  static const std::vector<std::string> names{field::liquidusTime, field::criticalTime,
                                              field::coolingRate, field::solidusTime,
                                              field::criticalGradient};
  return names;
}

double criticalTemperature(const FreezingRange& range, double fraction) {
  return range.solidus + fraction * (range.liquidus - range.solidus);
}

Real solidFraction(const Material& material, Real temperature) {
  const FreezingRange& range = material.requireFreezingRange("the solid fraction");
  const InternalEnergyTable& u = material.requireInternalEnergy("the solid fraction");
  const Real liquidus = u.energy(static_cast<Real>(range.liquidus));
  const Real solidus = u.energy(static_cast<Real>(range.solidus));
  return std::clamp((liquidus - u.energy(temperature)) / (liquidus - solidus), Real(0), Real(1));
}

void Solidification::update(double time, double heatDeltaT) {
  const auto& temperature = metal_.scalarField(field::T);
  // du/dt of the last heat step (none without a heat model: a crossing is then placed at `time`)
  const ParticleCloud::ScalarField* energyRate =
      metal_.hasScalarField(field::energyRate) ? &metal_.scalarField(field::energyRate) : nullptr;
  const InternalEnergyTable& internalEnergy = *material_.internalEnergy;
  auto& liquidusTime = metal_.scalarField(field::liquidusTime);
  auto& criticalTime = metal_.scalarField(field::criticalTime);
  auto& coolingRate = metal_.scalarField(field::coolingRate);
  auto& solidusTime = metal_.scalarField(field::solidusTime);
  auto& criticalGradient = metal_.scalarField(field::criticalGradient);
  // when u(t) = u_end + rate (t - time) reached `level`, within the step
  const auto crossing = [&](std::size_t i, Real energy, Real level) {
    const double rate = energyRate ? static_cast<double>((*energyRate)[i]) : 0.0;
    const double back = rate < 0 ? static_cast<double>(level - energy) / rate : 0.0;
    return static_cast<Real>(time + std::clamp(back, -heatDeltaT, 0.0));
  };
  auto& fraction = metal_.scalarField(field::solidFraction);
  auto& frozen = metal_.scalarField(field::frozen);
  auto& restDensity = metal_.scalarField(field::restDensity);
  auto& viscosity = metal_.scalarField(field::viscosity);
  const TemperatureTable& density = *material_.density;
  const TemperatureTable& mu = *material_.viscosity;
  const Real limit =
      settings_.viscosityLimit > 0 ? settings_.viscosityLimit : std::numeric_limits<Real>::max();
  const auto count = static_cast<std::ptrdiff_t>(metal_.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t n = 0; n < count; ++n) {
    const auto i = static_cast<std::size_t>(n);
    const double T = static_cast<double>(temperature[i]);
    const Real energy = internalEnergy.energy(temperature[i]);
    fraction[i] = std::clamp((liquidusEnergy_ - energy) / freezingRangeEnergy_, Real(0), Real(1));
    const bool isFrozen = fraction[i] >= settings_.frozenSolidFraction;
    // a frozen particle keeps the rho_s it froze with (its contraction moves nothing)
    if (!isFrozen || frozen[i] == 0) restDensity[i] = static_cast<Real>(density(T));
    frozen[i] = isFrozen ? Real(1) : Real(0);
    if (!rheologyWritesViscosity_) viscosity[i] = std::min(static_cast<Real>(mu(T)), limit);
    // the history
    if (energy > liquidusEnergy_) {
      liquidusTime[i] = criticalTime[i] = coolingRate[i] = solidusTime[i] = Real(-1);
      criticalGradient[i] = Real(-1);
      continue;
    }
    if (liquidusTime[i] < 0) liquidusTime[i] = crossing(i, energy, liquidusEnergy_);
    if (energy <= criticalEnergy_ && criticalTime[i] < 0) {
      criticalTime[i] = crossing(i, energy, criticalEnergy_);
      const Real rate = energyRate ? (*energyRate)[i] : Real(0);
      coolingRate[i] = std::max(Real(0), -rate / criticalSpecificHeat_);
    }
    if (energy <= solidusEnergy_ && solidusTime[i] < 0) {
      solidusTime[i] = crossing(i, energy, solidusEnergy_);
    }
  }
}

std::vector<std::size_t> Solidification::pendingCriticalGradients() const {
  const auto& criticalTime = metal_.scalarField(field::criticalTime);
  const auto& criticalGradient = metal_.scalarField(field::criticalGradient);
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < metal_.size(); ++i) {
    if (criticalTime[i] >= 0 && criticalGradient[i] < 0) pending.push_back(i);
  }
  return pending;
}

SolidificationSummary Solidification::summary(const Communicator& comm) const {
  SolidificationSummary s;
  const auto& temperature = metal_.scalarField(field::T);
  const auto& fraction = metal_.scalarField(field::solidFraction);
  const auto& frozen = metal_.scalarField(field::frozen);
  const auto& mass = metal_.scalarField(field::mass);
  const Real limit = settings_.viscosityLimit;
  double totalMass = 0, solidMass = 0;
  s.particles = metal_.ownedSize();
  for (std::size_t i = 0; i < metal_.ownedSize(); ++i) {
    if (fraction[i] == 0) ++s.liquid;
    if (fraction[i] == 1) ++s.solid;
    if (frozen[i] != 0) ++s.frozen;
    if (limit > 0 && (*material_.viscosity)(static_cast<double>(temperature[i])) > limit &&
        frozen[i] == 0) {
      ++s.viscosityCapped;
    }
    totalMass += static_cast<double>(mass[i]);
    solidMass += static_cast<double>(mass[i] * fraction[i]);
  }
  if (comm.size() > 1) {
    std::vector<std::int64_t> counts{
        static_cast<std::int64_t>(s.particles), static_cast<std::int64_t>(s.liquid),
        static_cast<std::int64_t>(s.solid), static_cast<std::int64_t>(s.frozen),
        static_cast<std::int64_t>(s.viscosityCapped)};
    std::vector<double> masses{totalMass, solidMass};
    comm.sum(counts);
    comm.sum(masses);
    s.particles = static_cast<std::size_t>(counts[0]);
    s.liquid = static_cast<std::size_t>(counts[1]);
    s.solid = static_cast<std::size_t>(counts[2]);
    s.frozen = static_cast<std::size_t>(counts[3]);
    s.viscosityCapped = static_cast<std::size_t>(counts[4]);
    totalMass = masses[0];
    solidMass = masses[1];
  }
  s.solidFraction = totalMass > 0 ? solidMass / totalMass : 0;
  return s;
}

bool Solidification::allSolid(const Communicator& comm) const {
  const auto& fraction = metal_.scalarField(field::solidFraction);
  const auto owned = fraction.begin() + static_cast<std::ptrdiff_t>(metal_.ownedSize());
  return !comm.any(!std::all_of(fraction.begin(), owned, [](Real f) { return f == 1; }));
}

std::string Solidification::description() const {
  const FreezingRange& range = *material_.freezingRange;
  std::ostringstream text;
  text << "solidification of cloud " << metal_.name() << " (material " << material_.name
       << "): solid fraction from the heat released between liquidus " << range.liquidus
       << " K and solidus " << range.solidus << " K (latent and sensible " << freezingRangeEnergy_
       << " J/kg); frozen from f_s = " << settings_.frozenSolidFraction;
  if (settings_.viscosityLimit > 0) {
    text << "; viscosity capped at " << settings_.viscosityLimit
         << " Pa s below that (0.9 of the acoustic step's viscous limit)";
  }
  return text.str();
}

}  // namespace sphcast
