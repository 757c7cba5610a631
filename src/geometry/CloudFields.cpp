#include "geometry/CloudFields.h"

#include <algorithm>
#include <sstream>

#include "core/Error.h"
#include "core/Gravity.h"
#include "core/Log.h"
#include "geometry/InitialDensity.h"
#include "particles/FieldNames.h"
#include "particles/WallSurfaceDistance.h"

namespace sphcast {

namespace {

constexpr double defaultSupportRadius = 3.0;  // x spacing, without system/sphSchemes
const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};
const Dimensions temperatureDimensions{{0, 0, 0, 1, 0, 0, 0}};
const Dimensions densityDimensions{{1, -3, 0, 0, 0, 0, 0}};

// `rho` of a cloud's fields: a number, or how to compute it from the material.
struct DensityChoice {
  std::optional<double> value;
  std::string model;  // standard | hydrostatic, when no value
};

}  // namespace

namespace dictionary {

template <>
struct ValueTraits<DensityChoice> {
  static std::string description() { return "a density (kg/m^3), standard or hydrostatic"; }
  static DensityChoice read(ItemCursor& cursor) {
    const ValueItem& item = cursor.take(description());
    if (item.kind == ValueItem::Kind::Number) return {item.number, ""};
    if (item.kind == ValueItem::Kind::Word &&
        (item.text == "standard" || item.text == "hydrostatic")) {
      return {std::nullopt, item.text};
    }
    cursor.fail(item, description());
  }
};

}  // namespace dictionary

namespace {

// Runs `read`, which opens a file of the case: a file that cannot be opened (no line to point
// at) is reported at `at` with what needs it ("rho hydrostatic needs ...: cannot open ...").
template <class Read>
auto neededBy(const SourceLocation& at, const std::string& what, Read&& read) {
  try {
    return read();
  } catch (const DictionaryError& error) {
    if (error.where().line != 0) throw;
    throw DictionaryError(at, what + " needs it: " + error.what());
  }
}

}  // namespace

Vector CastCaseSettings::gravity() const {
  return description_.gravity() ? *description_.gravity() : readGravity(description_.folder());
}

std::optional<std::pair<std::string, SourceLocation>> CastCaseSettings::mappedMaterial(
    const std::string& cloud) const {
  const Dictionary* mapping = description_.modelsEntry("materials");
  if (!mapping || !mapping->found(cloud)) return std::nullopt;
  return std::make_pair(mapping->get<std::string>(cloud), mapping->location(cloud));
}

double CastCaseSettings::flowWallClearance() const {
  return description_.hasSchemes()
             ? schemes().getOrDefault<double>("wallClearance", wallClearanceInSpacings)
             : wallClearanceInSpacings;
}

double CastCaseSettings::soundSpeed() const { return description_.soundSpeed(); }

double CastCaseSettings::supportRadius(double spacing) const {
  if (description_.hasSchemes() && schemes().found("supportRadius")) {
    const double h = schemes().get<double>("supportRadius", length);
    if (!(h > spacing)) {
      throw DictionaryError(schemes().location("supportRadius"),
                            "'supportRadius' must exceed the fill spacing for the relaxation");
    }
    return h;
  }
  info() << "Relaxation: no supportRadius in system/sphSchemes; using " << defaultSupportRadius
         << " x spacing\n";
  return defaultSupportRadius * spacing;
}

void setFieldValues(const Dictionary& fields, ParticleCloud& cloud,
                    const std::vector<bool>& selected, bool densityModelsAllowed) {
  fields.checkKeys({"U", "T", "rho"});
  auto chosen = [&](std::size_t i) { return selected.empty() || selected[i]; };
  if (fields.found("U")) {
    const Vector velocity = fields.get<Vector>("U", Dimensions{{0, 1, -1, 0, 0, 0, 0}});
    auto& u = cloud.addVectorField(field::U);
    for (std::size_t i = 0; i < u.size(); ++i) {
      if (chosen(i)) u[i] = velocity;
    }
  }
  std::optional<double> density;
  if (fields.found("rho")) {
    const auto choice = fields.get<DensityChoice>("rho", densityDimensions);
    if (!choice.value && !densityModelsAllowed) {
      throw DictionaryError(fields.location("rho"),
                            "rho " + choice.model +
                                " is for the new clouds of 'clouds'; give a "
                                "density in kg/m^3 in " +
                                fields.name());
    }
    density = choice.value;
  }
  const std::pair<const char*, Dimensions> scalars[] = {{"T", temperatureDimensions},
                                                        {"rho", densityDimensions}};
  for (const auto& [fieldName, dimensions] : scalars) {
    if (!fields.found(fieldName)) continue;
    const bool isDensity = std::string(fieldName) == "rho";
    if (isDensity && !density) continue;
    const double value = isDensity ? *density : fields.get<double>(fieldName, dimensions);
    if (!(value > 0.0)) {
      throw DictionaryError(
          fields.location(fieldName),
          "'" + std::string(fieldName) + "' must be positive in " + fields.name());
    }
    auto& field = cloud.addScalarField(fieldName);
    for (std::size_t i = 0; i < field.size(); ++i) {
      if (chosen(i)) field[i] = static_cast<Real>(value);
    }
  }
}

