#include "solver/FlowSetup.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "materials/MaterialLibrary.h"
#include "sph/EquationOfState.h"

namespace sphcast {

namespace {

const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};
const Dimensions speed{{0, 1, -1, 0, 0, 0, 0}};

// The range of h/dx (supportRadius over the particle spacing) a run can trust: below it the
// kernel reaches hardly a neighbour, above it a step costs (h/dx)^3 pairs for nothing.
constexpr double lowestSupportRatio = 1.2;
constexpr double highestSupportRatio = 6.0;

template <class Value>
Value positive(const Dictionary& dict, const std::string& key, const Dimensions& dimensions) {
  const Value value = dict.get<Value>(key, dimensions);
  if (!(value > 0)) {
    std::ostringstream message;
    message << "'" << key << "' is " << value << " in " << dict.name()
            << "; it must be positive (valid range: > 0)";
    throw DictionaryError(dict.location(key), message.str());
  }
  return value;
}

}  // namespace

// periodic { x (0 0.2); z (-0.01 0.01); }: each axis named with its interval [lower, upper).
PeriodicBox readPeriodicBox(const Dictionary& periodic, Real supportRadius, int dimension) {
  PeriodicBox box;
  const std::vector<std::string> axes{"x", "y", "z"};
  periodic.checkKeys(axes);
  for (int axis = 0; axis < 3; ++axis) {
    const std::string& key = axes[static_cast<std::size_t>(axis)];
    if (!periodic.found(key)) continue;
    const auto interval = periodic.get<Eigen::Vector2d>(key, length);
    const double period = interval[1] - interval[0];
    // the minimum image is unique only for pairs closer than half a period
    if (!(period > 2 * static_cast<double>(supportRadius))) {
      throw DictionaryError(periodic.location(key),
                            "periodic interval of " + key + " must be longer than twice the " +
                                "supportRadius (" + std::to_string(supportRadius) + " m) in " +
                                periodic.name());
    }
    if (dimension == 2 && axis == 2) {
      throw DictionaryError(periodic.location(key), "a 2D case has no periodic z axis");
    }
    box.setPeriodic(axis, static_cast<Real>(interval[0]), static_cast<Real>(period));
  }
  return box;
}

