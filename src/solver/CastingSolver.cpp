#include "solver/CastingSolver.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <new>
#include <numbers>
#include <ostream>
#include <sstream>

#include "core/Error.h"
#include "core/Gravity.h"
#include "core/dictionary/Dictionary.h"
#include "io/VtpCloud.h"
#include "sph/CorrectedGradient.h"

namespace sphcast {

CastingSolver::CastingSolver(const CaseFolder& caseFolder)
    : caseFolder_(caseFolder),
      repairedWrites_(caseFolder.recoverInterruptedWrites()),
      time_(caseFolder),
      // constant/g for a flow or ballistic clouds; a case that only conducts heat needs none
      gravityFile_(readGravityIfPresent(caseFolder)),
      gravity_(gravityFile_.value_or(Vector::Zero())),
      motion_(gravity_),
      flowSetup_(readFlowSetup(caseFolder, gravityFile_)),
      heatSetup_(readHeatSetup(caseFolder)),
      surfaceTensionSetup_(readSurfaceTensionSetup(caseFolder, flowSetup_)),
      solidificationSetup_(readSolidificationSetup(caseFolder, flowSetup_, heatSetup_)),
      writer_(caseFolder, time_.settings().purgeWrite) {
  for (const std::string& repaired : repairedWrites_) {
    info() << "Repaired interrupted write: " << repaired << std::endl;
  }
  info() << "Starting from time " << time_.startTimeName() << " (index " << time_.timeIndex()
         << ")\n";
  clouds_ = readTimeFolderClouds(caseFolder_, time_.startTimeName());
  if (clouds_.empty()) {
    throw Error("time folder " + (caseFolder_.root() / time_.startTimeName()).string() +
                " holds no cloud (.vtp) to run");
  }
  const std::vector<std::string> startFields = fieldInventory(clouds_);
  // controlDict's entries beyond run control (TimeControl's), read once
  const Dictionary controlDict = Dictionary::read(caseFolder_.systemFile("controlDict"));
  health_ = HealthSettings::read(controlDict);
  // Clouds join clouds_ before any model holds a pointer into it.
  if (heatSetup_.enabled) loadHeatClouds();
  if (flowSetup_.enabled || heatSetup_.enabled) {
    setUpNeighbourhood();
    if (flowSetup_.enabled) setUpFlow();
    if (heatSetup_.enabled) setUpHeat();
    if (solidificationSetup_.enabled) setUpSolidification();
    startModels();
    // setCastFields wrote the first time without the clouds and fields the models add (a held
    // mold with its T, solidFraction, ...): written again with them, ParaView lists every field
    // from the first time. It is the state a restart from this time starts from. A later time
    // (a restart) is left as its run wrote it.
    const auto times = caseFolder_.times();
    const bool firstTime = !times.empty() && times.front().name == time_.startTimeName();
    if (firstTime && fieldInventory(clouds_) != startFields) {
      std::vector<const ParticleCloud*> written;
      for (const ParticleCloud& cloud : clouds_) written.push_back(&cloud);
      writer_.rewriteStart(time_.state(), written);
      info() << "    (time " << time_.startTimeName()
             << " written again with every cloud and field the run writes)\n";
    }
  } else {
    // ballistic clouds need constant/g: reading it again gives the missing file's error
    if (!gravityFile_) readGravity(caseFolder_);
    for (const ParticleCloud& cloud : clouds_) {
      info() << "Cloud " << cloud.name() << ": " << cloud.size() << " particles"
             << (cloud.hasVectorField("U") ? ", moving ballistically" : ", static (no U field)")
             << '\n';
      if (time_.settings().adjustTimeStep && cloud.hasVectorField("U")) {
        motion_.stableDeltaT(cloud, time_.settings().maxCo);  // fail now, not after writing
      }
    }
  }
  setUpFunctionObjects(controlDict);
  info() << std::endl;
}

std::vector<std::string> CastingSolver::fieldInventory(const std::vector<ParticleCloud>& clouds) {
  std::vector<std::string> names;
  for (const ParticleCloud& cloud : clouds) {
    names.push_back(cloud.name());
    for (const auto& [name, field] : cloud.scalarFields()) names.push_back(cloud.name() + "." + name);
    for (const auto& [name, field] : cloud.vectorFields()) names.push_back(cloud.name() + "." + name);
    for (const auto& [name, field] : cloud.idFields()) names.push_back(cloud.name() + "." + name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

ParticleCloud* CastingSolver::findCloud(const std::string& name) {
  for (ParticleCloud& cloud : clouds_) {
    if (cloud.name() == name) return &cloud;
  }
  return nullptr;
}

ParticleCloud& CastingSolver::cloudNamed(const std::string& name) {
  if (ParticleCloud* cloud = findCloud(name)) return *cloud;
  std::string present;
  for (const ParticleCloud& cloud : clouds_) present += " " + cloud.name();
  throw Error("constant/physicsModels names the fluid cloud '" + name + "', but time " +
              time_.startTimeName() + " holds only (" + present + " )");
}

// A heat cloud is taken from the start time when it is there, else from constant/particles
// (a mold as particleizeMold wrote it): from then on it is written to every time folder, since
// its temperature changes.
void CastingSolver::loadHeatClouds() {
  for (const std::string& name : heatSetup_.clouds) {
    if (findCloud(name)) continue;
    const auto file = caseFolder_.constant() / "particles" / (name + ".vtp");
    if (!std::filesystem::exists(file)) {
      std::string present;
      for (const ParticleCloud& cloud : clouds_) present += " " + cloud.name();
      throw DictionaryError(heatSetup_.cloudsAt, "heat cloud '" + name + "' is neither in time " +
                                                     time_.startTimeName() + " (which holds (" +
                                                     present + " )) nor in constant/particles");
    }
    clouds_.push_back(readCloudVtp(file, name));
    info() << "Cloud " << name << ": from constant/particles (carries heat: written from now on)\n";
  }
}

// Every cloud a model works on, registered once: the flow's fluid moves, everything else is
// at rest (moving molds arrive with the rigid bodies).
void CastingSolver::setUpNeighbourhood() {
  const Real radius =
      flowSetup_.enabled ? flowSetup_.settings.supportRadius : heatSetup_.supportRadius;
  const PeriodicBox periodic =
      flowSetup_.enabled ? flowSetup_.settings.periodic : heatSetup_.periodic;
  if (flowSetup_.enabled && heatSetup_.enabled &&
      heatSetup_.supportRadius != flowSetup_.settings.supportRadius) {
    throw Error("internal: flow and heat read different supportRadius");
  }
  neighbourhood_ = std::make_unique<Neighbourhood>(radius, periodic);
  if (flowSetup_.enabled) {
    ParticleCloud& fluid = cloudNamed(flowSetup_.fluidCloud);
    neighbourhood_->addCloud(fluid, Neighbourhood::Motion::moving);
    evolving_.push_back(&fluid);
    // A wall cloud is taken from the start time when it is there (setCastFields may have set
    // its fields, or it carries heat), else from constant/particles, where particleizeMold
    // wrote it.
    for (const std::string& wallName : flowSetup_.wallClouds) {
      if (const ParticleCloud* inTime = findCloud(wallName)) {
        wallClouds_.push_back(inTime);
        continue;
      }
      const auto file = caseFolder_.constant() / "particles" / (wallName + ".vtp");
      if (!std::filesystem::exists(file)) {
        throw Error("wall cloud '" + wallName + "' is neither in time " + time_.startTimeName() +
                    " nor in constant/particles (run particleizeMold)");
      }
      staticClouds_.push_back(readCloudVtp(file, wallName));
    }
    for (const ParticleCloud& wall : staticClouds_) wallClouds_.push_back(&wall);
    for (const ParticleCloud* wall : wallClouds_) neighbourhood_->addFixedCloud(*wall);
  }
  for (const std::string& name : heatSetup_.clouds) {
    ParticleCloud& cloud = cloudNamed(name);
    neighbourhood_->addCloud(cloud, Neighbourhood::Motion::fixed);  // no-op for the fluid
    if (std::find(evolving_.begin(), evolving_.end(), &cloud) == evolving_.end()) {
      evolving_.push_back(&cloud);
    }
  }
  for (ParticleCloud* cloud : evolving_) lastGood_.push_back(*cloud);
}

void CastingSolver::setUpFlow() {
  ParticleCloud& fluid = cloudNamed(flowSetup_.fluidCloud);
  if (solidificationSetup_.enabled) {
    flowSetup_.settings.cavitationPressure = solidificationSetup_.cavitationPressure;
  }
  for (const std::string& added : prepareFluidFields(flowSetup_, fluid)) {
    info() << "Cloud " << fluid.name() << ": initial " << added << " from constant/\n";
  }
  const std::vector<const ParticleCloud*>& walls = wallClouds_;
  flow_ =
      std::make_unique<WeaklyCompressibleFlow>(flowSetup_.settings, fluid, walls, *neighbourhood_);
  fluid_ = &fluid;
  if (!walls.empty()) fillTime_ = std::make_unique<FillTime>(fluid, walls);
  domain_ = walls.empty() ? defaultDomain({&fluid}) : defaultDomain(walls);
  const FlowSettings& settings = flowSetup_.settings;
  info() << "Flow: weakly compressible SPH (" << settings.dimension << "D), densityScheme "
         << settings.densityScheme << ", kernelCorrection "
         << (settings.kernelCorrection ? "on" : "off") << ", viscousForm " << settings.viscousForm
         << ", h = " << settings.supportRadius << " m, c = " << settings.soundSpeed << " m/s\n"
         << "    fluid " << fluid.name() << ": " << fluid.size() << " particles\n";
  for (const ParticleCloud* wall : walls) {
    info() << "    wall " << wall->name() << ": " << wall->size() << " particles\n";
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (!settings.periodic.isPeriodic(axis)) continue;
    info() << "    periodic "
           << "xyz"[axis] << ": [" << settings.periodic.lower(axis) << ", "
           << settings.periodic.lower(axis) + settings.periodic.period(axis) << ")\n";
  }
  const Eigen::IOFormat plain(Eigen::StreamPrecision, Eigen::DontAlignCols, " ", " ");
  info() << "    domain (" << domain_.lower.transpose().format(plain) << ") ("
         << domain_.upper.transpose().format(plain)
         << "): a particle outside it, or not finite, stops the run\n"
         << "    health checks: density deviation warned above "
         << 100 * health_.warnDensityDeviation << " %, stops above "
         << 100 * health_.maxDensityDeviation << " %; a particle " << health_.maxWallPenetration
         << " dx behind a wall surface, or a stable step below " << health_.minDeltaTFraction
         << " of its running mean, stops the run\n"
         << "    wall clearance " << settings.wallClearance
         << " dx: fluid particles closer to a wall surface are moved back to it\n";
  const SoundSpeedCheck soundSpeed = checkSoundSpeed(settings, fluid, walls);
  if (soundSpeed.tooLow) {
    warning(soundSpeed.message);
  } else {
    info() << "    " << soundSpeed.message << '\n';
  }
  if (surfaceTensionSetup_.enabled) {
    SurfaceTensionSettings tension = surfaceTensionSetup_.settings;
    tension.spacing = static_cast<Real>(fluid.attributes().at("spacing"));
    surfaceTension_ =
        std::make_unique<SurfaceEnergyTension>(tension, fluid, walls, *neighbourhood_);
    flow_->addForceModel(*surfaceTension_);
    const TemperatureTable& gamma = *tension.gasTension;
    info() << "Surface tension: surface energy (paper eqs. (7)-(12)), R_d = "
           << surfaceTension_->energyFactor()
           << (tension.energyFactor > 0 ? "" : " (calibrated on a relaxed surface)") << ", Gamma_g "
           << gamma.description()
           << (gamma.isConstant() ? " = " + std::to_string(gamma(0)) + " N/m" : " (a table in T)")
           << '\n';
    const double compression = surfaceTension_->surfaceCompression(settings.soundSpeed);
    info() << "    surface layer's compression R_d Gamma_g / (rho c^2 dx) = " << 100 * compression
           << " % (at the particles' T now)\n";
    if (compression > 0.03) {
      warning("the surface tension compresses the surface layer by " +
              std::to_string(100 * compression) +
              " % of its density (R_d Gamma_g / (rho c^2 dx)): raise soundSpeed in system/sphSchemes "
              "towards " +
              std::to_string(settings.soundSpeed * std::sqrt(compression / 0.01)) +
              " m/s for 1 %; the calibration of R_d was measured at 0.3 to 3 %");
    }
    if (!walls.empty()) {
      info() << "    at the walls: "
             << (tension.solidTension
                     ? "Gamma_s = " + std::to_string(*tension.solidTension) + " N/m"
                     : "contact angle " +
                           std::to_string(
                               std::acos(static_cast<double>(
                                   tension.cosContactAngle ? *tension.cosContactAngle : Real(-1))) *
                               180 / std::numbers::pi) +
                           " degrees")
             << ", chi over "
             << (tension.wallSmoothing > 0 ? tension.wallSmoothing : tension.supportRadius)
             << " m\n";
    }
  }
  // Everything else stays where it is: only the fluid moves.
}

void CastingSolver::setUpHeat() {
  HeatTransferContext context;
  context.dimension = flowSetup_.enabled ? flowSetup_.settings.dimension : heatSetup_.dimension;
  context.supportRadius = neighbourhood_->radius();
  context.neighbourhood = neighbourhood_.get();
  double spacing = 0;
  for (const std::string& name : heatSetup_.clouds) {
    ParticleCloud& cloud = cloudNamed(name);
    HeatCloud heat{&cloud, &heatSetup_.materialOf(name), false, 0, {}};
    if (const auto held = heatSetup_.fixedTemperature.find(name);
        held != heatSetup_.fixedTemperature.end()) {
      heat.fixedTemperature = true;
      heat.heldTemperature = held->second;
    }
    if (const auto patches = heatSetup_.heldPatches.find(name);
        patches != heatSetup_.heldPatches.end()) {
      heat.heldPatches = patches->second;
    }
    const auto attribute = cloud.attributes().find("spacing");
    if (attribute == cloud.attributes().end() || !(attribute->second > 0)) {
      throw Error("heat cloud '" + name +
                  "' has no positive 'spacing' attribute (the particle spacing, which "
                  "particleizeMold and setCastFields write)");
    }
    // the finest cloud sets the regularisation and the step limits
    spacing = spacing == 0 ? attribute->second : std::min(spacing, attribute->second);
    context.clouds.push_back(heat);
  }
  context.spacing = static_cast<Real>(spacing);
  energy_ = std::make_unique<EnergyEquation>(context, heatSetup_.heatTransfer);
  if (energy_->needsExposedArea()) {
    std::vector<ParticleCloud*> exposed;
    std::vector<const ParticleCloud*> covering;
    exposedAreaRestored_ = energy_->restarted();
    for (const HeatCloud& heat : energy_->context().clouds) {
      exposedAreaRestored_ = exposedAreaRestored_ && heat.cloud->hasScalarField("exposedArea");
      exposed.push_back(heat.cloud);
      covering.push_back(heat.cloud);
    }
    for (const ParticleCloud* wall : wallClouds_) {
      if (std::find(covering.begin(), covering.end(), wall) == covering.end()) {
        covering.push_back(wall);
      }
    }
    exposedArea_ = std::make_unique<ExposedArea>(energy_->exposedAreaForm(), context.dimension,
                                                 context.supportRadius, context.spacing, exposed,
                                                 covering, *neighbourhood_);
  }
  info() << "Heat transfer: energy equation (17) on";
  for (const HeatCloud& heat : energy_->context().clouds) {
    info() << ' ' << heat.cloud->name() << " (" << heat.material->name;
    if (heat.fixedTemperature) info() << ", held at " << heat.heldTemperature << " K";
    for (std::size_t p = 0; p < heat.heldPatches.size(); ++p) {
      info() << ", patch " << heatSetup_.heldPatchNames.at(heat.cloud->name())[p] << " held at "
             << heat.heldPatches[p].second << " K";
    }
    info() << ')';
  }
  info() << '\n';
  for (const std::string& line : energy_->descriptions()) info() << "    " << line << '\n';
  if (exposedArea_) {
    info() << "    exposed area A_i ("
           << (energy_->exposedAreaForm() == ExposedAreaForm::gradient ? "gradient of s_i"
                                                                       : "eq. 11")
           << ") with R_A = " << exposedArea_->areaFactor()
           << " (a flat surface counts its area)\n";
  }
  if (!flowSetup_.enabled) info() << "    no flow: the particles stay where they are\n";
}

// The fluid's rho_s, mu and solid fraction from its T before the flow's start state is computed
// (a restart gets the same values: a frozen particle's rho_s is read back, the others follow T).
void CastingSolver::setUpSolidification() {
  SolidificationSettings settings = solidificationSetup_.settings;
  const Material& material = *solidificationSetup_.material;
  ParticleCloud& metal = cloudNamed(solidificationSetup_.cloud);
  if (flow_) {
    const FlowSettings& flow = flowSetup_.settings;
    const double spacing = fluid_->attributes().at("spacing");
    // 0.9 of the viscosity whose explicit limit 0.125 dx^2 rho / mu is the acoustic step
    // maxCo dx / c (SolidificationSetup.h)
    const double liquidDensity = (*material.density)(material.freezingRange->liquidus);
    settings.viscosityLimit = static_cast<Real>(0.9 * 0.125 * liquidDensity * spacing *
                                                flow.soundSpeed / time_.settings().maxCo);
  }
  solidification_ = std::make_unique<Solidification>(settings, material, metal);
  neighbourhood_->requestPairs(metal, metal);  // for G at T_c (recordCriticalGradients)
  solidification_->update(time_.value(), 0.0);
  if (const auto mode = metal.attributes().find("coolingMode"); mode != metal.attributes().end()) {
    cooling_ = solidificationSetup_.cooling && mode->second != 0;
  }
  info() << "Solidification: " << solidification_->description() << '\n';
  if (flow_) {
    info() << "    frozen particles stay where they are (wall for the melt; their own "
              "contraction moves nothing); melt below "
           << flowSetup_.settings.cavitationPressure << " Pa opens a cavity\n";
  } else {
    info() << "    no flow: the metal conducts and solidifies where it is\n";
  }
  logSolidification();
}

// G = |grad T| of the particles that have just crossed T_c (Solidification.h), from the pairs
// of the last search: the positions the heat step used.
void CastingSolver::recordCriticalGradients() {
  const std::vector<std::size_t> pending = solidification_->pendingCriticalGradients();
  if (pending.empty()) return;
  ParticleCloud& metal = cloudNamed(solidificationSetup_.cloud);
  const int dimension = flow_ ? flowSetup_.settings.dimension : heatSetup_.dimension;
  const std::vector<Real> volume = particleVolumes(metal, dimension);
  const NeighbourList& pairs = neighbourhood_->pairs(metal, metal);
  auto& gradient = metal.scalarField("criticalGradient");
  const auto& T = metal.scalarField("T");
  for (const std::size_t i : pending) {
    gradient[i] = correctedGradient(metal, T, volume, pairs, neighbourhood_->periodicBox(),
                                    neighbourhood_->radius(), dimension, i)
                      .norm();
  }
}

// The first search and the rates of the start state (a restart keeps the order and the rates
// it was written with).
void CastingSolver::startModels() {
  const bool restarted = (flow_ && flow_->restarted()) || (energy_ && energy_->restarted());
  addWallTime(searchSeconds_,
              [&] { neighbourhood_->update(restarted ? CloudOrder::keep : CloudOrder::byCell); });
  // a restart has the contacts up to its time already (the next search is the next step's)
  if (fillTime_ && !restarted) fillTime_->record(*neighbourhood_, time_.value());
  if (solidification_) recordCriticalGradients();
  // A restart keeps the A_i it was written with: summed again over neighbour lists in another
  // order (the wall clearance moves particles after the search) they could differ in the last
  // bit.
  if (exposedArea_ && !exposedAreaRestored_) exposedArea_->compute();
  if (flow_) flow_->start();
  if (energy_) energy_->start();
  info() << "    neighbourhood: " << neighbourhood_->pairCount() << " pairs\n";
}

void CastingSolver::setUpFunctionObjects(const Dictionary& controlDict) {
  FunctionObjectContext context;
  context.caseRoot = caseFolder_.root();
  context.startTimeName = time_.startTimeName();
  context.startTime = time_.startValue();
  context.supportRadius = flowSetup_.enabled ? flowSetup_.settings.supportRadius : Real(0);
  context.gravity = gravity_;
  for (const ParticleCloud& cloud : clouds_) context.clouds.push_back(&cloud);
  functions_ = FunctionObjectList(controlDict, context);
  for (const auto& object : functions_.objects()) {
    info() << "Function object " << object->name() << ": postProcessing/" << object->name() << '/'
           << time_.startTimeName() << '\n';
  }
}

double CastingSolver::stableDeltaT(std::string& limiter) const {
  if (cooling_) {  // the flow takes its own steps within (evolveCooling)
    const double heat = energy_->stableDeltaT(limiter);
    limiter += " (cooling)";
    return heat;
  }
  if (flow_ || energy_) {
    double stable = std::numeric_limits<double>::infinity();
    if (flow_) stable = flow_->stepLimits(time_.settings().maxCo).smallest(limiter);
    // with a flow and `interval auto` the heat takes steps of its own (heatStepsWithFlow)
    if (energy_ && (!flow_ || heatSetup_.heatEveryFlowStep)) {
      std::string heatLimiter;
      const double heat = energy_->stableDeltaT(heatLimiter);
      if (heat < stable) {
        stable = heat;
        limiter = heatLimiter;
      }
    }
    return stable;
  }
  limiter = "maxCo on particle travel";
  double stable = std::numeric_limits<double>::max();
  for (const ParticleCloud& cloud : clouds_) {
    if (cloud.hasVectorField("U")) {
      stable = std::min(stable, motion_.stableDeltaT(cloud, time_.settings().maxCo));
    }
  }
  return stable;
}

// One step: the models' passes over one neighbourhood search, kick-drift-kick.
void CastingSolver::evolve(double deltaT) {
  if (cooling_) {
    evolveCooling(deltaT);
    return;
  }
  if (!flow_ && !energy_) {
    for (ParticleCloud& cloud : clouds_) {
      if (cloud.hasVectorField("U")) motion_.step(cloud, deltaT);
    }
    return;
  }
  const bool heatThisStep = energy_ && heatStepsWithFlow(deltaT);
  // the first kicks with the rates of the current state, and the drift
  if (flow_) flow_->kickAndDrift(deltaT);
  if (heatThisStep) addWallTime(heatSeconds_, [&] { energy_->halfKick(heatDeltaT_); });
  // the search at the new positions (nothing moves without a flow), the quantities models share
  if (flow_) {
    addWallTime(searchSeconds_, [&] { neighbourhood_->update(); });
    if (fillTime_) fillTime_->record(*neighbourhood_, time_.value());
    flow_->keepClearOfWalls();
  }
  if (heatThisStep && flow_ && exposedArea_) {
    addWallTime(heatSeconds_, [&] { exposedArea_->compute(); });
  }
  // the rates at the new positions and the second kicks
  if (flow_) flow_->computeRatesAndKick(deltaT);
  if (heatThisStep) {
    addWallTime(heatSeconds_, [&] {
      energy_->computeRates();
      energy_->halfKick(heatDeltaT_);
      if (solidification_) {
        solidification_->update(time_.value(), heatDeltaT_);
        recordCriticalGradients();
      }
    });
    ++heatSteps_;
  }
}

// A stop between heat steps (stopAt writeNow) writes the heat brought up to the time written.
void CastingSolver::flushPendingHeat() {
  if (!energy_ || pendingHeatTime_ == 0) return;
  heatDeltaT_ = pendingHeatTime_;
  pendingHeatTime_ = 0;
  addWallTime(heatSeconds_, [&] {
    energy_->halfKick(heatDeltaT_);
    if (exposedArea_) exposedArea_->compute();
    energy_->computeRates();
    energy_->halfKick(heatDeltaT_);
    if (solidification_) {
      solidification_->update(time_.value(), heatDeltaT_);
      recordCriticalGradients();
    }
  });
  ++heatSteps_;
}

// Once the melt is still, the heat sets the pace (doc/physics.md §10.5): a step of the
// heat's stable length with the particles where they are, then flowStepsPerHeatStep flow steps
// of the acoustic length, in which the melt answers the rho_s the heat step changed (shrinkage
// feeding). The flow's time thus runs heat step / (n acoustic steps) times slower than the heat's:
// right for a melt that creeps, wrong for one that moves (updateCoolingMode leaves the mode then).
void CastingSolver::evolveCooling(double deltaT) {
  heatDeltaT_ = deltaT;
  addWallTime(heatSeconds_, [&] {
    energy_->halfKick(deltaT);
    if (exposedArea_) exposedArea_->compute();
    energy_->computeRates();
    energy_->halfKick(deltaT);
    solidification_->update(time_.value(), deltaT);
    recordCriticalGradients();
  });
  ++heatSteps_;
  for (int k = 0; k < solidificationSetup_.cooling->flowStepsPerHeatStep; ++k) {
    std::string limiter;
    const double flowDeltaT = flow_->stepLimits(time_.settings().maxCo).smallest(limiter);
    if (!(flowDeltaT > 0) || !std::isfinite(flowDeltaT)) {
      std::ostringstream problem;
      problem << "the flow's stable step (" << limiter << ") is " << flowDeltaT;
      throw Error(problem.str());
    }
    flow_->kickAndDrift(flowDeltaT);
    addWallTime(searchSeconds_, [&] { neighbourhood_->update(); });
    if (fillTime_) fillTime_->record(*neighbourhood_, time_.value());
    flow_->keepClearOfWalls();
    flow_->computeRatesAndKick(flowDeltaT);
    ++flowSubSteps_;
    lastFlowSubStep_ = flowDeltaT;
  }
}

// Enters the cooling mode when the melt is still (max|U| below stillSpeed), leaves it when the
// melt moves fast (above movingSpeed: a collapse), at the start of a step: the decision depends
// on the state only (and the mode, which the fluid carries as an attribute), so a restart takes
// the same one.
void CastingSolver::updateCoolingMode() {
  if (!solidification_ || !solidificationSetup_.cooling) return;
  const CoolingAcceleration& cooling = *solidificationSetup_.cooling;
  double fastest = 0;
  for (const Vector& v : fluid_->vectorField("U")) {
    fastest = std::max(fastest, static_cast<double>(v.norm()));
  }
  const bool wasCooling = cooling_;
  if (!cooling_ && fastest < cooling.stillSpeed) cooling_ = true;
  if (cooling_ && fastest > cooling.movingSpeed) cooling_ = false;
  if (cooling_ == wasCooling) return;
  fluid_->attributes()["coolingMode"] = cooling_ ? 1 : 0;
  meanStableDeltaT_ = 0;  // the steps change length by design
  if (cooling_) {
    flushPendingHeat();
    info() << "Cooling from time " << time_.timeName() << ": the melt is still (max|U| "
           << fastest << " m/s < " << cooling.stillSpeed << "): steps of the heat's length, each "
           << "followed by " << cooling.flowStepsPerHeatStep << " acoustic flow steps\n\n";
  } else {
    info() << "Cooling paused at time " << time_.timeName() << ": the melt moves (max|U| "
           << fastest << " m/s > " << cooling.movingSpeed
           << "): every step acoustic again\n\n";
  }
}

// Whether the heat paths run in this step, and over what time (heatDeltaT_). Without a flow,
// or with `interval everyStep`, every step is a heat step of the step's length. Otherwise the
// flow's steps (far shorter: acoustic, against the diffusion limit) add up until they reach
// heatStepFraction of the heat's own stable step, and the heat then takes one step of their
// sum at the positions of the end (the particles carry their u as they move; what lags is only
// the exchange between them, by at most that sum). Every written time is a heat step, so that
// a restart from it starts with nothing pending and reproduces the uninterrupted run.
//
// The fraction, measured (a half-full sphere of AC4CH at 900 K sloshing in an iron mold at
// 300 K, conduction and contact, 0.2 s, 2,621 flow steps; the largest change of T from the
// start is 16.4 K in the metal, 18.3 K in the mold): against heat at every flow step, the
// largest difference of a metal particle's T at 0.2 s is 1.20 / 0.61 / 0.13 / 0.015 K (mean
// 0.15 / 0.074 / 0.017 / 0.0025 K) with the fraction 0.5 / 0.25 / 0.1 / 0.03, in 10 / 20 /
// 50 / 141 heat steps: the error of the big steps is first order in their length, the steep
// start of a contact being what they resolve worst. 0.1 costs 50 heat steps instead of 2,621
// (0.25 s of heat in a 21 s run, against 13.4 s of a 35 s run).
bool CastingSolver::heatStepsWithFlow(double deltaT) {
  constexpr double heatStepFraction = 0.1;
  if (!flow_ || heatSetup_.heatEveryFlowStep) {
    heatDeltaT_ = deltaT;
    return true;
  }
  if (heatStepDue_ == 0) {  // the first, or just after a heat step: the limit of that state
    std::string limiter;
    heatStepDue_ = heatStepFraction * energy_->stableDeltaT(limiter);
  }
  pendingHeatTime_ += deltaT;
  if (pendingHeatTime_ < heatStepDue_ && !time_.writeTime() && time_.progress() < 1) return false;
  heatDeltaT_ = pendingHeatTime_;
  pendingHeatTime_ = 0;
  heatStepDue_ = 0;
  return true;
}

void CastingSolver::writeResults() {
  std::vector<const ParticleCloud*> written;
  for (const ParticleCloud& cloud : clouds_) written.push_back(&cloud);
  writer_.setPurgeWrite(time_.settings().purgeWrite);
  writer_.write(time_.state(), written);
  info() << "Writing time " << time_.timeName() << std::endl;
}

void CastingSolver::logStep(bool printBlock) {
  if (!printBlock) return;
  info() << "deltaT = " << time_.deltaT() << "  (" << time_.deltaTLimiter() << ")\n"
         << "Time = " << time_.timeName() << "\n\n";
  if (flow_) {
    const FluidSummary summary = summarizeFluid(*fluid_);
    const FlowSettings& settings = flowSetup_.settings;
    const double spacing = fluid_->attributes().at("spacing");
    const double courant = (static_cast<double>(settings.soundSpeed) + summary.largestSpeed) *
                           time_.deltaT() / spacing;
    std::ostringstream line;
    line.precision(6);
    line << "Step " << time_.timeIndex() << "  Courant " << courant << "  max|U| "
         << summary.largestSpeed << " m/s  Mach "
         << summary.largestSpeed / static_cast<double>(settings.soundSpeed) << '\n'
         << "Density range " << summary.lowestDensity << " .. " << summary.highestDensity
         << " kg/m^3 (" << 100 * summary.lowestDeviation << " .. " << 100 * summary.highestDeviation
         << " % of rho_s)  p " << summary.lowestPressure << " .. " << summary.highestPressure
         << " Pa\n"
         << "Mass " << summary.mass << " kg  kinetic energy " << summary.kineticEnergy
         << " J  moved back from walls " << flow_->lastWallClearance().corrected << '\n';
    info() << line.str();
  }
  if (energy_) logHeat();
  if (solidification_) logSolidification();
  info() << clock_.timesLine() << '\n'
         << clock_.progressLine(time_.progress(), stepsTaken_, solidEnd()) << '\n'
         << std::endl;  // flushed: a killed run's log ends at its last step
}

void CastingSolver::logHeat() {
  std::ostringstream line;
  line.precision(6);
  if (flow_) {
    std::string limiter;
    const double limit = energy_->stableDeltaT(limiter);
    line << "Heat: " << heatSteps_ << " heat steps in " << stepsTaken_ << " steps ("
         << (cooling_ ? "cooling" : heatSetup_.heatEveryFlowStep ? "every flow step" : "interval auto")
         << ", the last "
         << heatDeltaT_ << " s long; " << limiter << " limit " << limit << " s)\n";
  }
  for (const HeatCloud& heat : energy_->context().clouds) {
    if (heat.fixedTemperature) continue;
    const auto& T = heat.cloud->scalarField("T");
    const auto& u = heat.cloud->scalarField("u");
    const auto& mass = heat.cloud->scalarField("mass");
    double lowest = std::numeric_limits<double>::infinity(), highest = -lowest, energy = 0;
    for (std::size_t i = 0; i < T.size(); ++i) {
      lowest = std::min(lowest, double(T[i]));
      highest = std::max(highest, double(T[i]));
      energy += double(mass[i]) * double(u[i]);
    }
    line << "T " << heat.cloud->name() << ' ' << lowest << " .. " << highest
         << " K  internal energy " << energy << " J\n";
  }
  info() << line.str();
}

std::optional<std::pair<double, std::string>> CastingSolver::solidEnd() const {
  if (!solidification_ || !solidificationSetup_.endWhenSolid) return std::nullopt;
  const auto seconds = solidEstimate_.secondsLeft();
  if (!seconds) return std::nullopt;
  return std::make_pair(*seconds, std::string("all solid, endWhenSolid"));
}

void CastingSolver::logSolidification() {
  const SolidificationSummary s = solidification_->summary();
  std::ostringstream line;
  line.precision(4);
  line << "Solidification: solid fraction " << s.solidFraction << " (by mass); of "
       << s.particles << " particles " << s.liquid << " liquid, " << s.frozen << " frozen ("
       << s.solid << " fully solid), " << s.particles - s.frozen << " flowing";
  if (s.viscosityCapped > 0) line << " (" << s.viscosityCapped << " with mu capped)";
  // with endWhenSolid the run ends with the last liquid, not at endTime: the progress line's
  // ETA follows the rise of the solid fraction (CompletionEstimate)
  if (solidificationSetup_.endWhenSolid) solidEstimate_.add(clock_.clockTime(), s.solidFraction);
  if (cooling_) {
    line << "\n    cooling: heat steps of " << heatDeltaT_ << " s, each with "
         << solidificationSetup_.cooling->flowStepsPerHeatStep << " flow steps (the last "
         << lastFlowSubStep_ << " s); " << flowSubSteps_ << " flow steps so far";
  }
  info() << line.str() << '\n';
}

void CastingSolver::logTimeSpent() {
  std::ostringstream line;
  line.precision(3);
  line << "Time spent (wall, s):";
  if (neighbourhood_) line << " neighbour search " << searchSeconds_ << ",";
  if (flow_) {
    const FlowTimings& t = flow_->timings();
    line << " wall clearance " << t.wallClearance << ", flow rates " << t.rates;
    if (surfaceTension_) line << " (surface tension " << surfaceTension_->seconds() << ")";
    line << ", flow integration " << t.integration << ",";
  }
  if (energy_) line << " heat " << heatSeconds_ << ",";
  line << " health checks " << checkSeconds_ << ", function objects " << functionSeconds_
       << ", output " << outputSeconds_;
  info() << line.str() << '\n' << "Run health: " << warnings_.summary() << '\n';
}

void CastingSolver::logRereadMessage() {
  const std::string message = time_.takeRereadMessage();
  if (!message.empty()) info() << message << "\n\n";
}

std::string CastingSolver::checkHealth() {
  std::ostringstream problem;
  problem.precision(4);
  for (const ParticleCloud& cloud : clouds_) {
    if (!cloud.hasVectorField("U")) continue;  // at rest: nothing to go bad
    const bool cavities = &cloud == fluid_ && flowSetup_.settings.cavitationPressure >
                                                   std::numeric_limits<Real>::lowest();
    const CloudHealth health = measureCloudHealth(cloud, domain_, cavities);
    if (!health.finiteAndInside()) {
      problem << health.outside << " particle(s) of cloud '" << cloud.name()
              << "' left the domain and " << health.nonFinite << " went non-finite; the first, "
              << describeParticle(cloud, health.firstBad, health.firstBadPosition);
      return problem.str();
    }
    // only the flow evolves the density (a ballistic cloud carries its start value)
    if (!health.hasDensity || &cloud != fluid_) continue;
    const double deviation = health.largestDensityDeviation;
    if (deviation <= health_.warnDensityDeviation) continue;
    const std::string where =
        describeParticle(cloud, health.mostDeviating, health.mostDeviatingPosition);
    if (deviation > health_.maxDensityDeviation) {
      problem << "the density of " << where << " deviates by " << 100 * deviation
              << " % from rho_s (healthChecks maxDensityDeviation "
              << 100 * health_.maxDensityDeviation << " %)";
      return problem.str();
    }
    if (warnings_.shouldPrint("density deviation above " +
                                  std::to_string(std::lround(100 * health_.warnDensityDeviation)) +
                                  " %",
                              deviation)) {
      std::ostringstream message;
      message.precision(4);
      message << "time " << time_.timeName() << " (step " << time_.timeIndex()
              << "): the density of " << where << " deviates by " << 100 * deviation
              << " % from rho_s; a larger soundSpeed (c >= 10 |U|max) keeps it smaller";
      warning(message.str());
    }
  }
  if (energy_) {
    const std::string bad = checkTemperatures();
    if (!bad.empty()) return bad;
  }
  if (flow_) {
    const WallClearanceReport& clearance = flow_->lastWallClearance();
    const double spacing = fluid_->attributes().at("spacing");
    const double depth = static_cast<double>(clearance.deepest) / spacing;
    if (clearance.beyondSurface > 0) {
      const std::string where =
          describeParticle(*fluid_, clearance.deepestParticle, clearance.deepestPosition);
      if (depth > health_.maxWallPenetration) {
        problem << where << " was " << depth
                << " dx behind a wall surface after the step (healthChecks maxWallPenetration "
                << health_.maxWallPenetration << " dx): it went through the wall";
        return problem.str();
      }
      if (warnings_.shouldPrint("fluid pushed back out of a wall", depth)) {
        std::ostringstream message;
        message.precision(4);
        message << "time " << time_.timeName() << " (step " << time_.timeIndex()
                << "): " << clearance.beyondSurface
                << " fluid particle(s) reached behind a wall surface"
                << " and were moved back in front of it; the deepest, " << where << ", " << depth
                << " dx behind";
        warning(message.str());
      }
    }
  }
  return "";
}

// A temperature that is not finite or not above 0 K: the energy equation went unstable (a step
// past its limits) or a table was extrapolated far beyond its range.
std::string CastingSolver::checkTemperatures() const {
  for (const HeatCloud& heat : energy_->context().clouds) {
    const auto& T = heat.cloud->scalarField("T");
    for (std::size_t i = 0; i < T.size(); ++i) {
      if (T[i] > 0 && std::isfinite(T[i])) continue;
      std::ostringstream problem;
      problem << "the temperature of "
              << describeParticle(*heat.cloud, i, heat.cloud->positions()[i]) << " is " << T[i]
              << " K";
      return problem.str();
    }
  }
  return "";
}

std::string CastingSolver::checkStepCollapse(double stableDeltaT, const std::string& limiter) {
  if (!time_.settings().adjustTimeStep) return "";
  if (!(stableDeltaT > 0) || !std::isfinite(stableDeltaT)) {
    std::ostringstream problem;
    problem << "the stable time step (" << limiter << ") is " << stableDeltaT;
    return problem.str();
  }
  if (meanStableDeltaT_ > 0 && stableDeltaT < health_.minDeltaTFraction * meanStableDeltaT_) {
    std::ostringstream problem;
    problem.precision(4);
    problem << "the stable time step collapsed to " << stableDeltaT << " s (" << limiter
            << "), below " << health_.minDeltaTFraction << " of its running mean "
            << meanStableDeltaT_ << " s (healthChecks minDeltaTFraction)";
    return problem.str();
  }
  // a mean over about the last 100 steps
  meanStableDeltaT_ =
      meanStableDeltaT_ > 0 ? 0.99 * meanStableDeltaT_ + 0.01 * stableDeltaT : stableDeltaT;
  return "";
}

void CastingSolver::stopWithLastGoodState(const TimeState& good, bool restoreSaved,
                                          const std::string& what) {
  const std::string badTime = time_.timeName();
  const long badIndex = time_.timeIndex();
  logTimeSpent();
  const std::string failure =
      "at time " + badTime + " (step " + std::to_string(badIndex) + "): " + what + ". ";
  // Only the models keep the state before the step; ballistic clouds have nothing to go back
  // to.
  if (restoreSaved && evolving_.empty()) {
    throw Error(failure + "Nothing is written: the last written time is the last good state.");
  }
  // The start time is on disk as it was read: rewriting it would store the rates of this run's
  // settings in it, and a rerun with other settings would start from them.
  if (good.name == time_.startTimeName()) {
    throw Error(failure + "The last good state is the start time " + good.name +
                ", left as it was; change maxCo, deltaT or soundSpeed and run again.");
  }
  if (restoreSaved) {
    for (std::size_t c = 0; c < evolving_.size(); ++c) *evolving_[c] = lastGood_[c];
  }
  std::vector<const ParticleCloud*> written;
  for (const ParticleCloud& cloud : clouds_) written.push_back(&cloud);
  writer_.write(good, written);
  throw Error(failure + "The last good state, time " + good.name +
              ", is written (it passed every check); restart from it with a smaller maxCo or "
              "deltaT, a larger soundSpeed, or look for a gap in the walls there.");
}

void CastingSolver::run() {
  info() << "Starting time loop\n\n";
  functions_.execute(time_.state(), false);
  while (time_.run()) {
    logRereadMessage();
    updateCoolingMode();
    std::string limiter;
    const double stable = stableDeltaT(limiter);
    if (const std::string collapse = checkStepCollapse(stable, limiter); !collapse.empty()) {
      stopWithLastGoodState(time_.state(), false, collapse);  // this state passed every check
    }
    time_.adjustDeltaT(stable, limiter);
    if (!time_.settings().adjustTimeStep && (flow_ || energy_) && time_.deltaT() > stable &&
        warnings_.shouldPrint("a fixed deltaT above the stable step", time_.deltaT() / stable)) {
      std::ostringstream message;
      message.precision(4);
      message << "time " << time_.timeName() << ": the fixed deltaT " << time_.deltaT() << " s is "
              << time_.deltaT() / stable << " times the stable step " << stable << " s (" << limiter
              << "); set adjustTimeStep yes, or a smaller deltaT";
      warning(message.str());
    }
    const TimeState before = time_.state();
    // reuses their storage: no allocation per step
    for (std::size_t c = 0; c < evolving_.size(); ++c) lastGood_[c] = *evolving_[c];
    time_.advance();
    ++stepsTaken_;
    // A step that throws (a far-flung particle the cell grid cannot place, memory exhausted)
    // stops the run the same way as a failed check: with the last good state written.
    std::string failure;
    try {
      evolve(time_.deltaT());
    } catch (const std::bad_alloc&) {
      failure = "the step ran out of memory";
    } catch (const std::exception& error) {
      failure = std::string("the step failed: ") + error.what();
    }
    if (failure.empty()) failure = addWallTime(checkSeconds_, [&] { return checkHealth(); });
    if (!failure.empty()) stopWithLastGoodState(before, true, failure);
    if (solidificationSetup_.endWhenSolid && solidification_->allSolid()) {
      time_.requestStop("the casting is solid (endWhenSolid)");
    }
    const bool printBlock = stepsTaken_ % time_.settings().logInterval == 0 || time_.writeTime();
    logStep(printBlock);
    if (time_.writeTime()) addWallTime(outputSeconds_, [&] { writeResults(); });
    addWallTime(functionSeconds_, [&] { functions_.execute(time_.state(), time_.writeTime()); });
  }
  logRereadMessage();
  info() << "Stopping: " << time_.stopReason() << " at time " << time_.timeName() << '\n';
  if (time_.finalWriteWanted()) {
    flushPendingHeat();
    addWallTime(outputSeconds_, [&] { writeResults(); });
  }
  logTimeSpent();
  info() << clock_.timesLine() << "\n\nEnd\n\n";
}

}  // namespace sphcast
