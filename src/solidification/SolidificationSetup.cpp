#include "solidification/SolidificationSetup.h"

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"

namespace sphcast {

namespace {
const Dimensions dimensionless{{0, 0, 0, 0, 0, 0, 0}};
const Dimensions pressure{{1, -1, -2, 0, 0, 0, 0}};
const Dimensions speed{{0, 1, -1, 0, 0, 0, 0}};
}  // namespace

SolidificationSetup readSolidificationSetup(const CaseDescription& description) {
  SolidificationSetup setup;
  const Dictionary* entry = description.modelsEntry("solidification");
  if (!entry) return setup;
  const Dictionary& models = description.physicsModels();
  const Dictionary& dict = *entry;
  dict.checkKeys(
      {"model", "cloud", "frozenSolidFraction", "cavitationPressure", "cooling", "endWhenSolid"});
  if (dict.getChoice("model", {"none", "frozenSolid"}) == "none") return setup;
  // the flow's fluid; without a flow, the cloud named (a casting that only conducts heat)
  if (description.hasFlow()) {
    setup.cloud = description.fluidCloud();
    if (dict.found("cloud") && dict.get<std::string>("cloud") != setup.cloud) {
      throw DictionaryError(dict.location("cloud"),
                            "solidification acts on the flow's fluid '" + setup.cloud + "', not '" +
                                dict.get<std::string>("cloud") + "', in " + dict.name());
    }
  } else {
    if (!dict.found("cloud")) {
      throw DictionaryError(dict.location("model"),
                            "solidification without a flow needs the 'cloud' that solidifies "
                            "in " +
                                dict.name() + " (with a flow it is the flow's fluid)");
    }
    setup.cloud = dict.get<std::string>("cloud");
    for (const char* key : {"cooling", "cavitationPressure"}) {
      if (dict.found(key)) {
        throw DictionaryError(dict.location(key), "'" + std::string(key) + "' in " + dict.name() +
                                                      " needs a flow: without one nothing moves");
      }
    }
  }
  const SourceLocation& cloudAt =
      dict.found("cloud") ? dict.location("cloud") : dict.location("model");
  if (!description.carriesHeat(setup.cloud)) {
    throw DictionaryError(cloudAt, "solidification follows the temperature of '" + setup.cloud +
                                       "', but heatTransfer's clouds in " + models.name() +
                                       " do not carry it");
  }
  setup.enabled = true;
  if (dict.found("frozenSolidFraction")) {
    const double fraction = dict.get<double>("frozenSolidFraction", dimensionless);
    if (!(fraction > 0 && fraction <= 1)) {
      throw DictionaryError(dict.location("frozenSolidFraction"),
                            "'frozenSolidFraction' must lie in (0, 1] in " + dict.name());
    }
    setup.settings.frozenSolidFraction = static_cast<Real>(fraction);
    setup.frozenSolidFractionAt = dict.location("frozenSolidFraction");
  }
  if (dict.found("cavitationPressure")) {
    setup.cavitationPressure = dict.get<Real>("cavitationPressure", pressure);
    // a gauge pressure the melt may fall to: a positive floor would push on the melt where
    // nothing pushes (a cavity's vapour is at about 0 gauge, a melt holds suction below it)
    if (!(setup.cavitationPressure <= 0)) {
      throw DictionaryError(dict.location("cavitationPressure"),
                            "'cavitationPressure' is the suction the melt holds (gauge, Pa): "
                            "it must be 0 or negative in " +
                                dict.name());
    }
  }
  setup.endWhenSolid = dict.getOrDefault<bool>("endWhenSolid", false);
  if (dict.found("cooling")) {
    const Dictionary& cooling = dict.subDict("cooling");
    cooling.checkKeys(
        {"flowStepsPerHeatStep", "maxCo", "stillSpeed", "stillFraction", "movingSpeed"});
    CoolingAcceleration acceleration;
    acceleration.flowStepsPerHeatStep =
        cooling.getOrDefault<int>("flowStepsPerHeatStep", acceleration.flowStepsPerHeatStep);
    if (acceleration.flowStepsPerHeatStep < 1) {
      throw DictionaryError(cooling.location("flowStepsPerHeatStep"),
                            "'flowStepsPerHeatStep' must be at least 1 in " + cooling.name());
    }
    if (cooling.found("maxCo")) {
      acceleration.maxCo = cooling.get<double>("maxCo", dimensionless);
      if (!(acceleration.maxCo > 0 && acceleration.maxCo <= 1)) {
        throw DictionaryError(cooling.location("maxCo"),
                              "'maxCo' must be in (0, 1] in " + cooling.name());
      }
    }
    if (cooling.found("stillSpeed")) {
      acceleration.stillSpeed = cooling.get<double>("stillSpeed", speed);
      if (!(acceleration.stillSpeed > 0)) {
        throw DictionaryError(cooling.location("stillSpeed"),
                              "'stillSpeed' must be positive in " + cooling.name());
      }
    }
    if (cooling.found("stillFraction")) {
      acceleration.stillFraction = cooling.get<double>("stillFraction");
      if (!(acceleration.stillFraction >= 0 && acceleration.stillFraction < 0.5)) {
        throw DictionaryError(cooling.location("stillFraction"),
                              "'stillFraction' must be in [0, 0.5) in " + cooling.name() +
                                  " (the share of the melt's particles allowed above "
                                  "stillSpeed; 0: every one below it)");
      }
    }
    if (cooling.found("movingSpeed")) {
      acceleration.movingSpeed = cooling.get<double>("movingSpeed", speed);
    }
    if (!(acceleration.movingSpeed > acceleration.stillSpeed)) {
      throw DictionaryError(cooling.found("movingSpeed") ? cooling.location("movingSpeed")
                                                         : cooling.location("stillSpeed"),
                            "'movingSpeed' must exceed 'stillSpeed' in " + cooling.name());
    }
    setup.cooling = acceleration;
  }
  const Material& material = description.heatCloudMaterial(setup.cloud);
  // the checks now, with the material's place in the message, not at the first step
  material.requireFreezingRange("solidification");
  material.requireInternalEnergy("solidification");
  material.requireDensity("solidification");
  material.requireViscosity("solidification");
  setup.material = material;
  return setup;
}

}  // namespace sphcast
