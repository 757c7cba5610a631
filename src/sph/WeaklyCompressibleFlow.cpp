#include "sph/WeaklyCompressibleFlow.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>
#include <utility>

#include <Eigen/Geometry>

#include "core/Error.h"
#include "core/Log.h"
#include "particles/FieldNames.h"
#include "sph/EquationOfState.h"
#include "sph/FlowRates.h"

namespace sphcast {

WeaklyCompressibleFlow::WeaklyCompressibleFlow(FlowSettings settings, ParticleCloud& fluid,
                                               std::vector<const ParticleCloud*> walls)
    : settings_(std::move(settings)),
      fluid_(fluid),
      walls_(std::move(walls)),
      ownNeighbourhood_(
          std::make_unique<Neighbourhood>(settings_.supportRadius, settings_.periodic,
                                          settings_.neighbourListSkin * settings_.supportRadius)),
      neighbourhood_(*ownNeighbourhood_) {
  checkInput();
  // A restarted cloud keeps the order it was written in (the wall clearance may have moved a
  // particle into another cell after the last reorder; reordering it now would change the
  // order of the next step's sums): the restart stays bit for bit, and the log's pair count
  // is right.
  neighbourhood_.update(restarted_ ? CloudOrder::keep : CloudOrder::byCell);
  start();
}

WeaklyCompressibleFlow::WeaklyCompressibleFlow(FlowSettings settings, ParticleCloud& fluid,
                                               std::vector<const ParticleCloud*> walls,
                                               Neighbourhood& shared)
    : settings_(std::move(settings)),
      fluid_(fluid),
      walls_(std::move(walls)),
      neighbourhood_(shared) {
  if (shared.radius() != settings_.supportRadius) {
    throw Error("flow: the shared neighbourhood's radius differs from the supportRadius");
  }
  checkInput();
}

void WeaklyCompressibleFlow::checkInput() {
  if (settings_.dimension != 2 && settings_.dimension != 3) {
    throw Error("flow: dimension must be 2 or 3, not " + std::to_string(settings_.dimension));
  }
  if (settings_.reinitialiseDensity) {
    const auto spacing = fluid_.attributes().find("spacing");
    if (spacing == fluid_.attributes().end()) {
      throw Error("flow: densityReinitialisation needs the fluid cloud '" + fluid_.name() +
                  "' to have its spacing attribute");
    }
    densityReinitialisation_ = std::make_unique<DensityReinitialisation>(
        settings_.dimension, settings_.supportRadius, static_cast<Real>(spacing->second),
        settings_.densityRelaxation);
  }
  if (settings_.densityScheme != "riemann" && settings_.densityScheme != "standard" &&
      settings_.densityScheme != "deltaSPH") {
    throw Error("unknown densityScheme '" + settings_.densityScheme +
                "'; valid densityScheme are: (riemann standard deltaSPH)");
  }
  if (settings_.dualCriteria && settings_.densityScheme == "deltaSPH") {
    throw Error(
        "timeStepping dualCriteria takes densityScheme riemann or standard; deltaSPH has its "
        "own Stormer-Verlet step (timeStepping kickDriftKick)");
  }
  if (settings_.dualCriteria && !(settings_.advectionCo > 0 && settings_.acousticCo > 0)) {
    throw Error("flow: advectionCo and acousticCo must be positive");
  }
  if (settings_.incompressible) {
    const IncompressibleSettings& solver = settings_.pressureSolver;
    if (settings_.dualCriteria || settings_.densityScheme == "deltaSPH" ||
        settings_.reinitialiseDensity) {
      throw Error(
          "flow { model incompressible; } solves its pressure: timeStepping dualCriteria, "
          "densityScheme deltaSPH and densityReinitialisation are the weakly compressible "
          "flow's");
    }
    if (!(solver.densityTolerance > 0 && solver.largestCompression >= solver.densityTolerance &&
          solver.relaxation > 0 && solver.relaxation <= 1 &&
          solver.maxIterations >= solver.minIterations && solver.minIterations >= 1 &&
          solver.advectionCo > 0)) {
      throw Error("flow: pressureSolverCoeffs out of range");
    }
    incompressiblePressure_ = IncompressiblePressure(solver);
  }
  if (settings_.viscousForm != "Morris" && settings_.viscousForm != "Cleary") {
    throw Error("unknown viscousForm '" + settings_.viscousForm +
                "'; valid viscousForm are: (Morris Cleary)");
  }
  // The implicit solve is the Morris form's (ImplicitViscosity.h): with Cleary's the viscosity
  // stays explicit under auto, and implicit is refused.
  if (settings_.viscousForm == "Cleary") {
    if (settings_.viscositySolver == ViscositySolver::implicitForm) {
      throw Error("viscositySolver implicit solves the Morris form; set viscousForm Morris");
    }
    settings_.viscositySolver = ViscositySolver::explicitForm;
  }
  implicitViscosity_ = ImplicitViscosity(settings_.implicitViscosity);
  const auto spacing = fluid_.attributes().find("spacing");
  if (spacing == fluid_.attributes().end() || !(spacing->second > 0)) {
    throw Error("flow: cloud '" + fluid_.name() +
                "' has no positive 'spacing' attribute (the particle spacing dx, which "
                "setCastFields writes)");
  }
  // Each look-up throws an Error naming the cloud and the fields it has.
  fluid_.vectorField(field::U);
  for (const char* name : {field::rho, field::mass, field::viscosity, field::restDensity}) {
    fluid_.scalarField(name);
  }
  for (const ParticleCloud* wall : walls_) {
    wall->scalarField(field::volume);
    wall->vectorField(field::normal);
    wall->scalarField(field::wallDistance);
  }
  // particleizeMold's wall-surface patches reach up to 2 dx of a face from a particle up to a
  // spacing behind it (particles/WallSurfaceDistance.h): a smaller kernel misses some of them
  const Real dx = static_cast<Real>(spacing->second);
  const bool patched = std::any_of(walls_.begin(), walls_.end(), [](const ParticleCloud* wall) {
    return wall->hasScalarField(field::wallPatchRadius);
  });
  if (patched && settings_.supportRadius < Real(wallSurfaceReachInSpacings) * dx * Real(0.999)) {
    std::ostringstream message;
    message << "supportRadius " << settings_.supportRadius << " m is "
            << settings_.supportRadius / dx
            << " dx: the wall-surface estimate needs the wall particles within "
            << wallSurfaceReachInSpacings
            << " dx; beside the molds' edges off the lattice a particle may pass a wall unseen";
    warning(message.str());
  }
  if (settings_.dimension == 2) requirePlane();
  for (const ParticleCloud* wall : walls_) wallPressure_.emplace_back(wall->size(), Real(0));
  loadMeasured_.assign(walls_.size(), false);
  wallLoads_.assign(walls_.size(), WallLoad{});
  loadForce_.resize(walls_.size());
  loadTorque_.resize(walls_.size());
  const auto& restart = restartFields();  // acceleration (a vector), densityRate
  restarted_ = fluid_.hasVectorField(restart[0]) && fluid_.hasScalarField(restart[1]);
  fluid_.addScalarField(field::p);
  fluid_.addVectorField(field::acceleration);
  fluid_.addScalarField(field::densityRate);
  neighbourhood_.addCloud(fluid_, Neighbourhood::Motion::moving);
  neighbourhood_.requestPairs(fluid_, fluid_);
  for (const ParticleCloud* wall : walls_) {
    neighbourhood_.addFixedCloud(*wall);
    neighbourhood_.requestPairs(fluid_, *wall);
    neighbourhood_.requestPairs(*wall, fluid_);
  }
}

const std::vector<std::string>& WeaklyCompressibleFlow::restartFields() {
  static const std::vector<std::string> fields{"acceleration", "densityRate"};
  return fields;
}

std::size_t WeaklyCompressibleFlow::wallIndex(const ParticleCloud& wall) const {
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (walls_[w] == &wall) return w;
  }
  throw Error("flow: cloud '" + wall.name() + "' is not one of the flow's walls");
}

