#include "bodies/BodySetup.h"

#include <cmath>
#include <filesystem>
#include <set>
#include <tuple>
#include <type_traits>
#include <vector>

#include "core/Error.h"

namespace sphcast {

namespace {
const Dimensions massUnit{{1, 0, 0, 0, 0, 0, 0}};
const Dimensions densityUnit{{1, -3, 0, 0, 0, 0, 0}};
const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};
const Dimensions inertiaUnit{{1, 2, 0, 0, 0, 0, 0}};
const Dimensions time{{0, 0, 1, 0, 0, 0, 0}};
const Dimensions forceUnit{{1, 1, -2, 0, 0, 0, 0}};
const Dimensions areaUnit{{0, 2, 0, 0, 0, 0, 0}};
const Dimensions pressureUnit{{1, -1, -2, 0, 0, 0, 0}};

bool finite(const Vector& v) { return v.allFinite(); }

// A word out of `words`, or a vector: "free", "locked" or "(0 0 1)" ("" and the vector).
std::string wordOrVector(const Dictionary& body, const std::string& key,
                         const std::vector<std::string>& words, Vector& vector) {
  try {
    vector = body.get<Vector>(key);
    return "";
  } catch (const DictionaryError&) {
    return body.getChoice(key, words);  // not a vector: the word's error, if it is none
  }
}

// A load table: not empty, finite, its times rising; an error at its line otherwise.
template <class Value>
void checkTable(const std::vector<std::tuple<double, Value>>& table, const SourceLocation& at,
                const std::string& key, const std::string& name) {
  if (table.empty()) {
    throw DictionaryError(at, "'" + key + "' of body '" + name + "' is an empty table");
  }
  for (std::size_t p = 0; p < table.size(); ++p) {
    const auto& [t, value] = table[p];
    bool finiteValue = true;
    if constexpr (std::is_same_v<Value, double>) {
      finiteValue = std::isfinite(value);
    } else {
      finiteValue = value.allFinite();
    }
    if (!std::isfinite(t) || !finiteValue) {
      throw DictionaryError(at, "'" + key + "' of body '" + name + "': point " + std::to_string(p) +
                                    " is not finite");
    }
    if (p > 0 && !(t > std::get<0>(table[p - 1]))) {
      throw DictionaryError(at, "'" + key + "' of body '" + name +
                                    "': the times must rise; point " + std::to_string(p) +
                                    " (t = " + std::to_string(t) + " s) does not follow point " +
                                    std::to_string(p - 1));
    }
  }
}

// A load: a constant (a table of one point) or a table against time, checked; an error at the
// key saying `form` where it is neither.
template <class Value>
std::vector<std::tuple<double, Value>> readLoad(const Dictionary& body, const std::string& key,
                                                const std::string& name, const Dimensions& unit,
                                                const std::string& form) {
  const SourceLocation at = body.location(key);
  std::vector<std::tuple<double, Value>> table;
  try {
    table = {{0.0, body.get<Value>(key, unit)}};
  } catch (const DictionaryError&) {
    try {
      table = body.get<std::vector<std::tuple<double, Value>>>(key);
    } catch (const DictionaryError&) {
      throw DictionaryError(at, "'" + key + "' of body '" + name + "' must be " + form);
    }
  }
  checkTable(table, at, key, name);
  return table;
}

RigidBodySettings readBody(const Dictionary& body, const std::string& name) {
  body.checkKeys({"cloud", "motion", "mass", "density", "centreOfMass", "momentOfInertia",
                  "translation", "rotation", "releaseTime", "endStop", "appliedForce",
                  "appliedPressure", "pressedArea", "pressDirection", "displacement"});
  RigidBodySettings settings;
  settings.name = name;
  settings.cloud = body.getOrDefault<std::string>("cloud", name);
  const bool prescribed =
      body.getChoiceOrDefault("motion", {"dynamic", "prescribed"}, "dynamic") == "prescribed";
  if (body.found("mass") == body.found("density")) {
    throw DictionaryError(body.location(),
                          "body '" + name + "' in " + body.name() +
                              " needs either 'mass' (kg) or 'density' (kg/m^3, for the mass of "
                              "its particles' volume), not " +
                              (body.found("mass") ? "both" : "neither"));
  }
  auto positive = [&](const char* key, const Dimensions& unit) {
    const double value = body.get<double>(key, unit);
    if (!(value > 0) || !std::isfinite(value)) {
      throw DictionaryError(body.location(key),
                            std::string("'") + key + "' of body '" + name + "' must be positive");
    }
    return value;
  };
  if (body.found("mass")) settings.mass = positive("mass", massUnit);
  if (body.found("density")) settings.density = positive("density", densityUnit);
  if (body.found("centreOfMass")) settings.centreOfMass = body.get<Vector>("centreOfMass", length);
  if (body.found("momentOfInertia")) {
    const Vector inertia = body.get<Vector>("momentOfInertia", inertiaUnit);
    if (!((inertia.array() > 0).all()) || !finite(inertia)) {
      throw DictionaryError(body.location("momentOfInertia"),
                            "'momentOfInertia' of body '" + name +
                                "' must be three positive principal moments (kg m^2)");
    }
    settings.momentOfInertia = inertia;
  }
  if (prescribed) {
    for (const char* dynamicOnly :
         {"translation", "rotation", "releaseTime", "endStop", "appliedForce", "appliedPressure",
          "pressedArea", "pressDirection"}) {
      if (body.found(dynamicOnly)) {
        throw DictionaryError(body.location(dynamicOnly),
                              std::string("'") + dynamicOnly + "' of body '" + name +
                                  "' is for motion dynamic; a prescribed body follows "
                                  "'displacement' alone");
      }
    }
    settings.displacement = body.get<std::vector<std::tuple<double, Vector>>>("displacement");
    checkTable(settings.displacement, body.location("displacement"), "displacement", name);
    return settings;
  }
  if (body.found("displacement")) {
    throw DictionaryError(body.location("displacement"),
                          "'displacement' of body '" + name + "' needs motion prescribed");
  }
  if (body.found("translation")) {
    Vector axis = Vector::Zero();
    const std::string word = wordOrVector(body, "translation", {"free", "locked"}, axis);
    if (word == "locked") {
      settings.translation = RigidBodySettings::Translation::locked;
    } else if (word.empty()) {
      if (!finite(axis) || !(axis.norm() > 0)) {
        throw DictionaryError(
            body.location("translation"),
            "'translation' of body '" + name + "': the axis must be a non-zero vector");
      }
      settings.translation = RigidBodySettings::Translation::axis;
      settings.axis = axis.normalized();
    }
  }
  settings.rotationLocked =
      body.getChoiceOrDefault("rotation", {"free", "locked"}, "free") == "locked";
  if (body.found("releaseTime")) settings.releaseTime = body.get<double>("releaseTime", time);
  if (body.found("endStop")) {
    const Vector stop = body.get<Vector>("endStop", length);
    if (!finite(stop) || !(stop.norm() > 0)) {
      throw DictionaryError(
          body.location("endStop"),
          "'endStop' of body '" + name + "' must be a non-zero travel of the centre (m)");
    }
    if (settings.translation == RigidBodySettings::Translation::axis &&
        (stop - stop.dot(settings.axis) * settings.axis).norm() > 1e-9 * stop.norm()) {
      throw DictionaryError(
          body.location("endStop"),
          "'endStop' of body '" + name + "' does not lie along its translation axis");
    }
    if (settings.translation == RigidBodySettings::Translation::locked) {
      throw DictionaryError(body.location("endStop"),
                            "'endStop' of body '" + name + "': its translation is locked");
    }
    settings.endStop = stop;
  }
  if (body.found("appliedForce")) {
    settings.appliedForce = readLoad<Vector>(
        body, "appliedForce", name, forceUnit,
        "a force (Fx Fy Fz) in N, or a table of them against time ((t0 (Fx Fy Fz)) ...)");
  }
  if (body.found("appliedPressure")) {
    const SourceLocation at = body.location("appliedPressure");
    settings.appliedPressure =
        readLoad<double>(body, "appliedPressure", name, pressureUnit,
                         "a pressure in Pa, or a table of them against time ((t0 p0) (t1 p1) ...)");
    if (!body.found("pressedArea") || !body.found("pressDirection")) {
      throw DictionaryError(at, "'appliedPressure' of body '" + name +
                                    "' acts on 'pressedArea' (m^2) along 'pressDirection' (the "
                                    "direction it pushes the body): give both");
    }
    settings.pressedArea = body.get<double>("pressedArea", areaUnit);
    if (!(settings.pressedArea > 0) || !std::isfinite(settings.pressedArea)) {
      throw DictionaryError(body.location("pressedArea"),
                            "'pressedArea' of body '" + name + "' must be a positive area (m^2)");
    }
    const Vector direction = body.get<Vector>("pressDirection");
    if (!finite(direction) || !(direction.norm() > 0)) {
      throw DictionaryError(body.location("pressDirection"),
                            "'pressDirection' of body '" + name + "' must be a non-zero vector");
    }
    settings.pressDirection = direction.normalized();
  } else {
    for (const char* pressOnly : {"pressedArea", "pressDirection"}) {
      if (body.found(pressOnly)) {
        throw DictionaryError(
            body.location(pressOnly),
            std::string("'") + pressOnly + "' of body '" + name + "' is for 'appliedPressure'");
      }
    }
  }
  return settings;
}
}  // namespace

