#include "inlets/PouringInlet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <Eigen/Geometry>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "particles/FieldNames.h"

namespace sphcast {

PouringInlet::PouringInlet(PouringInletSettings settings, int number, ParticleCloud& fluid,
                           int dimension, Real supportRadius, const TemperatureTable& density,
                           const TemperatureTable& viscosity, const InternalEnergyTable* energy,
                           std::vector<std::string> unsetFields, const Communicator& comm)
    : comm_(comm),
      settings_(std::move(settings)),
      mark_(static_cast<Real>(number + 1)),
      fluid_(fluid),
      dimension_(dimension),
      bufferLength_(supportRadius),
      unsetFields_(std::move(unsetFields)) {
  const auto spacing = fluid_.attributes().find("spacing");
  if (spacing == fluid_.attributes().end() || !(spacing->second > 0)) {
    throw Error("inlet '" + settings_.name + "': cloud '" + fluid_.name() +
                "' has no positive 'spacing' attribute (setCastFields writes it)");
  }
  spacing_ = static_cast<Real>(spacing->second);
  const double T = settings_.temperature;
  restDensity_ = static_cast<Real>(density(T));
  viscosity_ = static_cast<Real>(viscosity(T));
  if (energy) energy_ = energy->energy(static_cast<Real>(T));
  particleMass_ = static_cast<double>(restDensity_) * std::pow(spacing_, dimension_);
  if (settings_.totalVolume) settings_.totalMass = *settings_.totalVolume * restDensity_;
  // the disk's lattice: points i dx t1 + j dx t2 within the radius (2D: j = 0, t1 in the plane)
  const Vector& n = settings_.direction;
  Vector t1 = dimension_ == 2
                  ? Vector(-n.y(), n.x(), 0)
                  : Vector(n.cross(std::abs(n.x()) < 0.9 ? Vector::UnitX() : Vector::UnitY()));
  t1.normalize();
  const Vector t2 = n.cross(t1);
  const int reach = static_cast<int>(std::ceil(settings_.radius / spacing_)) + 1;
  const int rows = dimension_ == 2 ? 0 : reach;
  // centred on the disk with an even or odd count alike: offsets (k + 1/2) dx when the
  // diameter holds an even number of spacings, k dx otherwise
  const double across = 2 * settings_.radius / spacing_;
  const Real shift = std::lround(across) % 2 == 0 ? Real(0.5) : Real(0);
  for (int j = -rows; j <= rows; ++j) {
    for (int i = -reach; i <= reach; ++i) {
      const Real a = (i + shift) * spacing_;
      const Real b = dimension_ == 2 ? Real(0) : (j + shift) * spacing_;
      if (a * a + b * b < settings_.radius * settings_.radius) layer_.push_back(a * t1 + b * t2);
    }
  }
  if (layer_.empty()) {
    throw Error("inlet '" + settings_.name + "': its radius " + std::to_string(settings_.radius) +
                " m holds no point of the particle lattice (dx = " + std::to_string(spacing_) +
                " m): make it at least half a spacing");
  }
  speed_ = settings_.massRate ? *settings_.massRate * spacing_ /
                                    (static_cast<double>(layer_.size()) * particleMass_)
                              : settings_.speed;
  if (fluid_.hasIdField(field::id)) {
    const auto& id = fluid_.idField(field::id);
    for (std::size_t i = 0; i < fluid_.ownedSize(); ++i) nextId_ = std::max(nextId_, id[i] + 1);
    // every rank's (exact as a double below 2^53)
    nextId_ = static_cast<std::int64_t>(comm_.max(static_cast<double>(nextId_)));
  }
  fluid_.addScalarField(field::inlet);
  fluid_.attributes().try_emplace("inflowEnergy", 0.0);
}

double PouringInlet::massRate() const {
  return static_cast<double>(layer_.size()) * particleMass_ * speed_ / spacing_;
}

bool PouringInlet::finished(double time) const { return finishedWith(time, emittedMass_); }

bool PouringInlet::finishedWith(double time, double emittedMass) const {
  if (settings_.endTime && time > *settings_.endTime) return true;
  const double layerMass = static_cast<double>(layer_.size()) * particleMass_;
  return settings_.totalMass && emittedMass + 0.5 * layerMass > *settings_.totalMass;
}

bool PouringInlet::lastLayerDistance(Real& distance) const {
  const auto& mark = fluid_.scalarField(field::inlet);
  const auto& x = fluid_.positions();
  bool found = false;
  distance = std::numeric_limits<Real>::max();
  for (std::size_t i = 0; i < fluid_.ownedSize(); ++i) {
    if (mark[i] != mark_) continue;
    distance = std::min(distance, (x[i] - settings_.centre).dot(settings_.direction));
    found = true;
  }
  if (comm_.size() == 1) return found;
  distance = static_cast<Real>(comm_.min(static_cast<double>(distance)));
  return comm_.any(found);
}

void PouringInlet::appendLayer(Real distance) {
  const double layerMass = static_cast<double>(layer_.size()) * particleMass_;
  emittedMass_ += layerMass;
  fluid_.attributes()["inflowEnergy"] += layerMass * static_cast<double>(energy_);
  ++layers_;
  if (!comm_.master()) {  // rank 0's particles; the next search sends them to their ranks
    nextId_ += static_cast<std::int64_t>(layer_.size());
    return;
  }
  const std::size_t first = fluid_.size();
  fluid_.resize(first + layer_.size());
  const Vector velocity = static_cast<Real>(speed_) * settings_.direction;
  const Vector offset = settings_.centre + distance * settings_.direction;
  auto& x = fluid_.positions();
  for (std::size_t k = 0; k < layer_.size(); ++k) x[first + k] = offset + layer_[k];
  auto setScalar = [&](const char* name, Real value) {
    if (!fluid_.hasScalarField(name)) return;
    auto& field = fluid_.scalarField(name);
    std::fill(field.begin() + static_cast<std::ptrdiff_t>(first), field.end(), value);
  };
  for (const std::string& name : unsetFields_) setScalar(name.c_str(), Real(-1));
  setScalar(field::rho, restDensity_);
  setScalar(field::restDensity, restDensity_);
  setScalar(field::mass, static_cast<Real>(particleMass_));
  setScalar(field::volume, static_cast<Real>(std::pow(spacing_, dimension_)));  // as setCastFields
  setScalar(field::viscosity, viscosity_);
  if (settings_.temperature > 0) setScalar(field::T, static_cast<Real>(settings_.temperature));
  setScalar(field::u, energy_);
  setScalar(field::inlet, mark_);
  auto& U = fluid_.vectorField(field::U);
  std::fill(U.begin() + static_cast<std::ptrdiff_t>(first), U.end(), velocity);
  if (fluid_.hasIdField(field::id)) {
    auto& id = fluid_.idField(field::id);
    for (std::size_t i = first; i < id.size(); ++i) id[i] = nextId_++;
  } else {
    nextId_ += static_cast<std::int64_t>(layer_.size());
  }
}

std::vector<Real> PouringInlet::layersDue(double time) const {
  std::vector<Real> distances;
  if (time < settings_.startTime) return distances;
  Real distance = 0;
  if (!lastLayerDistance(distance)) {
    if (!finished(time)) distances.push_back(0);  // the stream's first layer, on the disk
    return distances;
  }
  // each layer's mass counts towards the total, as appendLayer will add it
  const double layerMass = static_cast<double>(layer_.size()) * particleMass_;
  double emitted = emittedMass_;
  while (distance >= spacing_ && !finishedWith(time, emitted)) {
    distance -= spacing_;
    distances.push_back(distance);
    emitted += layerMass;
  }
  return distances;
}

std::size_t PouringInlet::appendLayers(const std::vector<Real>& distances) {
  const std::size_t before = fluid_.size();
  for (const Real distance : distances) appendLayer(distance);
  return fluid_.size() - before;
}

std::size_t PouringInlet::emit(double time) { return appendLayers(layersDue(time)); }

void PouringInlet::holdBuffer() {
  auto& mark = fluid_.scalarField(field::inlet);
  const auto& x = fluid_.positions();
  auto& U = fluid_.vectorField(field::U);
  auto& rho = fluid_.scalarField(field::rho);
  const auto& restDensity = fluid_.scalarField(field::restDensity);
  auto* acceleration = fluid_.hasVectorField(field::acceleration)
                           ? &fluid_.vectorField(field::acceleration)
                           : nullptr;
  auto* densityRate =
      fluid_.hasScalarField(field::densityRate) ? &fluid_.scalarField(field::densityRate) : nullptr;
  const Vector velocity = static_cast<Real>(speed_) * settings_.direction;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (mark[i] != mark_) continue;
    if ((x[i] - settings_.centre).dot(settings_.direction) >= bufferLength_) {
      mark[i] = 0;  // released into the stream
      continue;
    }
    U[i] = velocity;
    rho[i] = restDensity[i];
    if (acceleration) (*acceleration)[i].setZero();
    if (densityRate) (*densityRate)[i] = 0;
  }
}

std::string PouringInlet::stateDictionary() const {
  char text[256];
  std::snprintf(text, sizeof text,
                "%s\n{\n    emittedMass     %.17g;\n    emittedLayers   %ld;\n"
                "    nextId          %lld;\n}\n",
                settings_.name.c_str(), emittedMass_, layers_, static_cast<long long>(nextId_));
  return text;
}

void PouringInlet::readState(const Dictionary& state) {
  emittedMass_ = state.get<double>("emittedMass");
  layers_ = state.get<long>("emittedLayers");
  nextId_ = state.get<std::int64_t>("nextId");
}

}  // namespace sphcast
