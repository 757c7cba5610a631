#include "inlets/InletSetup.h"

#include <cmath>
#include <filesystem>

#include "core/Error.h"

namespace sphcast {

namespace {
const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};
const Dimensions velocity{{0, 1, -1, 0, 0, 0, 0}};
const Dimensions temperature{{0, 0, 0, 1, 0, 0, 0}};
const Dimensions time{{0, 0, 1, 0, 0, 0, 0}};

PouringInletSettings readInlet(const Dictionary& inlet, const std::string& name,
                               const std::string& fluidCloud, int dimension) {
  inlet.checkKeys({"centre", "direction", "radius", "speed", "massRate", "T", "mass", "volume",
                   "startTime", "endTime"});
  PouringInletSettings settings;
  settings.name = name;
  settings.cloud = fluidCloud;
  auto positive = [&](const char* key, const Dimensions* unit) {
    const double value = unit ? inlet.get<double>(key, *unit) : inlet.get<double>(key);
    if (!(value > 0) || !std::isfinite(value)) {
      throw DictionaryError(inlet.location(key),
                            std::string("'") + key + "' of inlet '" + name + "' must be positive");
    }
    return value;
  };
  settings.centre = inlet.get<Vector>("centre", length);
  const Vector direction = inlet.get<Vector>("direction");
  if (!direction.allFinite() || !(direction.norm() > 0)) {
    throw DictionaryError(inlet.location("direction"),
                          "'direction' of inlet '" + name + "' must be a non-zero vector");
  }
  settings.direction = direction.normalized();
  if (dimension == 2 && (settings.centre.z() != 0 || settings.direction.z() != 0)) {
    throw DictionaryError(inlet.location(), "inlet '" + name +
                                                "': the case is 2D, so its centre must lie on the "
                                                "plane z = 0 and its direction in it");
  }
  settings.radius = positive("radius", &length);
  if (inlet.found("speed") == inlet.found("massRate")) {
    throw DictionaryError(inlet.location(), "inlet '" + name +
                                                "' needs either 'speed' (m/s) or 'massRate' (kg/s; "
                                                "the speed then follows), not " +
                                                (inlet.found("speed") ? "both" : "neither"));
  }
  if (inlet.found("speed")) settings.speed = positive("speed", &velocity);
  if (inlet.found("massRate")) settings.massRate = positive("massRate", nullptr);
  if (inlet.found("T")) settings.temperature = positive("T", &temperature);
  if (inlet.found("mass") && inlet.found("volume")) {
    throw DictionaryError(inlet.location("volume"),
                          "inlet '" + name + "': give 'mass' or 'volume' to pour, not both");
  }
  if (inlet.found("mass")) settings.totalMass = positive("mass", nullptr);
  if (inlet.found("volume")) settings.totalVolume = positive("volume", nullptr);
  if (inlet.found("startTime")) settings.startTime = inlet.get<double>("startTime", time);
  if (inlet.found("endTime")) {
    settings.endTime = inlet.get<double>("endTime", time);
    if (!(*settings.endTime > settings.startTime)) {
      throw DictionaryError(inlet.location("endTime"),
                            "'endTime' of inlet '" + name + "' must be after its startTime");
    }
  }
  return settings;
}
}  // namespace

InletSetup readInletSetup(const CaseDescription& description) {
  InletSetup setup;
  const auto file = description.folder().constantFile("inlets");
  if (!std::filesystem::exists(file)) return setup;
  const Dictionary inlets = Dictionary::read(file);
  for (const std::string& name : inlets.keys()) {
    if (!inlets.isDict(name)) {
      throw DictionaryError(inlets.location(name),
                            "'" + name + "' in " + inlets.name() +
                                " is not an inlet: each inlet is a sub-dictionary { centre ...; }");
    }
    setup.inlets.push_back(
        readInlet(inlets.subDict(name), name, description.fluidCloud(), description.dimension()));
    setup.declaredAt[name] = inlets.subDict(name).location();
  }
  return setup;
}

std::string inletStateFile(const std::string& timeName,
                           const std::vector<const PouringInlet*>& inlets) {
  std::string text = foamFileHeader(timeName + "/uniform", "inlets") + "\n";
  for (const PouringInlet* inlet : inlets) text += inlet->stateDictionary() + '\n';
  return text;
}

}  // namespace sphcast