void WeaklyCompressibleFlow::measureLoadOn(const ParticleCloud& wall) {
  loadMeasured_[wallIndex(wall)] = true;
}

const WallLoad& WeaklyCompressibleFlow::wallLoad(const ParticleCloud& wall) const {
  return wallLoads_[wallIndex(wall)];
}

// The per-particle loads of the last pass, summed in particle order (a decomposed run's owned
// particles: the solver sums the ranks').
void WeaklyCompressibleFlow::sumWallLoads() {
  const std::size_t owned = fluid_.ownedSize();
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (!loadMeasured_[w]) continue;
    Vector force = Vector::Zero(), torque = Vector::Zero();
    for (std::size_t i = 0; i < owned; ++i) {
      force += loadForce_[w][i];
      torque += loadTorque_[w][i];
    }
    wallLoads_[w].force = force;
    wallLoads_[w].torque = torque;
  }
}

// The momentum the clearance gave the fluid particles it stopped at a measured wall, taken
// from that wall (at the fluid particle's place: the wall particle is within h of it).
void WeaklyCompressibleFlow::sumClearanceImpulses() {
  for (WallLoad& load : wallLoads_) {
    load.clearanceImpulse.setZero();
    load.clearanceAngularImpulse.setZero();
  }
  if (clearanceWall_.empty()) return;
  const auto& x = fluid_.positions();
  const auto& mass = fluid_.scalarField(field::mass);
  for (std::size_t i = 0; i < fluid_.ownedSize(); ++i) {  // the owned: the clearance's
    const int w = clearanceWall_[i];
    if (w < 0 || !loadMeasured_[w]) continue;
    const Vector impulse = -mass[i] * clearanceVelocityChange_[i];
    wallLoads_[w].clearanceImpulse += impulse;
    wallLoads_[w].clearanceAngularImpulse += x[i].cross(impulse);
  }
}

