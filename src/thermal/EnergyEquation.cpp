#include "thermal/EnergyEquation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "thermal/HeatTransferRegistration.h"

namespace sphcast {

namespace {

const char* const lossPaths[] = {"atmosphere", "radiation", "fixedTemperature"};

std::string lostKey(const std::string& path) { return "heatLost." + path; }
std::string rateKey(const std::string& path) { return "heatLossRate." + path; }

}  // namespace

EnergyEquation::EnergyEquation(HeatTransferContext context, const Dictionary& heatTransfer)
    : context_(std::move(context)) {
  if (context_.clouds.empty()) throw Error("heatTransfer: no heat cloud");
  restarted_ = true;
  for (HeatCloud& heat : context_.clouds) {
    for (const std::string& field : restartFields()) {
      restarted_ = restarted_ && heat.cloud->hasScalarField(field);
    }
  }
  for (HeatCloud& heat : context_.clouds) prepareFields(heat);
  paths_ = buildHeatTransferPaths(context_, heatTransfer, needsExposedArea_);
  if (heatTransfer.getChoiceOrDefault("exposedArea", {"gradient", "granularity"}, "gradient") ==
      "granularity") {
    exposedAreaForm_ = ExposedAreaForm::granularity;
  }
  if (paths_.empty()) {
    throw DictionaryError(heatTransfer.location(),
                          "heatTransfer in " + heatTransfer.name() +
                              " switches no heat path on (conduction, moldContact, atmosphere, "
                              "radiation)");
  }
}

EnergyEquation::~EnergyEquation() = default;

const std::vector<std::string>& EnergyEquation::restartFields() {
  static const std::vector<std::string> fields{"u", "energyRate"};
  return fields;
}

void EnergyEquation::prepareFields(HeatCloud& heat) {
  ParticleCloud& cloud = *heat.cloud;
  const Material& material = *heat.material;
  const InternalEnergyTable& energy = material.requireInternalEnergy("heatTransfer");
  if (heat.holdsAny()) {
    // which particles are held, and at what (0: free)
    std::vector<Real> held(cloud.size(), Real(0));
    if (heat.fixedTemperature) {
      for (Real& value : held) value = static_cast<Real>(heat.heldTemperature);
    } else {
      const auto& patch = cloud.idField(field::patch);  // throws, listing the cloud's fields
      for (std::size_t i = 0; i < held.size(); ++i) {
        for (const auto& [id, T] : heat.heldPatches) {
          if (patch[i] == id) held[i] = static_cast<Real>(T);
        }
      }
    }
    cloud.addScalarField(field::heldTemperature) = held;
    if (heat.fixedTemperature) cloud.addScalarField(field::T);
  }
  if (!cloud.hasScalarField(field::T)) {
    throw Error("heat cloud '" + cloud.name() +
                "' has no temperature field T: set it with setCastFields (fields { T ...; }, or "
                "setFields for a mold cloud), or hold the cloud with heatTransfer "
                "fixedTemperature");
  }
  if (heat.holdsAny()) {
    auto& T = cloud.scalarField(field::T);
    const auto& held = cloud.scalarField(field::heldTemperature);
    for (std::size_t i = 0; i < T.size(); ++i) {
      if (held[i] > 0) T[i] = held[i];
    }
  }
  const auto& T = cloud.scalarField(field::T);
  for (std::size_t i = 0; i < T.size(); ++i) {
    if (!(T[i] > 0) || !std::isfinite(T[i])) {
      throw Error("particle " + std::to_string(i) + " of heat cloud '" + cloud.name() +
                  "' has T = " + std::to_string(T[i]) + " K; temperatures are in kelvin, > 0");
    }
  }
  if (!cloud.hasScalarField(field::rho)) {
    const TemperatureTable& density = material.requireDensity("heatTransfer");
    const std::vector<Real> temperature = cloud.scalarField(field::T);  // adding fields may move it
    auto& rho = cloud.addScalarField(field::rho);
    for (std::size_t i = 0; i < rho.size(); ++i) {
      rho[i] = static_cast<Real>(density(static_cast<double>(temperature[i])));
    }
  }
  if (!cloud.hasScalarField(field::mass)) {
    const std::vector<Real> volume = cloud.scalarField(field::volume);  // throws, listing fields
    const std::vector<Real> rho = cloud.scalarField(field::rho);
    auto& mass = cloud.addScalarField(field::mass);
    for (std::size_t i = 0; i < mass.size(); ++i) mass[i] = rho[i] * volume[i];
  }
  if (!restarted_) {
    const std::vector<Real> temperature = cloud.scalarField(field::T);
    auto& u = cloud.addScalarField(field::u);
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = energy.energy(temperature[i]);
    cloud.addScalarField(field::energyRate);
    for (const char* path : lossPaths) {
      cloud.attributes()[lostKey(path)] = 0;
      cloud.attributes()[rateKey(path)] = 0;
    }
    const auto& mass = cloud.scalarField(field::mass);
    double total = 0;  // of every rank's own particles in a decomposed run
    for (std::size_t i = 0; i < cloud.ownedSize(); ++i) total += double(mass[i]) * double(u[i]);
    cloud.attributes()["internalEnergyAtStart"] = context_.comm.sum(total);
  }
  cloud.addScalarField(field::conductivity);
}

std::vector<std::string> EnergyEquation::start() {
  std::vector<std::string> lines;
  for (auto& path : paths_) {
    std::string line = path->start();
    if (!line.empty()) lines.push_back(std::move(line));
  }
  updateTemperatures();
  if (!restarted_) computeRates();
  return lines;
}

void EnergyEquation::halfKick(double deltaT) {
  kickEnergy(deltaT);
  updateTemperatures();
}

void EnergyEquation::kickEnergy(double deltaT) {
  const Real halfDt = static_cast<Real>(0.5 * deltaT);
  for (HeatCloud& heat : context_.clouds) {
    if (heat.fixedTemperature) continue;
    auto& u = heat.cloud->scalarField(field::u);
    const auto& rate = heat.cloud->scalarField(field::energyRate);
    const Real* held = heldTemperatures(heat);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < u.size(); ++i) {
      if (!held || held[i] == 0) u[i] += halfDt * rate[i];
    }
    // a decomposed run's halo kicked with its own, incomplete rates: its owners' u instead
    if (context_.neighbourhood) context_.neighbourhood->syncHalo(*heat.cloud, {"u"});
  }
  accountLosses(0.5 * deltaT);
}