std::optional<DensityStart> readDensityStart(const Dictionary& cloudDict,
                                             const std::string& cloudName,
                                             const CastCaseSettings& settings) {
  if (!cloudDict.found("fields")) return std::nullopt;
  const Dictionary& fields = cloudDict.subDict("fields");
  if (!fields.found("rho")) return std::nullopt;
  const auto choice = fields.get<DensityChoice>("rho", densityDimensions);
  if (choice.value) return std::nullopt;

  const std::string asked = "rho " + choice.model + " (of cloud '" + cloudName + "')";
  const MaterialLibrary& materials =
      neededBy(fields.location("rho"), asked,
               [&]() -> const MaterialLibrary& { return settings.materials(); });
  // the cloud's material: setCastFieldsDict's `material`, else physicsModels' `materials` map
  // (which the solver reads), else the cloud's name; the two files may not disagree
  const auto mapped = settings.mappedMaterial(cloudName);
  std::string materialName = cloudName;
  SourceLocation namedAt = fields.location("rho");
  if (cloudDict.found("material")) {
    materialName = cloudDict.get<std::string>("material");
    namedAt = cloudDict.location("material");
    if (mapped && mapped->first != materialName) {
      throw DictionaryError(namedAt, "cloud '" + cloudName + "' is of material '" + materialName +
                                         "' here, but of '" + mapped->first + "' in " +
                                         mapped->second.str() +
                                         " (the solver's): give the same material in both");
    }
  } else if (mapped) {
    materialName = mapped->first;
    namedAt = mapped->second;
  }
  if (!materials.has(materialName)) {
    std::string present;
    for (const auto& name : materials.names()) present += " " + name;
    throw DictionaryError(namedAt, "rho " + choice.model + " needs the material '" + materialName +
                                       "' in " + materials.file() + ", which has (" + present +
                                       " )");
  }
  const TemperatureTable& restDensity =
      materials.get(materialName, namedAt, "material").requireDensity("rho " + choice.model);
  double temperature = 0.0;
  if (!restDensity.isConstant()) {
    if (!fields.found("T")) {
      throw DictionaryError(fields.location("rho"),
                            "rho " + choice.model + " with the table " + restDensity.description() +
                                " needs the initial temperature 'T' in " + fields.name());
    }
    temperature = fields.get<double>("T", temperatureDimensions);
    restDensity.checkCovers(temperature, fields.location("T"));
  }
  DensityStart start;
  start.model = choice.model;
  start.restDensity = restDensity(temperature);
  std::ostringstream origin;
  if (!restDensity.isConstant()) origin << "at T = " << temperature << " K ";
  origin << "(" << restDensity.description() << ")";
  start.origin = origin.str();
  if (start.model == "hydrostatic") {
    start.gravity = neededBy(fields.location("rho"), asked, [&] { return settings.gravity(); });
    start.soundSpeed =
        neededBy(fields.location("rho"), asked, [&] { return settings.soundSpeed(); });
  }
  return start;
}

void setMaterialDensity(const DensityStart& start, ParticleCloud& cloud, double spacing) {
  auto& rho = cloud.addScalarField(field::rho);
  const double rhoS = start.restDensity;
  std::ostringstream log;
  log << "Cloud " << cloud.name() << ": rho " << start.model << " from rho_s = " << rhoS
      << " kg/m^3 " << start.origin;
  if (start.model == "standard") {
    for (Real& r : rho) r = static_cast<Real>(rhoS);
  } else {
    const double g = start.gravity.cast<double>().norm(), c = start.soundSpeed;
    const auto depths = depthsBelowFreeSurface(cloud.positions(), start.gravity, spacing);
    double deepest = 0.0;
    for (std::size_t i = 0; i < rho.size(); ++i) {
      rho[i] = static_cast<Real>(hydrostaticDensity(rhoS, g, depths[i], c));
      deepest = std::max(deepest, depths[i]);
    }
    log << ", |g| = " << g << " m/s^2, c = " << c << " m/s: depth up to " << deepest
        << " m, rho up to " << hydrostaticDensity(rhoS, g, deepest, c) << " kg/m^3";
  }
  info() << log.str() << "\n";
}

}  // namespace sphcast
