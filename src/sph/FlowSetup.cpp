#include "sph/FlowSetup.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "particles/FieldNames.h"
#include "sph/EquationOfState.h"

namespace sphcast {

namespace {

// The range of h/dx (supportRadius over the particle spacing) a run can trust: below it the
// kernel reaches hardly a neighbour, above it a step costs (h/dx)^3 pairs for nothing.
constexpr double lowestSupportRatio = 1.2;
constexpr double highestSupportRatio = 6.0;

// flow { model incompressible; }: the weakly compressible flow's own schemes refused, and
// pressureSolverCoeffs read (IncompressiblePressure.h).
void readPressureSolver(const Dictionary& schemes, FlowSettings& settings) {
  for (const char* key : {"timeStepping", "densityReinitialisation"}) {
    if (!schemes.found(key)) continue;
    const std::string value = schemes.get<std::string>(key);
    if (value == "kickDriftKick" || value == "none") continue;
    throw DictionaryError(schemes.location(key),
                          "'" + std::string(key) + " " + value +
                              "' is the weakly compressible flow's; flow { model incompressible; "
                              "} solves its pressure in steps of its own (remove it from " +
                              schemes.name() + ")");
  }
  if (settings.densityScheme == "deltaSPH") {
    throw DictionaryError(schemes.location("densityScheme"),
                          "densityScheme deltaSPH is the weakly compressible flow's; with flow { "
                          "model incompressible; } write riemann (the viscous and wall terms "
                          "are the same) in " +
                              schemes.name());
  }
  if (!schemes.found("pressureSolverCoeffs")) return;
  const Dictionary& coeffs = schemes.subDict("pressureSolverCoeffs");
  coeffs.checkKeys({"densityTolerance", "largestCompression", "minIterations", "maxIterations",
                    "relaxation", "advectionCo"});
  IncompressibleSettings& solver = settings.pressureSolver;
  solver.densityTolerance = coeffs.getOrDefault<Real>("densityTolerance", solver.densityTolerance);
  solver.largestCompression =
      coeffs.getOrDefault<Real>("largestCompression", solver.largestCompression);
  solver.minIterations = coeffs.getOrDefault<int>("minIterations", solver.minIterations);
  solver.maxIterations = coeffs.getOrDefault<int>("maxIterations", solver.maxIterations);
  solver.relaxation = coeffs.getOrDefault<Real>("relaxation", solver.relaxation);
  solver.advectionCo = coeffs.getOrDefault<Real>("advectionCo", solver.advectionCo);
  auto refuse = [&](const char* key, const std::string& why) {
    throw DictionaryError(coeffs.location(key),
                          "'" + std::string(key) + "' " + why + " in " + coeffs.name());
  };
  if (!(solver.densityTolerance > 0 && solver.densityTolerance < Real(0.1))) {
    refuse("densityTolerance", "(the mean compression left, a fraction of rho_s) must lie in (0, 0.1)");
  }
  if (!(solver.largestCompression >= solver.densityTolerance && solver.largestCompression < 1)) {
    refuse("largestCompression",
           "(the largest compression of one particle left) must lie in [densityTolerance, 1)");
  }
  if (solver.minIterations < 1) refuse("minIterations", "must be at least 1");
  if (solver.maxIterations < solver.minIterations) {
    refuse("maxIterations", "must be at least minIterations");
  }
  if (!(solver.relaxation > 0 && solver.relaxation <= 1)) {
    refuse("relaxation", "(the Jacobi iteration's omega) must lie in (0, 1]");
  }
  if (!(solver.advectionCo > 0 && solver.advectionCo <= 1)) {
    refuse("advectionCo", "(dt |U|max / dx) must lie in (0, 1]");
  }
}

}  // namespace

FlowSetup readFlowSetup(const CaseDescription& description) {
  FlowSetup setup;
  const Dictionary* flow = description.modelsEntry("flow");
  if (!flow) return setup;
  const std::string model = flow->getChoice("model", {"none", "weaklyCompressible", "incompressible"});
  if (model == "none") return setup;
  setup.enabled = true;
  setup.settings.incompressible = model == "incompressible";
  const Dictionary& models = description.physicsModels();
  if (!description.gravity()) {
    throw DictionaryError(models.location("flow"),
                          "a flow needs gravity, but " +
                              description.folder().constantFile("g").string() +
                              " does not exist (write 'dimensions [0 1 -2 0 0 0 0]; value (0 0 "
                              "-9.81);' there, or (0 0 0) for none)");
  }
  const Vector gravity = *description.gravity();
  setup.fluidCloud = description.fluidCloud();
  setup.wallClouds = description.wallClouds();

  const Dictionary& schemes = description.schemes();
  schemes.checkKeys({"densityScheme", "kernelCorrection", "viscousForm", "wallSlip",
                     "wallDissipation", "supportRadius", "soundSpeed", "deltaSPHCoeffs",
                     "wallClearance", "neighbourListSkin", "viscositySolver",
                     "viscositySolverCoeffs", "densityReinitialisation",
                     "densityReinitialisationCoeffs", "timeStepping", "dualCriteriaCoeffs",
                     "pressureSolverCoeffs"});
  FlowSettings& settings = setup.settings;
  settings.densityScheme = schemes.getChoice("densityScheme", {"riemann", "standard", "deltaSPH"});
  settings.kernelCorrection = schemes.getOrDefault<bool>("kernelCorrection", false);
  settings.reinitialiseDensity =
      schemes.getChoiceOrDefault("densityReinitialisation", {"none", "packed"}, "none") == "packed";
  if (schemes.found("densityReinitialisationCoeffs")) {
    const Dictionary& coeffs = schemes.subDict("densityReinitialisationCoeffs");
    coeffs.checkKeys({"relaxation"});
    settings.densityRelaxation =
        coeffs.getOrDefault<Real>("relaxation", settings.densityRelaxation);
    if (!(settings.densityRelaxation > 0 && settings.densityRelaxation <= 1)) {
      throw DictionaryError(coeffs.location("relaxation"),
                            "'relaxation' (the share of the way to the packed density taken "
                            "each flow step) must lie in (0, 1] in " +
                                coeffs.name());
    }
  }
  settings.dualCriteria =
      schemes.getChoiceOrDefault("timeStepping", {"kickDriftKick", "dualCriteria"},
                                 "kickDriftKick") == "dualCriteria";
  if (settings.dualCriteria && settings.densityScheme == "deltaSPH") {
    throw DictionaryError(schemes.location("timeStepping"),
                          "timeStepping dualCriteria takes densityScheme riemann or standard; "
                          "deltaSPH has its own Stormer-Verlet step (kickDriftKick) in " +
                              schemes.name());
  }
  if (schemes.found("dualCriteriaCoeffs")) {
    const Dictionary& coeffs = schemes.subDict("dualCriteriaCoeffs");
    coeffs.checkKeys({"advectionCo", "acousticCo"});
    settings.advectionCo = coeffs.getOrDefault<Real>("advectionCo", settings.advectionCo);
    settings.acousticCo = coeffs.getOrDefault<Real>("acousticCo", settings.acousticCo);
    if (!(settings.advectionCo > 0 && settings.advectionCo <= 1)) {
      throw DictionaryError(coeffs.location("advectionCo"),
                            "'advectionCo' (the most a particle travels between two searches, "
                            "in particle spacings) must lie in (0, 1] in " +
                                coeffs.name());
    }
    if (!(settings.acousticCo > 0 && settings.acousticCo <= 2)) {
      throw DictionaryError(coeffs.location("acousticCo"),
                            "'acousticCo' (the acoustic sub-steps' Courant number, dt (c + "
                            "|U|max) / dx) must lie in (0, 2] in " +
                                coeffs.name());
    }
  }
  if (settings.incompressible) readPressureSolver(schemes, settings);
  settings.viscousForm = schemes.getChoice("viscousForm", {"Morris", "Cleary"});
  const std::string solver =
      schemes.getChoiceOrDefault("viscositySolver", {"auto", "explicit", "implicit"}, "auto");
  settings.viscositySolver = solver == "implicit"   ? ViscositySolver::implicitForm
                             : solver == "explicit" ? ViscositySolver::explicitForm
                                                    : ViscositySolver::automatic;
  if (solver == "implicit" && settings.viscousForm == "Cleary") {
    throw DictionaryError(schemes.location("viscositySolver"),
                          "viscositySolver implicit solves the Morris form; set viscousForm "
                          "Morris in " +
                              schemes.name());
  }
  if (schemes.found("viscositySolverCoeffs")) {
    const Dictionary& coeffs = schemes.subDict("viscositySolverCoeffs");
    coeffs.checkKeys({"tolerance", "relTol", "maxIter"});
    ImplicitViscositySettings& implicit = settings.implicitViscosity;
    implicit.tolerance = coeffs.getOrDefault<Real>("tolerance", implicit.tolerance);
    implicit.relativeTolerance = coeffs.getOrDefault<Real>("relTol", implicit.relativeTolerance);
    implicit.maxIterations = coeffs.getOrDefault<int>("maxIter", implicit.maxIterations);
    if (!(implicit.relativeTolerance >= 0 && implicit.relativeTolerance < 1)) {
      throw DictionaryError(
          coeffs.location("relTol"),
          "'relTol' (of the residual against its start) must lie in [0, 1) in " + coeffs.name());
    }
    if (!(implicit.tolerance > 0 && implicit.tolerance < 1)) {
      throw DictionaryError(coeffs.location("tolerance"),
                            "'tolerance' (of the residual against the right side) must lie in "
                            "(0, 1) in " +
                                coeffs.name());
    }
    if (implicit.maxIterations < 1) {
      throw DictionaryError(coeffs.location("maxIter"),
                            "'maxIter' must be at least 1 in " + coeffs.name());
    }
  }
  settings.walls.all = readWallCondition(schemes, WallCondition());
  for (const auto& [cloud, entry] : description.wallEntries()) {
    settings.walls.own[cloud] = readWallCondition(*entry, settings.walls.all);
  }
  settings.supportRadius = description.supportRadius();
  setup.supportRadiusAt = description.supportRadiusAt();
  settings.soundSpeed = description.soundSpeed();
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
                          "[0, 1] in " +
                              schemes.name());
  }
  settings.gravity = gravity;
  settings.dimension = description.dimension();
  if (settings.dimension == 2 && gravity[2] != 0) {
    throw DictionaryError(models.location("dimension"),
                          "a 2D case lies in the x-y plane, but constant/g has a z component");
  }
  settings.periodic = description.periodic();

  // The fluid's material must be in physicalProperties, which may hold other materials too
  // (setCastFields' clouds may use them); the error is where the name is written.
  const Material& fluid = description.fluidMaterial();
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
  if (fluid.hasVectorField(field::U)) {
    const auto& u = fluid.vectorField(field::U);
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
    message << ", above " << maxStartMach
            << ": the density will stray by about Ma^2 = " << 100 * check.mach * check.mach
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
    if (!fluid.hasScalarField(field::T)) {
      throw DictionaryError(table.location(), table.description() +
                                                  " is a table in T, but cloud '" + fluid.name() +
                                                  "' has no T (set it with setCastFields)");
    }
    // a copy: adding a field may move the others
    const std::vector<Real> temperature = fluid.scalarField(field::T);
    auto& field = fluid.addScalarField(name);
    for (std::size_t i = 0; i < field.size(); ++i) {
      field[i] = static_cast<Real>(table(static_cast<double>(temperature[i])));
    }
    added.emplace_back(name);
  };
  fillFromTable(field::restDensity, *setup.restDensity);
  fillFromTable(field::viscosity, *setup.viscosity);
  if (!fluid.hasScalarField(field::rho)) {
    // a copy: adding a field may move the others
    const std::vector<Real> restValues = fluid.scalarField(field::restDensity);
    fluid.addScalarField(field::rho) = restValues;
    added.emplace_back(field::rho);
  }
  if (!fluid.hasScalarField(field::mass)) {
    if (!fluid.hasScalarField(field::volume)) {
      throw Error("cloud '" + fluid.name() +
                  "' has neither 'mass' nor 'volume' (setCastFields writes volume)");
    }
    const auto& volume = fluid.scalarField(field::volume);
    const auto& rho = fluid.scalarField(field::rho);
    auto& mass = fluid.addScalarField(field::mass);
    for (std::size_t i = 0; i < mass.size(); ++i) mass[i] = rho[i] * volume[i];
    added.emplace_back(field::mass);
  }
  if (!fluid.hasVectorField(field::U)) {
    fluid.addVectorField(field::U);
    added.emplace_back(field::U);
  }
  return added;
}

std::vector<Real> startPressure(const FlowSetup& setup, const ParticleCloud& fluid) {
  ParticleCloud started = fluid;
  prepareFluidFields(setup, started);
  const LinearEquationOfState equationOfState{setup.settings.soundSpeed};
  const auto& rho = started.scalarField(field::rho);
  const auto& restDensity = started.scalarField(field::restDensity);
  std::vector<Real> pressure(rho.size());
  for (std::size_t i = 0; i < rho.size(); ++i) {
    pressure[i] = equationOfState.pressure(rho[i], restDensity[i]);
  }
  return pressure;
}

}  // namespace sphcast
