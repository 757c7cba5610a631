// The pouring inlets' set-up (their passes in the step: PouringInlets.h) and the uniform/ state
// files of the bodies and the inlets.
#include <filesystem>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "solver/CastingSolver.h"

namespace sphcast {

void CastingSolver::setUpInlets() {
  if (inletSetup_.inlets.empty()) return;  // the constructor refused inlets without a flow
  const InternalEnergyTable* energy = nullptr;
  if (fluid_->hasScalarField(field::u)) {
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
  pouringInlets_ =
      PouringInlets(inletSetup_, *fluid_, flow.dimension, flow.supportRadius,
                    *flowSetup_.restDensity, *flowSetup_.viscosity, energy, unset, state, comm_);
}

std::vector<UniformFile> CastingSolver::uniformStateFiles(const std::string& timeName) const {
  std::vector<UniformFile> files;
  if (!movingMolds_.empty()) {
    files.push_back({"dynamicBodies", movingMolds_.stateFileText(timeName)});
  }
  if (!pouringInlets_.empty()) {
    files.push_back({"inlets", pouringInlets_.stateFileText(timeName)});
  }
  return files;
}

}  // namespace sphcast