FlowSetup readFlowSetup(const CaseFolder& caseFolder, const std::optional<Vector>& gravityFile) {
  FlowSetup setup;
  const auto modelsFile = caseFolder.constantFile("physicsModels");
  if (!std::filesystem::exists(modelsFile)) return setup;
  const Dictionary models = Dictionary::read(modelsFile);
  models.checkKeys(
      {"dimension", "periodic", "materials", "flow", "heatTransfer", "surfaceTension",
       "solidification"});
  if (!models.found("flow")) return setup;
  const Dictionary& flow = models.subDict("flow");
  flow.checkKeys({"model", "fluid", "walls"});
  if (flow.getChoice("model", {"none", "weaklyCompressible"}) == "none") return setup;
  setup.enabled = true;
  if (!gravityFile) {
    throw DictionaryError(models.location("flow"),
                          "a flow needs gravity, but " +
                              caseFolder.constantFile("g").string() +
                              " does not exist (write 'dimensions [0 1 -2 0 0 0 0]; value (0 0 "
                              "-9.81);' there, or (0 0 0) for none)");
  }
  const Vector gravity = *gravityFile;
  setup.fluidCloud = flow.get<std::string>("fluid");
  setup.wallClouds = flow.getOrDefault<std::vector<std::string>>("walls", {});

  const Dictionary schemes = Dictionary::read(caseFolder.systemFile("sphSchemes"));
  schemes.checkKeys({"densityScheme", "kernelCorrection", "viscousForm", "wallSlip",
                     "wallDissipation", "supportRadius", "soundSpeed", "deltaSPHCoeffs",
                     "wallClearance", "neighbourListSkin"});
  FlowSettings& settings = setup.settings;
  settings.densityScheme = schemes.getChoice("densityScheme", {"riemann", "standard", "deltaSPH"});
  settings.kernelCorrection =
      schemes.getChoiceOrDefault("kernelCorrection", {"on", "off"}, "off") == "on";
  settings.viscousForm = schemes.getChoice("viscousForm", {"Morris", "Cleary"});
  settings.slipWalls =
      schemes.getChoiceOrDefault("wallSlip", {"noSlip", "slip"}, "noSlip") == "slip";
  settings.wallDissipationNormalApproach =
      schemes.getChoiceOrDefault("wallDissipation", {"relativeVelocity", "normalApproach"},
                                 "relativeVelocity") == "normalApproach";
  settings.supportRadius = positive<Real>(schemes, "supportRadius", length);
  setup.supportRadiusAt = schemes.location("supportRadius");
  settings.soundSpeed = positive<Real>(schemes, "soundSpeed", speed);
  if (schemes.found("deltaSPHCoeffs")) {
    const Dictionary& coeffs = schemes.subDict("deltaSPHCoeffs");
    coeffs.checkKeys({"delta", "alpha"});
    settings.deltaSPHDiffusion = coeffs.getOrDefault<Real>("delta", settings.deltaSPHDiffusion);
    settings.deltaSPHViscosity = coeffs.getOrDefault<Real>("alpha", settings.deltaSPHViscosity);
    for (const char* key : {"delta", "alpha"}) {
      if (coeffs.found(key) && !(coeffs.get<Real>(key) >= 0)) {
        throw DictionaryError(
            coeffs.location(key),
            std::string("'") + key + "' must not be negative in " + coeffs.name());
      }
    }
  }
  // in spacings; at 0 a particle is still moved back when it is behind the surface, onto it
  settings.wallClearance = schemes.getOrDefault<Real>("wallClearance", settings.wallClearance);
  if (!(settings.wallClearance >= 0 && settings.wallClearance <= Real(0.5))) {
    throw DictionaryError(
        schemes.location("wallClearance"),
        "'wallClearance' (in particle spacings) must lie in [0, 0.5] in " + schemes.name());
  }
  // a fraction of h: pair lists searched with h (1 + skin) and reused until particles may have
  // closed in by the skin (particles/Neighbourhood.h)
  settings.neighbourListSkin =
      schemes.getOrDefault<Real>("neighbourListSkin", settings.neighbourListSkin);
  if (!(settings.neighbourListSkin >= 0 && settings.neighbourListSkin <= 1)) {
    throw DictionaryError(schemes.location("neighbourListSkin"),
                          "'neighbourListSkin' (a fraction of the supportRadius) must lie in "
                          "[0, 1] in " + schemes.name());
  }
  settings.gravity = gravity;
  settings.dimension = models.getOrDefault<int>("dimension", 3);
  if (settings.dimension != 2 && settings.dimension != 3) {
    throw DictionaryError(models.location("dimension"),
                          "'dimension' must be 2 or 3 in " + models.name());
  }
  if (settings.dimension == 2 && gravity[2] != 0) {
    throw DictionaryError(models.location("dimension"),
                          "a 2D case lies in the x-y plane, but constant/g has a z component");
  }
  if (models.found("periodic")) {
    settings.periodic =
        readPeriodicBox(models.subDict("periodic"), settings.supportRadius, settings.dimension);
  }

  // The fluid's material must be in physicalProperties, which may hold other materials too
  // (setCastFields' clouds may use them); the error is where the name is written.
  const MaterialLibrary materials =
      MaterialLibrary::read(caseFolder.constantFile("physicalProperties"));
  // the fluid cloud's material: named in `materials { cloud material; }`, else like the cloud
  const bool mapped =
      models.found("materials") && models.subDict("materials").found(setup.fluidCloud);
  const Material& fluid =
      mapped ? materials.get(models.subDict("materials").get<std::string>(setup.fluidCloud),
                             models.subDict("materials").location(setup.fluidCloud), "materials")
             : materials.get(setup.fluidCloud, flow.location("fluid"), "fluid");
  setup.restDensity = fluid.requireDensity("the flow");
  setup.viscosity = fluid.requireViscosity("the flow");
  return setup;
}

SoundSpeedCheck checkSoundSpeed(const FlowSettings& settings, const ParticleCloud& fluid,
                                const std::vector<const ParticleCloud*>& walls,
                                const Communicator& comm) {
  SoundSpeedCheck check;
  const double g = static_cast<double>(settings.gravity.norm());
  const Eigen::Vector3d up =
      g > 0 ? Eigen::Vector3d(-settings.gravity.cast<double>() / g) : Eigen::Vector3d::Zero();
  double top = -std::numeric_limits<double>::infinity();
  double bottom = std::numeric_limits<double>::infinity();
  const auto& x = fluid.positions();
  for (std::size_t i = 0; i < fluid.ownedSize(); ++i) {
    top = std::max(top, x[i].cast<double>().dot(up));
    bottom = std::min(bottom, x[i].cast<double>().dot(up));
  }
  for (const ParticleCloud* wall : walls) {
    const auto& y = wall->positions();
    for (std::size_t k = 0; k < wall->ownedSize(); ++k) {
      bottom = std::min(bottom, y[k].cast<double>().dot(up));
    }
  }
  if (fluid.hasVectorField("U")) {
    const auto& u = fluid.vectorField("U");
    for (std::size_t i = 0; i < fluid.ownedSize(); ++i) {
      check.initialSpeed = std::max(check.initialSpeed, static_cast<double>(u[i].norm()));
    }
  }
  // over every rank of a decomposed run
  std::vector<double> largest{top, -bottom, check.initialSpeed};
  comm.max(largest);
  top = largest[0];
  bottom = -largest[1];
  check.initialSpeed = largest[2];
  const bool anyFluid = comm.sum(static_cast<std::int64_t>(fluid.ownedSize())) > 0;
  check.fallHeight = anyFluid ? std::max(0.0, top - bottom) : 0.0;
  check.largestSpeed =
      std::sqrt(check.initialSpeed * check.initialSpeed + 2.0 * g * check.fallHeight);
  const double c = static_cast<double>(settings.soundSpeed);
  check.mach = check.largestSpeed / c;
  check.tooLow = check.mach > maxStartMach;
  std::ostringstream message;
  message.precision(3);
  message << "Sound speed: c = " << c << " m/s against the largest speed the metal can reach, "
          << "sqrt(|U0|^2 + 2 |g| H) = " << check.largestSpeed << " m/s (|U0| up to "
          << check.initialSpeed << " m/s, a fall H = " << check.fallHeight
          << " m from its top to the lowest wall, or its own bottom): Mach up to " << check.mach;
  if (check.tooLow) {
    message << ", above " << maxStartMach << ": the density will stray by about Ma^2 = "
            << 100 * check.mach * check.mach
            << " % from rho_s (the pressure waves with it); raise soundSpeed in "
               "system/sphSchemes to at least "
            << 10 * check.largestSpeed << " m/s (10 times that speed; the step shrinks as 1/c)";
  }
  check.message = message.str();
  return check;
}

