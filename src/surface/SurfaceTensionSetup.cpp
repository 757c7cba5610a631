#include "surface/SurfaceTensionSetup.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"

namespace sphcast {

namespace {
const Dimensions dimensionless{{0, 0, 0, 0, 0, 0, 0}};
const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};
const Dimensions tension{{1, 0, -2, 0, 0, 0, 0}};

// With Gamma_s < 0 the energy (8) of a particle at the wall falls as its neighbours move away
// (its exposed area grows), so the particles on a wetting wall spread apart: a 2D drop on a
// 60-degree wall threw particles off, then went non-finite (doc/validation.md §2).
std::string wettingUnsupported(const std::string& dictName) {
  return "a wetting wall (contactAngle below 90 degrees, solidTension below 0) is not "
         "supported in " +
         dictName +
         ": with Gamma_s < 0 the surface energy falls as the "
         "particles at the wall move apart, and they do (doc/physics.md section 10.1)";
}
}  // namespace

SurfaceTensionSetup readSurfaceTensionSetup(const CaseDescription& description) {
  SurfaceTensionSetup setup;
  const Dictionary* entry = description.modelsEntry("surfaceTension");
  if (!entry) return setup;
  const Dictionary& models = description.physicsModels();
  const Dictionary& dict = *entry;
  setup.model = dict.found("model") ? surfaceTensionModels().choose(dict, "model", {"none"})
                                    : surfaceTensionModels().names().front();
  const bool energy = setup.model == "surfaceEnergy";
  // each model's keys: a key of the other model is a mistake, not something to ignore (with
  // none, any model's key may wait there)
  if (energy) {
    dict.checkKeys(
        {"model", "energyFactor", "contactAngle", "solidTension", "wallSmoothing", "coreRadius"});
  } else if (setup.model == "none") {
    dict.checkKeys({"model", "energyFactor", "contactAngle", "solidTension", "wallSmoothing",
                    "coreRadius", "gapMeniscus"});
  } else {
    dict.checkKeys({"model", "contactAngle", "gapMeniscus"});
  }
  if (setup.model == "none") return setup;
  if (!description.hasFlow()) {
    throw DictionaryError(
        dict.found("model") ? dict.location("model") : models.location("surfaceTension"),
        "surface tension acts on the flow's fluid, but " + models.name() +
            " has no flow (flow { model weaklyCompressible; ... })");
  }
  setup.enabled = true;
  SurfaceTensionSettings& settings = setup.settings;
  settings.dimension = description.dimension();
  settings.supportRadius = description.supportRadius();

  if (dict.found("energyFactor")) {
    const std::string mustBe =
        "'energyFactor' must be 'calibrated' or a positive number in " + dict.name();
    double value = 0;
    bool number = true;
    try {
      value = dict.get<double>("energyFactor");
    } catch (const DictionaryError&) {
      number = false;  // a word
    }
    if (!number && dict.get<std::string>("energyFactor") != "calibrated") {
      throw DictionaryError(dict.location("energyFactor"), mustBe);
    }
    if (number && !(value > 0)) throw DictionaryError(dict.location("energyFactor"), mustBe);
    if (number) settings.energyFactor = static_cast<Real>(value);
  }
  if (dict.found("contactAngle") && dict.found("solidTension")) {
    throw DictionaryError(dict.location("solidTension"),
                          "give 'contactAngle' or 'solidTension' in " + dict.name() +
                              ", not both (cos theta = -solidTension / Gamma_g)");
  }
  settings.gapMeniscus = dict.getChoiceOrDefault("gapMeniscus", {"on", "off"}, "off") == "on";
  if (dict.found("contactAngle")) {
    const double degrees = dict.get<double>("contactAngle", dimensionless);
    if (!(degrees >= 0 && degrees <= 180)) {
      throw DictionaryError(dict.location("contactAngle"),
                            "'contactAngle' must lie in [0, 180] degrees in " + dict.name());
    }
    if (energy && degrees < 90) {
      throw DictionaryError(dict.location("contactAngle"), wettingUnsupported(dict.name()));
    }
    settings.cosContactAngle = static_cast<Real>(std::cos(degrees * std::numbers::pi / 180));
  }
  if (dict.found("solidTension")) {
    settings.solidTension = dict.get<Real>("solidTension", tension);
    if (*settings.solidTension < 0) {
      throw DictionaryError(dict.location("solidTension"), wettingUnsupported(dict.name()));
    }
  }
  if (dict.found("wallSmoothing")) {
    settings.wallSmoothing = dict.get<Real>("wallSmoothing", length);
    if (!(settings.wallSmoothing > 0)) {
      throw DictionaryError(dict.location("wallSmoothing"),
                            "'wallSmoothing' must be positive in " + dict.name());
    }
  }
  if (dict.found("coreRadius")) {
    settings.coreRadius = dict.get<Real>("coreRadius", dimensionless);
    if (!(settings.coreRadius >= 0 && settings.coreRadius < 1.5)) {
      throw DictionaryError(
          dict.location("coreRadius"),
          "'coreRadius' (in particle spacings) must lie in [0, 1.5) in " + dict.name());
    }
  }

  const Material& fluid = description.fluidMaterial();
  settings.gasTension = fluid.requireSurfaceTension("the surface tension");
  return setup;
}

}  // namespace sphcast
