#include "materials/Material.h"

#include <sstream>

namespace sphcast {

namespace {

const Dimensions densityDimensions{{1, -3, 0, 0, 0, 0, 0}};
const Dimensions dynamicViscosityDimensions{{1, -1, -1, 0, 0, 0, 0}};
const Dimensions conductivityDimensions{{1, 1, -3, -1, 0, 0, 0}};
const Dimensions specificEnergyDimensions{{0, 2, -2, 0, 0, 0, 0}};
const Dimensions specificHeatDimensions{{0, 2, -2, -1, 0, 0, 0}};
const Dimensions surfaceTensionDimensions{{1, 0, -2, 0, 0, 0, 0}};
const Dimensions dimensionless{{0, 0, 0, 0, 0, 0, 0}};
const Dimensions temperatureDimensions{{0, 0, 0, 1, 0, 0, 0}};

std::optional<TemperatureTable> readIfFound(const Dictionary& dict, const char* key,
                                            const Dimensions& dimensions,
                                            Interpolation interpolation, ValueRule rule,
                                            const TemperatureColumn* columns) {
  if (!dict.found(key)) return std::nullopt;
  return TemperatureTable::read(dict, key, dimensions, interpolation, rule, columns);
}

}  // namespace

const std::vector<std::string>& Material::validKeys() {
  static const std::vector<std::string> keys{"temperatures",   "density",        "viscosity",
                                             "conductivity",   "internalEnergy", "specificHeat",
                                             "surfaceTension", "emissivity",
                                             "liquidus",       "solidus",
                                             "dendriteArmSpacing"};
  return keys;
}

Material Material::read(const Dictionary& dict, const std::string& name, const std::string& file) {
  dict.checkKeys(validKeys());
  Material material;
  material.name = name;
  material.location = dict.location();
  material.file = file;

  std::optional<TemperatureColumn> columns;
  if (dict.found("temperatures")) columns = readTemperatureColumn(dict, "temperatures");
  const TemperatureColumn* rows = columns ? &*columns : nullptr;

  material.density = readIfFound(dict, "density", densityDimensions, Interpolation::linear,
                                 ValueRule::positive, rows);
  material.viscosity = readIfFound(dict, "viscosity", dynamicViscosityDimensions,
                                   Interpolation::logLinear, ValueRule::positive, rows);
  material.conductivity = readIfFound(dict, "conductivity", conductivityDimensions,
                                      Interpolation::linear, ValueRule::positive, rows);
  material.surfaceTension = readIfFound(dict, "surfaceTension", surfaceTensionDimensions,
                                        Interpolation::linear, ValueRule::nonNegative, rows);

  if (dict.found("internalEnergy") && dict.found("specificHeat")) {
    throw DictionaryError(dict.location("specificHeat"),
                          "material '" + name + "' in " + file +
                              " gives both 'internalEnergy' (line " +
                              std::to_string(dict.location("internalEnergy").line) +
                              ") and 'specificHeat'; give one: u(T) is either tabulated or "
                              "the integral of cp(T)");
  }
  if (dict.found("internalEnergy")) {
    material.internalEnergy = InternalEnergyTable::fromInternalEnergy(
        readPropertyEntry(dict, "internalEnergy", specificEnergyDimensions, rows));
  } else if (dict.found("specificHeat")) {
    material.internalEnergy = InternalEnergyTable::fromSpecificHeat(
        readPropertyEntry(dict, "specificHeat", specificHeatDimensions, rows));
  }

  if (dict.found("emissivity")) {
    const auto emissivity = dict.get<double>("emissivity", dimensionless);
    if (!(emissivity >= 0.0 && emissivity <= 1.0)) {
      std::ostringstream message;
      message << "'emissivity' is " << emissivity << " in " << dict.name()
              << "; it must lie in [0, 1]";
      throw DictionaryError(dict.location("emissivity"), message.str());
    }
    material.emissivity = emissivity;
  }

  if (dict.found("liquidus") || dict.found("solidus")) {
    const char* absent = dict.found("liquidus") ? "solidus" : "liquidus";
    const char* given = dict.found("liquidus") ? "liquidus" : "solidus";
    if (!dict.found(absent)) {
      throw DictionaryError(dict.location(given), "material '" + name + "' in " + file +
                                                      " gives '" + given + "' but not '" +
                                                      absent + "'; give both (K)");
    }
    const auto liquidus = dict.get<double>("liquidus", temperatureDimensions);
    const auto solidus = dict.get<double>("solidus", temperatureDimensions);
    if (!(solidus > 0 && solidus < liquidus)) {
      std::ostringstream message;
      message << "'solidus' " << solidus << " K of material '" << name << "' in " << file
              << " must be positive and below its 'liquidus' " << liquidus << " K";
      throw DictionaryError(dict.location("solidus"), message.str());
    }
    material.freezingRange = FreezingRange{solidus, liquidus, dict.location("liquidus")};
  }
  if (dict.found("dendriteArmSpacing")) {
    const auto spacing = dict.get<std::vector<double>>("dendriteArmSpacing");
    if (spacing.size() != 2 || !(spacing[0] > 0) || !(spacing[1] > 0 && spacing[1] <= 1)) {
      throw DictionaryError(dict.location("dendriteArmSpacing"),
                            "'dendriteArmSpacing' of material '" + name + "' in " + file +
                                " must be (A n): lambda_2 = A t_f^n with A > 0 (m s^-n) and n "
                                "in (0, 1], e.g. (1.0e-5 0.333)");
    }
    material.dendriteArmSpacing = DendriteArmSpacing{spacing[0], spacing[1]};
  }
  return material;
}

void Material::missing(std::string_view key, std::string_view neededBy) const {
  throw DictionaryError(location, "material '" + name + "' in " + file + " has no '" +
                                      std::string(key) + "', which " + std::string(neededBy) +
                                      " needs");
}

const TemperatureTable& Material::requireDensity(std::string_view neededBy) const {
  if (!density) missing("density", neededBy);
  return *density;
}

const TemperatureTable& Material::requireViscosity(std::string_view neededBy) const {
  if (!viscosity) missing("viscosity", neededBy);
  return *viscosity;
}

const TemperatureTable& Material::requireConductivity(std::string_view neededBy) const {
  if (!conductivity) missing("conductivity", neededBy);
  return *conductivity;
}

const TemperatureTable& Material::requireSurfaceTension(std::string_view neededBy) const {
  if (!surfaceTension) missing("surfaceTension", neededBy);
  return *surfaceTension;
}

const InternalEnergyTable& Material::requireInternalEnergy(std::string_view neededBy) const {
  if (!internalEnergy) missing("internalEnergy' or 'specificHeat", neededBy);
  return *internalEnergy;
}

double Material::requireEmissivity(std::string_view neededBy) const {
  if (!emissivity) missing("emissivity", neededBy);
  return *emissivity;
}

const FreezingRange& Material::requireFreezingRange(std::string_view neededBy) const {
  if (!freezingRange) missing("liquidus' and 'solidus", neededBy);
  return *freezingRange;
}

}  // namespace sphcast
