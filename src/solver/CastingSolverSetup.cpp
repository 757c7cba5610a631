// The solver's construction: the case's clouds, the neighbourhood and every model of the step
// set up from the dictionaries, the first time written again with their fields.
#include "particles/FieldNames.h"
#include "solver/CastingSolver.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <ostream>

#include "core/Error.h"
#include "core/Gravity.h"
#include "core/dictionary/Dictionary.h"
#include "io/VtpCloud.h"
#include "parallel/ParticleTransfer.h"
#include "sph/CorrectedGradient.h"

namespace sphcast {

namespace {
// postProcessing/dynamicBodies/<startTime>/<body>.dat (post/BodyHistory.h)
constexpr const char* bodyHistoryName = "dynamicBodies";

// Rank 0 repairs what a killed write left; the others wait for it before they look for times.
std::vector<std::string> repairInterruptedWrites(const CaseFolder& caseFolder,
                                                 const Communicator& comm) {
  std::vector<std::string> repaired;
  if (comm.master()) repaired = caseFolder.recoverInterruptedWrites();
  comm.barrier();
  return repaired;
}
}  // namespace

CastingSolver::CastingSolver(const CaseFolder& caseFolder, const Communicator& comm)
    : caseFolder_(caseFolder),
      comm_(comm),
      parallel_(comm.size() > 1),
      repairedWrites_(repairInterruptedWrites(caseFolder, comm)),
      time_(caseFolder),
      description_(caseFolder),
      // constant/g for a flow or ballistic clouds; a case that only conducts heat needs none
      gravity_(description_.gravity().value_or(Vector::Zero())),
      motion_(gravity_),
      flowSetup_(readFlowSetup(description_)),
      heatSetup_(readHeatSetup(description_)),
      surfaceTensionSetup_(readSurfaceTensionSetup(description_)),
      solidificationSetup_(readSolidificationSetup(description_)),
      bodySetup_(readBodySetup(description_)),
      inletSetup_(readInletSetup(description_)),
      heatSchedule_(!flowSetup_.enabled || heatSetup_.heatEveryFlowStep),
      monitor_(models_, time_, comm_, heatSchedule_, flowSetup_, heatSetup_, solidificationSetup_),
      writer_(caseFolder, time_.settings().purgeWrite, comm) {
  if (parallel_) {
    time_.agreeOnChanges([this](bool changed) { return comm_.any(changed); },
                         [this](const std::string& text) { return comm_.firstNonEmpty(text); });
  }
  for (const std::string& repaired : repairedWrites_) {
    info() << "Repaired interrupted write: " << repaired << std::endl;
  }
  info() << "Starting from time " << time_.startTimeName() << " (index " << time_.timeIndex()
         << ")\n";
  clouds_ = readTimeFolderClouds(caseFolder_, time_.startTimeName(), comm_);
  if (clouds_.empty()) {
    throw Error("time folder " + (caseFolder_.root() / time_.startTimeName()).string() +
                " holds no cloud (.vtp) to run");
  }
  const std::vector<std::string> startFields = fieldInventory(clouds_);
  // controlDict's entries beyond run control (TimeControl's), read once
  const Dictionary controlDict = Dictionary::read(caseFolder_.systemFile("controlDict"));
  monitor_.setHealthSettings(HealthSettings::read(controlDict));
  if (parallel_) checkParallelSupport();
  // Clouds join clouds_ before any model holds a pointer into it.
  if (heatSetup_.enabled) loadHeatClouds();
  loadBodyClouds();
  if (!inletSetup_.inlets.empty() && !flowSetup_.enabled) {
    const std::string& name = inletSetup_.inlets.front().name;
    throw DictionaryError(
        inletSetup_.declaredAt.at(name),
        "inlet '" + name + "' feeds the flow's fluid, but constant/physicsModels has no flow");
  }
  if (flowSetup_.enabled || heatSetup_.enabled) {
    setUpNeighbourhood();
    if (flowSetup_.enabled) setUpFlow();
    if (!bodySetup_.bodies.empty()) setUpBodies();
    if (heatSetup_.enabled) setUpHeat();
    if (solidificationSetup_.enabled) setUpSolidification();
    setUpRheology();
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
      writer_.rewriteStart(time_.state(), written, uniformStateFiles(time_.startTimeName()));
      info() << "    (time " << time_.startTimeName()
             << " written again with every cloud and field the run writes)\n";
    }
  } else {
    // ballistic clouds need constant/g: reading it again gives the missing file's error
    if (!description_.gravity()) readGravity(caseFolder_);
    for (const ParticleCloud& cloud : clouds_) {
      info() << "Cloud " << cloud.name() << ": " << cloud.size() << " particles"
             << (cloud.hasVectorField(field::U) ? ", moving ballistically"
                                                : ", static (no U field)")
             << '\n';
      if (time_.settings().adjustTimeStep && cloud.hasVectorField(field::U)) {
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
    for (const auto& [name, field] : cloud.scalarFields())
      names.push_back(cloud.name() + "." + name);
    for (const auto& [name, field] : cloud.vectorFields())
      names.push_back(cloud.name() + "." + name);
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
      throw DictionaryError(description_.heatCloudsAt(),
                            "heat cloud '" + name + "' is neither in time " +
                                time_.startTimeName() + " (which holds (" + present +
                                " )) nor in constant/particles");
    }
    clouds_.push_back(readOnMaster([&] { return readCloudVtp(file, name); }, comm_));
    info() << "Cloud " << name << ": from constant/particles (carries heat: written from now on)\n";
  }
}

// Every cloud a model works on, registered once: the flow's fluid moves, everything else is
// at rest (a body's mold is registered again as rigid by setUpBodies).
void CastingSolver::setUpNeighbourhood() {
  const Real radius = description_.supportRadius();
  const PeriodicBox periodic = description_.periodic();
  // pair lists reused over steps only where particles move (a heat-only case has no flow)
  const Real skin = flowSetup_.enabled ? flowSetup_.settings.neighbourListSkin * radius : Real(0);
  models_.neighbourhood = std::make_unique<Neighbourhood>(radius, periodic, skin);
  if (flowSetup_.enabled) {
    ParticleCloud& fluid = cloudNamed(flowSetup_.fluidCloud);
    models_.neighbourhood->addCloud(fluid, Neighbourhood::Motion::moving);
    evolving_.push_back(&fluid);
    // A wall cloud is taken from the start time when it is there (setCastFields may have set
    // its fields, or it carries heat), else from constant/particles, where particleizeMold
    // wrote it.
    for (const std::string& wallName : flowSetup_.wallClouds) {
      if (const ParticleCloud* inTime = findCloud(wallName)) {
        models_.walls.push_back(inTime);
        continue;
      }
      const auto file = caseFolder_.constant() / "particles" / (wallName + ".vtp");
      if (!std::filesystem::exists(file)) {
        throw Error("wall cloud '" + wallName + "' is neither in time " + time_.startTimeName() +
                    " nor in constant/particles (run particleizeMold)");
      }
      staticClouds_.push_back(readOnMaster([&] { return readCloudVtp(file, wallName); }, comm_));
    }
    for (const ParticleCloud& wall : staticClouds_) models_.walls.push_back(&wall);
    for (const ParticleCloud* wall : models_.walls) models_.neighbourhood->addFixedCloud(*wall);
    if (parallel_) decompose();
  }
  for (const std::string& name : heatSetup_.clouds) {
    ParticleCloud& cloud = cloudNamed(name);
    models_.neighbourhood->addCloud(cloud, Neighbourhood::Motion::fixed);  // no-op for the fluid
    if (std::find(evolving_.begin(), evolving_.end(), &cloud) == evolving_.end()) {
      evolving_.push_back(&cloud);
    }
  }
  if (parallel_ && !flowSetup_.enabled) decompose();
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
  const std::vector<const ParticleCloud*>& walls = models_.walls;
  models_.flow = std::make_unique<WeaklyCompressibleFlow>(flowSetup_.settings, fluid, walls,
                                                          *models_.neighbourhood);
  models_.fluid = &fluid;
  if (!walls.empty()) models_.fillTime = std::make_unique<FillTime>(fluid, walls);
  domain_ = runDomain(monitor_.healthSettings(), fluid, walls, comm_);
  auto countOf = [&](const ParticleCloud& cloud) {
    return comm_.sum(static_cast<std::int64_t>(cloud.ownedSize()));
  };
  const FlowSettings& settings = flowSetup_.settings;
  info() << "Flow: " << (settings.incompressible ? "incompressible" : "weakly compressible")
         << " SPH (" << settings.dimension << "D), densityScheme " << settings.densityScheme
         << ", kernelCorrection "
         << (settings.kernelCorrection ? "on" : "off") << ", viscousForm " << settings.viscousForm
         << ", " << settings.walls.all.describe() << ", viscositySolver "
         << describeViscositySolver(settings.viscositySolver, settings.implicitViscosity)
         << ", h = " << settings.supportRadius << " m, c = " << settings.soundSpeed << " m/s\n"
         << "    time stepping: ";
  if (settings.incompressible) {
    const IncompressibleSettings& solver = settings.pressureSolver;
    info() << "incompressible: steps of at most advectionCo " << solver.advectionCo
           << " dx / |U|max (and the viscous, body-force and force models' limits), each with "
              "a search and the pressure solved for rho_s by relaxed Jacobi (Ihmsen et al. "
              "2014; omega "
           << solver.relaxation << ", " << solver.minIterations << " to " << solver.maxIterations
           << " iterations, to a mean compression below " << 100 * solver.densityTolerance
           << " % and none above " << 100 * solver.largestCompression << " %)\n";
  } else if (settings.dualCriteria) {
    info() << "dualCriteria: steps of at most advectionCo " << settings.advectionCo
           << " dx / |U|max (and the viscous, body-force and force models' limits), each with "
              "a search and the viscous term, in acoustic sub-steps of acousticCo "
           << settings.acousticCo << " of the pressure and the density\n";
  } else {
    info() << "kickDriftKick: steps of maxCo " << time_.settings().maxCo
           << " (controlDict), each with every pass\n";
  }
  info() << "    pair lists: searched with h + " << models_.neighbourhood->skin()
         << " m, reused until particles may have closed in by that skin\n"
         << "    fluid " << fluid.name() << ": " << countOf(fluid) << " particles\n";
  for (const ParticleCloud* wall : walls) {
    info() << "    wall " << wall->name() << ": " << countOf(*wall) << " particles";
    if (settings.walls.own.count(wall->name())) {
      info() << ", " << settings.walls.of(wall->name()).describe();
    }
    info() << '\n';
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (!settings.periodic.isPeriodic(axis)) continue;
    info() << "    periodic "
           << "xyz"[axis] << ": [" << settings.periodic.lower(axis) << ", "
           << settings.periodic.lower(axis) + settings.periodic.period(axis) << ")\n";
  }
  const Eigen::IOFormat plain(Eigen::StreamPrecision, Eigen::DontAlignCols, " ", " ");
  info() << "    domain (" << domain_.lower.transpose().format(plain) << ") ("
         << domain_.upper.transpose().format(plain) << "): fluid of cloud '"
         << models_.fluid->name()
         << "' outside it is spilled (removed, its mass and heat booked; the run stops when more "
         << "than " << 100 * monitor_.healthSettings().maxSpilledFraction
         << " % of it has spilled), any other particle outside it, or one not finite, "
         << "stops the run\n"
         << "    health checks: density deviation warned above "
         << 100 * monitor_.healthSettings().warnDensityDeviation << " %, stops above "
         << 100 * monitor_.healthSettings().maxDensityDeviation << " %; a particle "
         << monitor_.healthSettings().maxWallPenetration
         << " dx behind a wall surface, or a stable step below "
         << monitor_.healthSettings().minDeltaTFraction << " of its running mean, stops the run\n"
         << "    wall clearance " << settings.wallClearance
         << " dx: fluid particles closer to a wall surface are moved back to it\n";
  const SoundSpeedCheck soundSpeed = checkSoundSpeed(settings, fluid, walls, comm_);
  if (settings.incompressible) {
    info() << "    no sound speed: the pressure is solved (soundSpeed sets nothing)\n";
  } else if (soundSpeed.tooLow) {
    if (comm_.master()) warning(soundSpeed.message);
  } else {
    info() << "    " << soundSpeed.message << '\n';
  }
  if (surfaceTensionSetup_.enabled) {
    SurfaceTensionSettings tension = surfaceTensionSetup_.settings;
    tension.spacing = static_cast<Real>(fluid.attributes().at("spacing"));
    models_.surfaceTension = surfaceTensionModels().build(surfaceTensionSetup_.model, tension,
                                                          fluid, walls, *models_.neighbourhood);
    models_.flow->addForceModel(*models_.surfaceTension);
    info() << "Surface tension: " << models_.surfaceTension->summary(settings.soundSpeed) << '\n';
    const std::string warned = models_.surfaceTension->settingsWarning(settings.soundSpeed);
    if (!warned.empty()) warning(warned);
  }
}

void CastingSolver::setUpHeat() {
  HeatTransferContext context;
  context.dimension = description_.dimension();
  context.supportRadius = models_.neighbourhood->radius();
  context.neighbourhood = models_.neighbourhood.get();
  double spacing = 0;
  for (const std::string& name : heatSetup_.clouds) {
    ParticleCloud& cloud = cloudNamed(name);
    HeatCloud heat{&cloud, &description_.heatCloudMaterial(name), false, 0, {}};
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
  context.maxDi = time_.settings().maxDi;
  context.comm = comm_;
  models_.energy = std::make_unique<EnergyEquation>(context, heatSetup_.heatTransfer);
  if (models_.energy->needsExposedArea()) {
    // The areas a surface loss reads. Where those are all of walls (kept lattices, whose area
    // needs no gate), only they are computed: crossDitchPress's molds lose heat to the air, its
    // metal does not, and the metal's rows were a sixth of the pass (the other clouds cover, as
    // before, so the molds' areas are the same bits). A gated cloud's area reads the fullness
    // of every exposed neighbour: then every heat cloud is computed, as before.
    const auto& heatClouds = models_.energy->context().clouds;
    auto isWall = [&](const ParticleCloud* cloud) {
      return std::find(models_.walls.begin(), models_.walls.end(), cloud) != models_.walls.end();
    };
    bool onlyWallsRead = true;
    for (std::size_t c = 0; c < heatClouds.size(); ++c) {
      if (models_.energy->readsExposedAreaOf(c) && !isWall(heatClouds[c].cloud)) {
        onlyWallsRead = false;
      }
    }
    std::vector<ParticleCloud*> exposed;
    std::vector<const ParticleCloud*> covering;
    exposedAreaRestored_ = models_.energy->restarted();
    for (std::size_t c = 0; c < heatClouds.size(); ++c) {
      covering.push_back(heatClouds[c].cloud);
      if (onlyWallsRead && !models_.energy->readsExposedAreaOf(c)) continue;
      exposedAreaRestored_ =
          exposedAreaRestored_ && heatClouds[c].cloud->hasScalarField(field::exposedArea);
      exposed.push_back(heatClouds[c].cloud);
    }
    for (const ParticleCloud* wall : models_.walls) {
      if (std::find(covering.begin(), covering.end(), wall) == covering.end()) {
        covering.push_back(wall);
      }
    }
    // the walls keep their lattice (fixed or rigid): nothing inside them to gate
    models_.exposedArea = std::make_unique<ExposedArea>(
        models_.energy->exposedAreaForm(), context.dimension, context.supportRadius,
        context.spacing, exposed, covering, *models_.neighbourhood, models_.walls);
  }
  info() << "Heat transfer: energy equation (17) on";
  for (const HeatCloud& heat : models_.energy->context().clouds) {
    info() << ' ' << heat.cloud->name() << " (" << heat.material->name;
    if (heat.fixedTemperature) info() << ", held at " << heat.heldTemperature << " K";
    for (std::size_t p = 0; p < heat.heldPatches.size(); ++p) {
      info() << ", patch " << heatSetup_.heldPatchNames.at(heat.cloud->name())[p] << " held at "
             << heat.heldPatches[p].second << " K";
    }
    info() << ')';
  }
  info() << '\n';
  for (const std::string& line : models_.energy->descriptions()) info() << "    " << line << '\n';
  if (models_.exposedArea) {
    info() << "    exposed area A_i ("
           << (models_.energy->exposedAreaForm() == ExposedAreaForm::gradient ? "gradient of s_i"
                                                                              : "eq. 11")
           << ") with R_A = " << models_.exposedArea->areaFactor()
           << " (a flat surface counts its area)\n";
  }
  if (!flowSetup_.enabled) info() << "    no flow: the particles stay where they are\n";
}

// The fluid's rho_s, mu and solid fraction from its T before the flow's start state is computed
// (a restart gets the same values: a frozen particle's rho_s is read back, the others follow T).
// physicsModels' rheology: the Newtonian mu(T) (the default) needs nothing per step; another
// law writes the fluid's viscosity before every flow step's rates, and where it knows the
// solid fraction at which the mush stops flowing, the solidification freezes there.
void CastingSolver::setUpRheology() {
  const Dictionary* rheology = description_.modelsEntry("rheology");
  if (!rheology) return;
  const std::string name = rheology->found("model") ? rheologyModels().choose(*rheology, "model")
                                                    : rheologyModels().names().front();
  if (!models_.flow) {
    throw DictionaryError(rheology->location(), "'rheology' in " + rheology->name() +
                                                    " sets the flow's viscosity, but there is "
                                                    "no flow (flow { model weaklyCompressible; })");
  }
  models_.rheology = rheologyModels().build(
      name,
      RheologyContext{*models_.fluid, description_.fluidMaterial(), *models_.neighbourhood,
                      shearWalls(*models_.flow), description_.dimension(),
                      flowSetup_.settings.supportRadius},
      *rheology);
  info() << "Rheology: " << models_.rheology->description() << '\n';
  if (FluidForceModel* stress = models_.rheology->force()) models_.flow->addForceModel(*stress);
  if (models_.solidification && models_.rheology->writesViscosity()) {
    models_.solidification->leaveViscosityToRheology();
  }
  const Real coherent = models_.rheology->coherentSolidFraction();
  if (coherent <= 0 || !models_.solidification) return;
  if (solidificationSetup_.frozenSolidFractionAt) {
    throw DictionaryError(*solidificationSetup_.frozenSolidFractionAt,
                          "'frozenSolidFraction' is set by rheology " + name +
                              " (the mush stops flowing at f_s " + std::to_string(coherent) +
                              "); remove it");
  }
  models_.solidification->setFrozenSolidFraction(coherent);
  models_.solidification->update(time_.value(), 0.0);
  info() << "    the metal freezes at f_s " << coherent << ", where the mush stops flowing\n";
}

void CastingSolver::setUpSolidification() {
  SolidificationSettings settings = solidificationSetup_.settings;
  const Material& material = *solidificationSetup_.material;
  ParticleCloud& metal = cloudNamed(solidificationSetup_.cloud);
  // The mush's viscosity is capped only where the flow steps it explicitly: solved implicitly
  // (viscositySolver auto or implicit) it sets no step limit (sph/ImplicitViscosity.h).
  if (models_.flow && models_.flow->settings().viscositySolver == ViscositySolver::explicitForm) {
    const FlowSettings& flow = flowSetup_.settings;
    const double spacing = models_.fluid->attributes().at("spacing");
    // 0.9 of the viscosity whose explicit limit 0.125 dx^2 rho / mu is the acoustic step
    // maxCo dx / c, the longer of controlDict's and the cooling mode's (SolidificationSetup.h)
    const double liquidDensity = (*material.density)(material.freezingRange->liquidus);
    const double maxCo = std::max(time_.settings().maxCo, coolingMaxCo());
    settings.viscosityLimit =
        static_cast<Real>(0.9 * 0.125 * liquidDensity * spacing * flow.soundSpeed / maxCo);
  }
  models_.solidification = std::make_unique<Solidification>(settings, material, metal);
  models_.neighbourhood->requestPairs(metal, metal);  // for G at T_c (recordCriticalGradients)
  models_.solidification->update(time_.value(), 0.0);
  if (const auto mode = metal.attributes().find("coolingMode"); mode != metal.attributes().end()) {
    cooling_ = solidificationSetup_.cooling && mode->second != 0;
  }
  info() << "Solidification: " << models_.solidification->description() << '\n';
  if (models_.flow) {
    info() << "    frozen particles stay where they are (wall for the melt; their own "
              "contraction moves nothing); melt below "
           << flowSetup_.settings.cavitationPressure << " Pa opens a cavity\n";
  } else {
    info() << "    no flow: the metal conducts and solidifies where it is\n";
  }
  monitor_.logSolidification(cooling_);
}

// G = |grad T| of the particles that have just crossed T_c (Solidification.h), from the pairs
// of the last search: the positions the heat step used.
void CastingSolver::recordCriticalGradients() {
  const std::vector<std::size_t> pending = models_.solidification->pendingCriticalGradients();
  if (pending.empty()) return;
  ParticleCloud& metal = cloudNamed(solidificationSetup_.cloud);
  const int dimension = description_.dimension();
  const std::vector<Real> volume = particleVolumes(metal, dimension);
  const NeighbourList& pairs = models_.neighbourhood->pairs(metal, metal);
  auto& gradient = metal.scalarField(field::criticalGradient);
  const auto& T = metal.scalarField(field::T);
  for (const std::size_t i : pending) {
    gradient[i] = correctedGradient(metal, T, volume, pairs, models_.neighbourhood->periodicBox(),
                                    models_.neighbourhood->radius(), dimension, i)
                      .norm();
  }
}

// The first search and the rates of the start state (a restart keeps the order and the rates
// it was written with).
void CastingSolver::startModels() {
  const bool restarted = (models_.flow && models_.flow->restarted()) ||
                         (models_.energy && models_.energy->restarted());
  addWallTime(monitor_.times().search,
              [&] { searchNeighbours(restarted ? CloudOrder::keep : CloudOrder::byCell, false); });
  // a restart has the contacts up to its time already (the next search is the next step's)
  if (models_.fillTime && !restarted)
    models_.fillTime->record(*models_.neighbourhood, time_.value());
  if (models_.solidification) recordCriticalGradients();
  // A restart keeps the A_i it was written with: summed again over neighbour lists in another
  // order (the wall clearance moves particles after the search) they could differ in the last
  // bit.
  if (models_.exposedArea && !exposedAreaRestored_) models_.exposedArea->compute();
  if (models_.flow) models_.flow->start();
  // the bodies' acceleration under the start state's loads
  if (!restarted) models_.movingMolds.kick(0.0, time_.value());
  setUpInlets();
  if (models_.energy) {
    for (const std::string& line : models_.energy->start()) info() << "    " << line << "\n";
  }
  info() << "    neighbourhood: "
         << comm_.sum(static_cast<std::int64_t>(models_.neighbourhood->pairCount())) << " pairs\n";
}

void CastingSolver::setUpFunctionObjects(const Dictionary& controlDict) {
  FunctionObjectContext context;
  context.caseRoot = caseFolder_.root();
  context.startTimeName = time_.startTimeName();
  context.startTime = time_.startValue();
  context.supportRadius = flowSetup_.enabled ? flowSetup_.settings.supportRadius : Real(0);
  context.gravity = gravity_;
  context.comm = comm_;
  for (const ParticleCloud& cloud : clouds_) context.clouds.push_back(&cloud);
  context.bodies = models_.movingMolds.bodyList();
  try {
    functions_ = FunctionObjectList(controlDict, context);
    // the bodies' history, every step, which castPostProcess's bodyMotion reads
    if (!models_.movingMolds.empty()) {
      const Dictionary history =
          Dictionary::parse("type bodyHistory;", "sphCastFoam's bodies' history");
      for (const auto& object : functions_.objects()) {
        if (object->name() == bodyHistoryName) {
          throw DictionaryError(controlDict.subDict("functions").location(bodyHistoryName),
                                "'" + std::string(bodyHistoryName) +
                                    "' in controlDict's functions is the name of the bodies' "
                                    "history, which sphCastFoam writes itself: choose another");
        }
      }
      functions_.add(functionObjectTypes().build("bodyHistory", bodyHistoryName, history, context));
    }
  } catch (const Error& error) {  // read from the dictionaries alone: every rank throws alike
    if (parallel_) throw CollectiveError(error.what());
    throw;
  }
  for (const auto& object : functions_.objects()) {
    info() << "Function object " << object->name() << ": postProcessing/" << object->name() << '/'
           << time_.startTimeName() << '\n';
  }
}

}  // namespace sphcast