BodySetup readBodySetup(const CaseDescription& description) {
  BodySetup setup;
  const auto file = description.folder().constantFile("dynamicBodies");
  if (!std::filesystem::exists(file)) return setup;
  const Dictionary bodies = Dictionary::read(file);
  std::set<std::string> clouds;
  for (const std::string& name : bodies.keys()) {
    if (!bodies.isDict(name)) {
      throw DictionaryError(bodies.location(name),
                            "'" + name + "' in " + bodies.name() +
                                " is not a body: each body is a sub-dictionary { cloud ...; }");
    }
    const Dictionary& body = bodies.subDict(name);
    setup.bodies.push_back(readBody(body, name));
    setup.declaredAt[name] = body.location();
    if (!clouds.insert(setup.bodies.back().cloud).second) {
      throw DictionaryError(body.location(), "body '" + name + "' moves cloud '" +
                                                 setup.bodies.back().cloud +
                                                 "', which another body moves already");
    }
  }
  return setup;
}

std::string bodyStateFile(const std::string& timeName,
                          const std::vector<const RigidBody*>& bodies) {
  std::string text = foamFileHeader(timeName + "/uniform", "dynamicBodies") + "\n";
  for (const RigidBody* body : bodies) text += body->stateDictionary() + '\n';
  return text;
}

}  // namespace sphcast