void WeaklyCompressibleFlow::start() {
  // the incompressible step needs no rates from before: its pressure starts from p as it is
  if (restarted_ || settings_.incompressible) return;
  updatePressure();
  computeRates();
  // dualCriteria's first sub-step takes the halo's density rate (its owners'; a search brings
  // it after every later step)
  if (settings_.dualCriteria) neighbourhood_.syncHalo(fluid_, {field::densityRate});
}

// A 2D case keeps every particle, fluid and wall, at the z of the first fluid particle: the 2D
// kernel counts no z distance, and a particle off the plane would interact as if it were on it.
void WeaklyCompressibleFlow::requirePlane() const {
  if (fluid_.size() == 0) return;
  const Real plane = fluid_.positions()[0][2];
  auto check = [plane](const ParticleCloud& cloud) {
    const auto& x = cloud.positions();
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (x[i][2] != plane) {
        throw Error("flow: the case is 2D (dimension 2), but particle " + std::to_string(i) +
                    " of cloud '" + cloud.name() + "' lies at z = " + std::to_string(x[i][2]) +
                    ", off the plane z = " + std::to_string(plane) + " of the fluid");
      }
    }
  };
  check(fluid_);
  for (const ParticleCloud* wall : walls_) check(*wall);
}

std::vector<WallSurfaceView> WeaklyCompressibleFlow::wallSurfaces() const {
  return wallSurfaceViews(fluid_, walls_, neighbourhood_);
}

