// The pouring inlets of constant/inlets in the time loop: their set-up and restart, the layers
// they emit after the drift, their buffers held after the kick, their state in uniform/.
#include <cmath>
#include <filesystem>
#include <ostream>
#include <sstream>

#include "core/Error.h"
#include "solver/CastingSolver.h"

namespace sphcast {

void CastingSolver::setUpInlets() {
  if (inletSetup_.inlets.empty()) return;  // the constructor refused inlets without a flow
  const InternalEnergyTable* energy = nullptr;
  if (fluid_->hasScalarField("u")) {
    energy =
        &description_.heatCloudMaterial(fluid_->name()).requireInternalEnergy("a pouring inlet");
  }
  std::vector<std::string> unset{FillTime::field};
  if (solidification_) {
    for (const std::string& name : Solidification::historyFields()) unset.push_back(name);
  }
  const auto stateFile = caseFolder_.root() / time_.startTimeName() / "uniform" / "inlets";
  std::optional<Dictionary> state;
  if (std::filesystem::exists(stateFile)) state = Dictionary::read(stateFile);
  const FlowSettings& flow = flowSetup_.settings;
  for (const PouringInletSettings& settings : inletSetup_.inlets) {
    const bool constantProperties =
        flowSetup_.restDensity->isConstant() && flowSetup_.viscosity->isConstant();
    if (settings.temperature == 0 && (fluid_->hasScalarField("T") || !constantProperties)) {
      throw DictionaryError(inletSetup_.declaredAt.at(settings.name),
                            "inlet '" + settings.name + "' needs the temperature T of its metal (" +
                                (fluid_->hasScalarField("T") ? "the fluid carries T"
                                                             : "the fluid's rho_s or mu is a "
                                                               "table in T") +
                                ")");
    }
    auto inlet = std::make_unique<PouringInlet>(
        settings, static_cast<int>(inlets_.size()), *fluid_, flow.dimension, flow.supportRadius,
        *flowSetup_.restDensity, *flowSetup_.viscosity, energy, unset, comm_);
    if (state && state->found(settings.name)) inlet->readState(state->subDict(settings.name));
    const double dx = fluid_->attributes().at("spacing");
    const double lattice =
        static_cast<double>(inlet->particlesPerLayer()) * std::pow(dx, flow.dimension - 1);
    const double nominal = flow.dimension == 2
                               ? 2 * settings.radius
                               : std::acos(-1.0) * settings.radius * settings.radius;
    std::ostringstream line;
    line.precision(6);
    line << "Inlet " << settings.name << ": " << inlet->particlesPerLayer()
         << " particles a layer (lattice " << (flow.dimension == 2 ? "width " : "area ") << lattice
         << " against the disk's " << nominal << "), speed " << inlet->speed() << " m/s";
    if (settings.massRate) {
      line << " (from massRate; the lattice changes it by " << 100 * (nominal / lattice - 1)
           << " % from the disk's)";
    }
    line << ", mass rate " << inlet->massRate() << " kg/s";
    if (settings.temperature > 0) line << ", T " << settings.temperature << " K";
    line << ", from t = " << settings.startTime << " s";
    if (settings.endTime) line << " to " << *settings.endTime << " s";
    if (settings.totalMass || settings.totalVolume) line << ", until it has poured its mass";
    info() << line.str() << "\n    held at the inlet's velocity and rho_s within h of the disk\n";
    const double across = 2 * settings.radius / dx;
    if (across < 8) {
      // measured (tests/unit/inlets/PouringInletTest.cpp): 5 across compresses by 15 %
      warning("inlet '" + settings.name + "' is " + std::to_string(across) +
              " particle spacings across: a falling stream under 8 across necks and compresses "
              "on its axis (15 % measured at 5 across); widen it or refine the spacing");
    }
    inlets_.push_back(std::move(inlet));
  }
  holdInletBuffers();
}

// In a decomposed run a new layer joins rank 0's own particles: every rank drops the fluid's
// halo first (they all find the same layers due), and the next search rebuilds it and sends
// the layer's particles to their ranks.
void CastingSolver::pour() {
  for (auto& inlet : inlets_) {
    const std::vector<Real> layers = inlet->layersDue(time_.value());
    if (layers.empty()) continue;
    if (decomposition_) decomposition_->dropHalo(*fluid_);
    inlet->appendLayers(layers);
  }
}

void CastingSolver::holdInletBuffers() {
  for (auto& inlet : inlets_) inlet->holdBuffer();
}

std::vector<UniformFile> CastingSolver::uniformStateFiles(const std::string& timeName) const {
  std::vector<UniformFile> files;
  if (!movingMolds_.empty()) {
    files.push_back({"dynamicBodies", movingMolds_.stateFileText(timeName)});
  }
  if (!inlets_.empty()) {
    std::vector<const PouringInlet*> inlets;
    for (const auto& inlet : inlets_) inlets.push_back(inlet.get());
    files.push_back({"inlets", inletStateFile(timeName, inlets)});
  }
  return files;
}

void CastingSolver::logInlets() {
  for (const auto& inlet : inlets_) {
    std::ostringstream line;
    line.precision(6);
    line << "Inlet " << inlet->settings().name << ": poured " << inlet->emittedMass() << " kg in "
         << inlet->emittedLayers() << " layers" << (inlet->finished(time_.value()) ? ", done" : "")
         << '\n';
    info() << line.str();
  }
}

}  // namespace sphcast