std::vector<std::string> prepareFluidFields(const FlowSetup& setup, ParticleCloud& fluid) {
  const auto spacing = fluid.attributes().find("spacing");
  if (spacing == fluid.attributes().end() || !(spacing->second > 0)) {
    throw Error("cloud '" + fluid.name() + "' (" + fluid.name() +
                ".vtp of the start time) has no positive 'spacing' attribute, the particle "
                "spacing dx that the flow needs; write the cloud with setCastFields, which "
                "records it");
  }
  const double ratio = static_cast<double>(setup.settings.supportRadius) / spacing->second;
  if (!(ratio >= lowestSupportRatio && ratio <= highestSupportRatio)) {
    std::ostringstream message;
    message << "'supportRadius' " << setup.settings.supportRadius << " m is " << ratio
            << " times the spacing " << spacing->second << " m of cloud '" << fluid.name()
            << "'; supportRadius/spacing must lie in [" << lowestSupportRatio << ", "
            << highestSupportRatio << "] (3 is usual)";
    throw DictionaryError(setup.supportRadiusAt, message.str());
  }
  std::vector<std::string> added;
  auto fill = [&](const char* name, Real value) {
    if (fluid.hasScalarField(name)) return;
    for (Real& x : fluid.addScalarField(name)) x = value;
    added.emplace_back(name);
  };
  // A property of the material as a field: its value, or its value at each particle's T.
  auto fillFromTable = [&](const char* name, const TemperatureTable& table) {
    if (fluid.hasScalarField(name)) return;
    if (table.isConstant()) {
      fill(name, static_cast<Real>(table(0)));
      return;
    }
    if (!fluid.hasScalarField("T")) {
      throw DictionaryError(table.location(), table.description() +
                                                  " is a table in T, but cloud '" + fluid.name() +
                                                  "' has no T (set it with setCastFields)");
    }
    // a copy: adding a field may move the others
    const std::vector<Real> temperature = fluid.scalarField("T");
    auto& field = fluid.addScalarField(name);
    for (std::size_t i = 0; i < field.size(); ++i) {
      field[i] = static_cast<Real>(table(static_cast<double>(temperature[i])));
    }
    added.emplace_back(name);
  };
  fillFromTable("restDensity", *setup.restDensity);
  fillFromTable("viscosity", *setup.viscosity);
  if (!fluid.hasScalarField("rho")) {
    // a copy: adding a field may move the others
    const std::vector<Real> restValues = fluid.scalarField("restDensity");
    fluid.addScalarField("rho") = restValues;
    added.emplace_back("rho");
  }
  if (!fluid.hasScalarField("mass")) {
    if (!fluid.hasScalarField("volume")) {
      throw Error("cloud '" + fluid.name() +
                  "' has neither 'mass' nor 'volume' (setCastFields writes volume)");
    }
    const auto& volume = fluid.scalarField("volume");
    const auto& rho = fluid.scalarField("rho");
    auto& mass = fluid.addScalarField("mass");
    for (std::size_t i = 0; i < mass.size(); ++i) mass[i] = rho[i] * volume[i];
    added.emplace_back("mass");
  }
  if (!fluid.hasVectorField("U")) {
    fluid.addVectorField("U");
    added.emplace_back("U");
  }
  return added;
}

std::vector<Real> startPressure(const FlowSetup& setup, const ParticleCloud& fluid) {
  ParticleCloud started = fluid;
  prepareFluidFields(setup, started);
  const LinearEquationOfState equationOfState{setup.settings.soundSpeed};
  const auto& rho = started.scalarField("rho");
  const auto& restDensity = started.scalarField("restDensity");
  std::vector<Real> pressure(rho.size());
  for (std::size_t i = 0; i < rho.size(); ++i) {
    pressure[i] = equationOfState.pressure(rho[i], restDensity[i]);
  }
  return pressure;
}

}  // namespace sphcast