void WeaklyCompressibleFlow::keepClearOfWalls() {
  const Real spacing = static_cast<Real>(fluid_.attributes().at("spacing"));
  const bool anyLoad =
      std::find(loadMeasured_.begin(), loadMeasured_.end(), true) != loadMeasured_.end();
  if (anyLoad) {
    clearanceVelocityChange_.resize(fluid_.size());
    clearanceWall_.resize(fluid_.size());
  }
  // the owned particles (all of a serial run's); a decomposed run's halo then takes its
  // owners' positions and velocities
  const std::size_t owned = fluid_.ownedSize();
  addWallTime(timings_.wallClearance, [&] {
    lastClearance_ = enforceWallClearance(
        std::span<Vector>(fluid_.positions()).first(owned),
        std::span<Vector>(fluid_.vectorField(field::U)).first(owned), wallSurfaces(),
        settings_.periodic, spacing, settings_.wallClearance * spacing,
        fluid_.hasScalarField(field::frozen)
            ? std::span<const Real>(fluid_.scalarField(field::frozen)).first(owned)
            : std::span<const Real>(),
        anyLoad ? std::span<Vector>(clearanceVelocityChange_).first(owned) : std::span<Vector>(),
        anyLoad ? std::span<int>(clearanceWall_).first(owned) : std::span<int>());
    if (anyLoad) sumClearanceImpulses();
  });
  neighbourhood_.syncHalo(fluid_, {"position", "U"});
  // The lists stay those of the positions before the move (by the clearance plus the depth it
  // had reached, under 0.75 dx unless the run then stops; most moves are far smaller): a pair
  // that came within h misses W's last (1 - r/h)^4 sliver, and one that left it adds W = 0. A
  // second search for the few particles moved would cost as much as the first.
}

void WeaklyCompressibleFlow::updatePressure() {
  const LinearEquationOfState eos{settings_.soundSpeed};
  const auto& density = fluid_.scalarField(field::rho);
  const auto& restDensity = fluid_.scalarField(field::restDensity);
  auto& pressure = fluid_.scalarField(field::p);
  const Real lowest = settings_.cavitationPressure;
#pragma omp parallel for
  for (std::size_t i = 0; i < density.size(); ++i) {
    pressure[i] = std::max(eos.pressure(density[i], restDensity[i]), lowest);
  }
}

// Frozen particles (solidified metal) neither move nor accelerate: the kicks that follow keep
// their velocity at zero, whatever it was when they froze. Called after the rates and before the
// first kick, so that a particle frozen between two steps does not drift on its old velocity.
void WeaklyCompressibleFlow::holdFrozenParticles() {
  if (!fluid_.hasScalarField(field::frozen)) return;
  const auto& frozen = fluid_.scalarField(field::frozen);
  auto& v = fluid_.vectorField(field::U);
  auto& acceleration = fluid_.vectorField(field::acceleration);
#pragma omp parallel for
  for (std::size_t i = 0; i < frozen.size(); ++i) {
    if (frozen[i] != 0) {
      v[i].setZero();
      acceleration[i].setZero();
    }
  }
}

void WeaklyCompressibleFlow::step(double deltaT) {
  if (!ownNeighbourhood_) {
    throw Error(
        "flow: step() is for a flow with its own neighbourhood; in a shared one the "
        "solver calls the phases");
  }
  if (settings_.stepsBeforeSearch()) {
    advectionStep(deltaT);
    addWallTime(timings_.neighbourSearch, [&] { neighbourhood_.update(); });
    keepClearOfWalls();
    return;
  }
  kickAndDrift(deltaT);
  addWallTime(timings_.neighbourSearch, [&] { neighbourhood_.update(); });
  keepClearOfWalls();
  computeRatesAndKick(deltaT);
}

