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
  if (models_.fluid->hasScalarField(field::u)) {
    energy = &description_.heatCloudMaterial(models_.fluid->name())
                  .requireInternalEnergy("a pouring inlet");
  }
  std::vector<std::string> unset{FillTime::field};
  if (models_.solidification) {
    for (const std::string& name : Solidification::historyFields()) unset.push_back(name);
  }
  const auto stateFile = caseFolder_.root() / time_.startTimeName() / "uniform" / "inlets";
  std::optional<Dictionary> state;
  if (std::filesystem::exists(stateFile)) state = Dictionary::read(stateFile);
  const FlowSettings& flow = flowSetup_.settings;
  models_.pouringInlets =
      PouringInlets(inletSetup_, *models_.fluid, flow.dimension, flow.supportRadius,
                    *flowSetup_.restDensity, *flowSetup_.viscosity, energy, unset, state, comm_);
}

std::vector<UniformFile> CastingSolver::uniformStateFiles(const std::string& timeName) const {
  std::vector<UniformFile> files;
  if (!models_.movingMolds.empty()) {
    files.push_back({"dynamicBodies", models_.movingMolds.stateFileText(timeName)});
  }
  if (!models_.pouringInlets.empty()) {
    files.push_back({"inlets", models_.pouringInlets.stateFileText(timeName)});
  }
  return files;
}

}  // namespace sphcast