void EnergyEquation::accountLosses(double duration) {
  for (HeatCloud& heat : context_.clouds) {
    auto& attributes = heat.cloud->attributes();
    for (const char* path : lossPaths)
      attributes[lostKey(path)] += duration * attributes[rateKey(path)];
  }
}

void EnergyEquation::computeRates() {
  for (HeatCloud& heat : context_.clouds) {
    auto& rate = heat.cloud->scalarField(field::energyRate);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < rate.size(); ++i) rate[i] = 0;
  }
  for (auto& path : paths_) path->addEnergyRates();
  for (HeatCloud& heat : context_.clouds) {
    for (const char* name : lossPaths) heat.cloud->attributes()[rateKey(name)] = 0;
  }
  for (auto& path : paths_) {
    std::vector<double> power = path->powerLeaving();
    context_.comm.sum(power);  // every rank's particles
    for (std::size_t c = 0; c < power.size(); ++c) {
      context_.clouds[c].cloud->attributes()[rateKey(path->name())] = power[c];
    }
  }
  // The heat the held particles take in left the system through them (summed in particle
  // order: the same bits on any thread count).
  // (decided by the settings, not by the field's storage, which a rank that has held none of
  // the cloud's particles lacks: every rank must take part in the sum)
  for (HeatCloud& heat : context_.clouds) {
    if (!heat.holdsAny()) continue;
    const Real* held = heldTemperatures(heat);
    const auto& mass = heat.cloud->scalarField(field::mass);
    const auto& rate = heat.cloud->scalarField(field::energyRate);
    double absorbed = 0;
    for (std::size_t i = 0; i < heat.cloud->ownedSize(); ++i) {
      if (held[i] > 0) absorbed += double(mass[i]) * double(rate[i]);
    }
    heat.cloud->attributes()[rateKey("fixedTemperature")] = context_.comm.sum(absorbed);
  }
}

void EnergyEquation::updateTemperatures() {
  for (HeatCloud& heat : context_.clouds) {
    ParticleCloud& cloud = *heat.cloud;
    const Material& material = *heat.material;
    auto& T = cloud.scalarField(field::T);
    auto& kappa = cloud.scalarField(field::conductivity);
    const auto& u = cloud.scalarField(field::u);
    const InternalEnergyTable& energy = *material.internalEnergy;
    const TemperatureTable* conductivity =
        material.conductivity ? &*material.conductivity : nullptr;
    const Real* held = heldTemperatures(heat);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < T.size(); ++i) {
      if (!held || held[i] == 0) T[i] = energy.temperature(u[i]);
      kappa[i] =
          conductivity ? static_cast<Real>((*conductivity)(static_cast<double>(T[i]))) : Real(0);
    }
  }
}

double EnergyEquation::stableDeltaT(std::string& limiter) const {
  std::vector<double> limits;
  for (const auto& path : paths_) limits.push_back(path->stableDeltaT());
  context_.comm.min(limits);  // the surface losses' depend on each rank's particles
  double shortest = std::numeric_limits<double>::infinity();
  limiter = "heat";
  for (std::size_t p = 0; p < paths_.size(); ++p) {
    if (limits[p] < shortest) {
      shortest = limits[p];
      limiter = std::string("heat ") + paths_[p]->name();
    }
  }
  return shortest;
}

bool EnergyEquation::readsExposedAreaOf(std::size_t c) const {
  return std::any_of(paths_.begin(), paths_.end(),
                     [c](const auto& path) { return path->readsExposedAreaOf(c); });
}

std::vector<std::string> EnergyEquation::descriptions() const {
  std::vector<std::string> lines;
  for (const auto& path : paths_) lines.push_back(path->description());
  return lines;
}

}  // namespace sphcast