// Kick and drift with the rates of the current state (kick-drift-kick); deltaSPH's
// Stormer-Verlet kicks only the velocity here (computeRatesAndKickStormerVerlet says why).
void WeaklyCompressibleFlow::kickAndDrift(double deltaT) {
  holdFrozenParticles();  // those frozen since the last rates (by a heat step) too
  const Real dt = static_cast<Real>(deltaT);
  const Real halfDt = Real(0.5) * dt;
  const bool kickDensity = settings_.densityScheme != "deltaSPH";
  auto& x = fluid_.positions();
  auto& v = fluid_.vectorField(field::U);
  auto& rho = fluid_.scalarField(field::rho);
  const auto& densityRate = fluid_.scalarField(field::densityRate);
  const auto& acceleration = fluid_.vectorField(field::acceleration);
  const PeriodicBox periodic = settings_.periodic;
  addWallTime(timings_.integration, [&] {
    if (kickDensity) {
#pragma omp parallel for
      for (std::size_t i = 0; i < x.size(); ++i) {
        v[i] += halfDt * acceleration[i];
        rho[i] += halfDt * densityRate[i];
        x[i] = periodic.wrap(x[i] + dt * v[i]);
      }
    } else {
#pragma omp parallel for
      for (std::size_t i = 0; i < x.size(); ++i) {
        v[i] += halfDt * acceleration[i];
        x[i] = periodic.wrap(x[i] + dt * v[i]);
      }
    }
  });
}

// The second kick with the rates at the new positions (the neighbourhood's reorder permutes
// the fields in place, so references taken before it stay valid).
void WeaklyCompressibleFlow::computeRatesAndKick(double deltaT) {
  const Real dt = static_cast<Real>(deltaT);
  if (settings_.densityScheme == "deltaSPH") {
    computeRatesAndKickStormerVerlet(dt);
    return;
  }
  const Real halfDt = Real(0.5) * dt;
  auto& v = fluid_.vectorField(field::U);
  auto& rho = fluid_.scalarField(field::rho);
  const auto& densityRate = fluid_.scalarField(field::densityRate);
  const auto& acceleration = fluid_.vectorField(field::acceleration);
  viscosityImplicit_ = solvesViscosityImplicitly(deltaT);
  addWallTime(timings_.rates, [&] {
    if (densityReinitialisation_) densityReinitialisation_->apply(fluid_, walls_, neighbourhood_);
    updatePressure();
    computeRates();
  });
  addWallTime(timings_.integration, [&] {
#pragma omp parallel for
    for (std::size_t i = 0; i < v.size(); ++i) {
      v[i] += halfDt * acceleration[i];
      rho[i] += halfDt * densityRate[i];
    }
    // the halo's rates are not computed (computeRatesFor): what the heat and the next passes
    // read there is its owners'
    neighbourhood_.syncHalo(fluid_, {field::U, field::rho});
    updatePressure();
  });
  if (viscosityImplicit_) solveViscosity(dt);
}

// deltaSPH's step: Stormer-Verlet with the density as a position-like variable,
//   v^{n+1/2} = v^n + dt/2 a^n,   x^{n+1} = x^n + dt v^{n+1/2},
//   rho^{n+1} = rho^n + dt Drho(x^{n+1}, v^{n+1/2}, rho^n),
//   v^{n+1} = v^{n+1/2} + dt/2 a(x^{n+1}, rho^{n+1}, v^{n+1/2}),
// two passes over the pairs per step. The kick-drift-kick of step() kicks rho like v, so the
// pressure of a^{n+1} comes from rho^{n+1/2} and the density rate from v^{n+1/2}: for an acoustic
// mode of frequency w (drho/dt = -w v, dv/dt = w rho) that amplifies by about 1 + (w dt)^2 / 4 in
// amplitude (1 + (w dt)^2 / 2 in energy) every step, for any dt. The Riemann interface damps that
// growth; the plain-mean pressure of deltaSPH has only the density diffusion and alpha to do it,
// which is too little at maxCo 0.25 (measured, delta 0.1 and alpha 0.02: the 2D hydrostatic tank's
// density oscillates with growing amplitude from the free-surface corners and blows up by
// t sqrt(g/H) = 1.6; at maxCo 0.1 it survives, at 0.05 it stays at rest; the 2D dam break loses
// particles at a/dx = 10 and 20). This step is neutral for w dt < 2 and costs a second pass over
// the pairs (the 2D dam break at a/dx = 20: 4.2 s against riemann's 2.8 s).
void WeaklyCompressibleFlow::computeRatesAndKickStormerVerlet(Real dt) {
  const Real halfDt = Real(0.5) * dt;
  viscosityImplicit_ = solvesViscosityImplicitly(dt);
  if (densityReinitialisation_) {
    addWallTime(timings_.rates, [&] {
      densityReinitialisation_->apply(fluid_, walls_, neighbourhood_);
      updatePressure();
    });
  }
  auto& v = fluid_.vectorField(field::U);
  auto& rho = fluid_.scalarField(field::rho);
  const auto& densityRate = fluid_.scalarField(field::densityRate);
  const auto& acceleration = fluid_.vectorField(field::acceleration);
  addWallTime(timings_.rates, [&] { computeRates(RatePart::densityRate); });  // p is still of rho^n
  addWallTime(timings_.integration, [&] {
#pragma omp parallel for
    for (std::size_t i = 0; i < rho.size(); ++i) rho[i] += dt * densityRate[i];
    // the acceleration reads the neighbours' rho^{n+1}: the halo's are its owners'
    neighbourhood_.syncHalo(fluid_, {field::rho});
    updatePressure();
  });
  addWallTime(timings_.rates, [&] { computeRates(RatePart::acceleration); });
  addWallTime(timings_.integration, [&] {
#pragma omp parallel for
    for (std::size_t i = 0; i < v.size(); ++i) v[i] += halfDt * acceleration[i];
    neighbourhood_.syncHalo(fluid_, {field::U});  // the halo's rates are not computed
  });
  if (viscosityImplicit_) solveViscosity(dt);
}

double WeaklyCompressibleFlow::explicitViscousLimit() const {
  const auto& rho = fluid_.scalarField(field::rho);
  const auto& mu = fluid_.scalarField(field::viscosity);
  double largest = 0;
  const std::size_t owned = fluid_.ownedSize();
#pragma omp parallel for reduction(max : largest)
  for (std::size_t i = 0; i < owned; ++i) {
    largest = std::max(largest, static_cast<double>(mu[i] / rho[i]));
  }
  largest = neighbourhood_.maxOverRanks(largest);  // every rank decides alike
  const double dx = fluid_.attributes().at("spacing");
  return largest > 0 ? 0.125 * dx * dx / largest : std::numeric_limits<double>::infinity();
}

bool WeaklyCompressibleFlow::solvesViscosityImplicitly(double deltaT) const {
  switch (settings_.viscositySolver) {
    case ViscositySolver::implicitForm:
      return true;
    case ViscositySolver::automatic:
      return deltaT > explicitViscousLimit();
    default:
      return false;
  }
}

// After the second kick: U stepped by the viscous term over dt, backward in time, and the
// walls' loads given the viscous shear the rates left out.
void WeaklyCompressibleFlow::solveViscosity(Real dt) {
  std::vector<ViscousWall> walls;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const ParticleCloud& wall = *walls_[w];
    walls.push_back(
        {&wall.positions(), wall.hasVectorField(field::U) ? &wall.vectorField(field::U) : nullptr,
         &wall.scalarField(field::volume), &wall.vectorField(field::normal),
         &wall.scalarField(field::wallDistance), &wallPairs(w), settings_.walls.of(wall.name())});
  }
  const Real spacing = static_cast<Real>(fluid_.attributes().at("spacing"));
  addWallTime(timings_.viscousSolve, [&] {
    lastViscousSolve_ = settings_.dimension == 2
                            ? implicitViscosity_.solve<2>(fluid_, neighbourhood_, walls,
                                                          settings_.supportRadius, spacing, dt)
                            : implicitViscosity_.solve<3>(fluid_, neighbourhood_, walls,
                                                          settings_.supportRadius, spacing, dt);
  });
  ++work_.implicitViscousSteps;
  work_.viscousIterations += static_cast<std::uint64_t>(lastViscousSolve_.iterations);
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (!loadMeasured_[w]) continue;
    wallLoads_[w].force += implicitViscosity_.wallForces()[w];
    wallLoads_[w].torque += implicitViscosity_.wallTorques()[w];
  }
}

}  // namespace sphcast
