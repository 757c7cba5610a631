#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "boundaries/WallCondition.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"
#include "sph/DensityReinitialisation.h"
#include "sph/FluidForceModel.h"
#include "sph/ImplicitViscosity.h"
#include "sph/IncompressiblePressure.h"
#include "sph/KernelCorrection.h"
#include "sph/WallClearance.h"

namespace sphcast {

// Numerics and constants of the flow (system/sphSchemes and constant/ once the solver reads
// them; set directly by tests).
struct FlowSettings {
  int dimension = 3;       // 2 or 3
  Real supportRadius = 0;  // h of the kernel, m
  Real soundSpeed = 0;     // c of eq. (3), m/s
  Vector gravity = Vector::Zero();
  std::string densityScheme = "riemann";  // riemann | standard | deltaSPH
  // Kernel-gradient normalisation (KernelCorrection.h) of the pair gradients.
  bool kernelCorrection = false;
  // deltaSPH (Antuono et al. 2010): density diffusion delta and artificial viscosity alpha,
  // both scaled by the smoothing length h/2 and c. alpha 0.02 by default: with 0 the 2D dam
  // break's thin front runs 0.54 a ahead of Martin & Moyce's (0.22 a with 0.02).
  Real deltaSPHDiffusion = Real(0.1);
  Real deltaSPHViscosity = Real(0.02);
  std::string viscousForm = "Morris";  // Morris | Cleary (FlowRates.h says why Morris)
  // viscositySolver and viscositySolverCoeffs in system/sphSchemes (ImplicitViscosity.h); the
  // implicit solve takes the Morris form
  ViscositySolver viscositySolver = ViscositySolver::automatic;
  ImplicitViscositySettings implicitViscosity;
  // The walls' conditions (boundaries/WallCondition.h): wallSlip and wallDissipation of
  // system/sphSchemes for every wall, a wall's own entry in physicsModels' flow walls for it.
  WallConditions walls;
  // neighbourListSkin in system/sphSchemes: the skin of the reused pair lists as a fraction of
  // h (particles/Neighbourhood.h); 0 searches the cells at every step.
  Real neighbourListSkin = Real(0.1);
  PeriodicBox periodic;
  // The least distance, in particle spacings, a fluid particle keeps from a wall surface
  // (WallClearance.h, WallSurfaceDistance.h).
  Real wallClearance = Real(wallClearanceInSpacings);
  // The lowest pressure the melt holds, Pa (gauge): below it the equation of state gives this
  // value, so that melt pulled apart (shrinkage enclosed by solid) opens a cavity instead of
  // clumping through the tensile instability. Solidification sets it (cavitationPressure);
  // otherwise there is none.
  Real cavitationPressure = std::numeric_limits<Real>::lowest();
  // densityReinitialisation packed in system/sphSchemes: the density relaxed towards the
  // particles' arrangement before every evaluation of the rates (DensityReinitialisation.h), by
  // densityReinitialisationCoeffs' relaxation of the way each step; none (the default): the
  // continuity equation's alone.
  bool reinitialiseDensity = false;
  Real densityRelaxation = Real(0.3);
  // timeStepping in system/sphSchemes: kickDriftKick (the default), one step of the acoustic
  // length (controlDict's maxCo) with every pass; dualCriteria, an advection step
  // (advectionStep) of dualCriteriaCoeffs' advectionCo dx / |v|max and the viscous, body-force
  // and force models' limits, made of acoustic sub-steps of its acousticCo.
  bool dualCriteria = false;
  Real advectionCo = Real(0.2);
  Real acousticCo = Real(1);
  // flow { model incompressible; } of constant/physicsModels: the pressure solved implicitly
  // for the rest density (IncompressiblePressure.h) instead of eq. (3)'s from the density, in
  // steps set by the flow speed (pressureSolverCoeffs in system/sphSchemes).
  bool incompressible = false;
  IncompressibleSettings pressureSolver;
  // Whether a flow step is one pass of its own over the lists of the last search
  // (advectionStep: dualCriteria's acoustic sub-steps, or the incompressible step) rather than
  // kick-drift-kick's two halves around the search.
  bool stepsBeforeSearch() const { return dualCriteria || incompressible; }
};

// The work the rate passes did and left out since the start, in particle-steps (one particle's
// rates in one flow step), for the log's account of what the run skipped.
struct FlowWork {
  std::uint64_t flowSteps = 0;             // acceleration passes
  std::uint64_t particleSteps = 0;         // every fluid particle at every acceleration pass
  std::uint64_t skippedFrozen = 0;         // frozen with no melt within two neighbour hops
  std::uint64_t implicitViscousSteps = 0;  // flow steps whose viscosity was solved implicitly
  std::uint64_t viscousIterations = 0;     // the conjugate gradient's iterations in them
  std::uint64_t advectionSteps = 0;        // dualCriteria: the steps of the pair lists
  std::uint64_t acousticSubSteps = 0;      // dualCriteria: the pressure passes within them
  std::uint64_t pressureSolves = 0;        // incompressible: the steps' pressure solves
  std::uint64_t pressureIterations = 0;    // and their Jacobi iterations
  std::uint64_t unconvergedPressureSolves = 0;  // left above densityTolerance at maxIterations
};

// Wall time spent in each part of the flow's steps, seconds since construction.
struct FlowTimings {
  double neighbourSearch = 0;  // grids, reorder, pair lists (a flow with its own neighbourhood)
  double wallClearance = 0;    // keepClearOfWalls
  double rates = 0;            // wall pressure, correction, the pair loops
  double viscousSolve = 0;     // the implicit viscosity's solves
  double integration = 0;      // kicks and drifts
};

// Why the step is what it is: each limit in seconds, for the log.
// With dualCriteria the solver's step takes advection, viscous, bodyForce and forceModel (the
// others are infinite there), and the acoustic sub-steps within it the acoustic, acceleration and
// density-rate limits (WeaklyCompressibleFlow::acousticSubStep).
struct FlowStepLimits {
  double acoustic;      // maxCo dx / (c + |v|max)
  double viscous;       // 0.125 dx^2 / nu_max; infinite where the viscosity is solved implicitly
  double bodyForce;     // 0.25 sqrt(dx / |g|)
  double acceleration;  // 0.25 sqrt(dx / |a|max), Monaghan's force criterion
  double densityRate;   // 0.02 min rho / |drho/dt|: no density changes by more than 2 % a step
  double forceModel;    // the smallest of the force models' (FluidForceModel), if any
  std::string forceModelName;
  double advection = std::numeric_limits<double>::infinity();  // advectionCo dx / |v|max
  double smallest(std::string& limiter) const;
};

// What the fluid puts on a wall cloud whose load is measured (measureLoadOn): the exact negative
// of every pair term the wall's particles put on the fluid (interface pressure, viscous,
// deltaSPH's artificial viscosity), each acting at its wall particle, so that fluid and wall
// conserve momentum pair by pair; and the momentum the last wall clearance took out of the fluid
// particles it stopped at this wall.
struct WallLoad {
  Vector force = Vector::Zero();                    // N, at the last evaluation of the rates
  Vector torque = Vector::Zero();                   // N m about the origin, likewise
  Vector clearanceImpulse = Vector::Zero();         // N s, of the last keepClearOfWalls
  Vector clearanceAngularImpulse = Vector::Zero();  // N m s about the origin, likewise
};

// Weakly compressible SPH for one fluid cloud among wall clouds (paper eqs. (1)-(4),
// doc/physics.md): continuity and momentum with the interface pressure and velocity of a Riemann
// solver (or plain means: densityScheme standard; plain means with the density diffusion and
// artificial viscosity of Antuono et al. 2010: deltaSPH), optionally with the normalised kernel
// gradient (KernelCorrection.h), the viscous term with dynamic viscosity, and gravity;
// integrated kick-drift-kick (deltaSPH: Stormer-Verlet with the density updated like the
// positions, stepStormerVerlet says why).
//
// Fluid fields read: U, rho, mass, viscosity (mu, Pa s), restDensity (rho_s), and frozen when the
// cloud has it (solidification/Solidification.h: a particle with frozen != 0 has zero velocity
// and acceleration, so it stays where it is, a wall for the others, while its density follows
// the continuity equation; frozen particles with no melt within two neighbour hops compute
// nothing); written: p,
// acceleration, densityRate (kept in the cloud, so a restart continues bit for bit). Cloud
// attribute spacing (dx) for the step limits. Wall fields read (as particleizeMold writes them):
// volume, normal (unit, out of the wall into the fluid), wallDistance (depth behind the wall
// surface); a wall with a field U moves (a mold that is a rigid body, bodies/RigidBody.h): U and,
// when present, acceleration enter its mirror state (no penetration and no slip relative to the
// wall; the extrapolated pressure with g - a_wall, Adami et al. 2012 eq. (27)), the wall
// clearance and the acoustic step limit. Whoever moves it keeps U and acceleration current.
//
// The pairs come from a Neighbourhood: the solver's, shared with the other models of the step
// (the solver then calls the phases of a step in order, with its own search between them), or
// one the flow owns (tests and benchmarks: step() is then a whole step):
//   kickAndDrift(dt)  -> neighbourhood.update() -> keepClearOfWalls() -> computeRatesAndKick(dt)
class WeaklyCompressibleFlow {
 public:
  // With a neighbourhood of its own (the fluid is reordered along its grid every step).
  WeaklyCompressibleFlow(FlowSettings settings, ParticleCloud& fluid,
                         std::vector<const ParticleCloud*> walls);
  // In a shared neighbourhood: registers the fluid (moving) and the walls (fixed) and asks for
  // the fluid-fluid, fluid-wall and wall-fluid pairs. The owner updates the neighbourhood
  // (CloudOrder::keep when restarted()), then calls start().
  WeaklyCompressibleFlow(FlowSettings settings, ParticleCloud& fluid,
                         std::vector<const ParticleCloud*> walls, Neighbourhood& shared);

  // The fluid came with the rates of its last step (a restart): start() keeps them.
  bool restarted() const { return restarted_; }
  // The fields of the fluid a restart reads back instead of computing (p follows from rho).
  static const std::vector<std::string>& restartFields();
  // The pressure and rates of the start state (after the first neighbourhood update).
  void start();

  // The limits of a step: with dualCriteria those of an advection step (FlowStepLimits), with
  // advectionStep false those of a kick-drift-kick step (the casting's cooling mode takes them).
  FlowStepLimits stepLimits(double maxCo) const {
    return stepLimits(maxCo, settings_.dualCriteria);
  }
  FlowStepLimits stepLimits(double maxCo, bool advectionStep) const;

  // A force the flow adds at every evaluation of the rates, after its own (surface tension);
  // the model must stay alive while the flow steps.
  void addForceModel(FluidForceModel& model) {
    forceModels_.push_back(&model);
    if (std::vector<Vector>* buffer = model.colourGradientBuffer()) {
      colourGradientBuffers_.push_back(buffer);
    }
  }

  // One whole step of deltaT (a flow with its own neighbourhood): kick-drift-kick, or with
  // dualCriteria an advection step of acoustic sub-steps.
  void step(double deltaT);

  // dualCriteria (Zhang, Hu & Adams 2017 §2.3, as SPHinXsys): the step of the pair lists,
  // deltaT, in acoustic sub-steps. The viscous term and the force models (and the packed density,
  // when asked for) are evaluated once, at its start, over the lists of the last search (a
  // viscosity solved implicitly is solved in every sub-step, after its kick); each
  // sub-step of dt is then a Verlet step of the pressure and the density alone,
  //   rho += dt/2 drho/dt,  x += dt/2 v,  v += dt (a_p(x, rho) + a_prior),
  //   x += dt/2 v,  drho/dt(x, v),  rho += dt/2 drho/dt,
  // two passes over the same pairs (the positions move, the pairs stay those of the search),
  // symplectic in the acoustic mode, so its Courant number may be about three times the
  // kick-drift-kick's. The hooks run the bodies beside it: `drift` after each sub-step's first
  // half, `kick` after its second, each given dt and the time elapsed since the advection
  // step's start at the sub-step's end. The search follows (the owner's, or step()'s).
  struct SubStepHooks {
    std::function<void(double dt, double elapsed)> drift;
    std::function<void(double dt, double elapsed)> kick;
    // The incompressible step's strong coupling (IncompressiblePressure.h): for a measured wall
    // that is a body, the velocities its particles would have at the step's end under the
    // fluid's whole load (force, torque about the origin; every rank's summed); false for a
    // wall that is no body (it keeps its U).
    std::function<bool(const ParticleCloud& wall, const Vector& force, const Vector& torque,
                       double dt, std::vector<Vector>& velocity)>
        predict;
  };
  // With flow { model incompressible; } the step is incompressibleStep's instead.
  void advectionStep(double deltaT, const SubStepHooks& hooks = {});
  // The incompressible step (Ihmsen et al. 2014's symplectic Euler step), over the lists of the
  // last search:
  //   v* = v + dt (g + a_viscous + a_forces)   (a viscosity solved implicitly: v* from its solve)
  //   p  = the pressure that brings the density to rho_s at the step's end (IncompressiblePressure)
  //   v  = v* + dt a^p,   x += dt v.
  // The hooks run the bodies: `kick` once the loads of the step are known (pressure, viscous,
  // forces), `drift` after the fluid's drift, each given dt and deltaT (the bodies' own
  // kick-drift-kick over one step of fixed loads is their symplectic Euler step).
  void incompressibleStep(double deltaT, const SubStepHooks& hooks);
  const IncompressibleReport& lastPressureSolve() const { return lastPressureSolve_; }
  // The acoustic sub-step's limits now: the smallest of the acoustic (of acousticCo),
  // acceleration and density rate limits over every rank.
  double acousticSubStepLimit(std::string& limiter) const;

  // The phases of a step, for a solver that searches once for several models:
  // the first kick and the drift (deltaSPH: the velocity's half kick and the drift) ...
  void kickAndDrift(double deltaT);
  // ... after the search, fluid particles too close to a wall moved back (WallClearance.h) ...
  void keepClearOfWalls();
  // ... the rates at the new positions and the second kick.
  void computeRatesAndKick(double deltaT);

  std::size_t fluidPairCount() const { return fluidPairs().pairCount(); }
  const Neighbourhood& neighbourhood() const { return neighbourhood_; }
  const std::vector<const ParticleCloud*>& walls() const { return walls_; }

  // Measures the load on `wall` (one of the flow's walls) at every evaluation of the rates and
  // wall clearance from now on; until the next rates, the load is zero.
  void measureLoadOn(const ParticleCloud& wall);
  const WallLoad& wallLoad(const ParticleCloud& wall) const;

  // What the wall clearance did in the last step (for the run's health checks).
  const WallClearanceReport& lastWallClearance() const { return lastClearance_; }

  // The last implicit viscosity solve (zero iterations before the first).
  const ImplicitViscosityReport& lastViscousSolve() const { return lastViscousSolve_; }
  const FlowSettings& settings() const { return settings_; }

  const FlowTimings& timings() const { return timings_; }
  const FlowWork& work() const { return work_; }

 private:
  // Which rates a pass computes: both at once (riemann, standard), or, for deltaSPH's
  // Stormer-Verlet step (stepStormerVerlet), the density rate and the acceleration in separate
  // passes.
  // dualCriteria's sub-steps take the pressure's acceleration (with gravity) and the density
  // rate in passes of their own, the viscous term (with the force models) once per advection
  // step.
  enum class RatePart { both, densityRate, acceleration, pressure, viscous };
  void checkInput();
  void requirePlane() const;
  void computeRatesAndKickStormerVerlet(Real dt);
  const NeighbourList& fluidPairs() const { return neighbourhood_.pairs(fluid_, fluid_); }
  const NeighbourList& wallPairs(std::size_t w) const {  // fluid particles' wall neighbours
    return neighbourhood_.pairs(fluid_, *walls_[w]);
  }
  const NeighbourList& fluidAroundWall(std::size_t w) const {  // wall particles' fluid ones
    return neighbourhood_.pairs(*walls_[w], fluid_);
  }
  std::vector<WallSurfaceView> wallSurfaces() const;
  void updatePressure();
  template <int Dim>
  void extrapolateWallPressure();
  template <int Dim>
  void computeCorrection();
  bool needsCorrectionMatrix(RatePart part) const {
    return settings_.kernelCorrection ||
           (settings_.densityScheme == "deltaSPH" &&
            (part == RatePart::both || part == RatePart::densityRate));
  }
  void computePriorAcceleration();
  // every limit, for stepLimits (the solver's step) and acousticSubStepLimit
  FlowStepLimits allStepLimits(double maxCo) const;
  void acousticSubStep(Real dt, const SubStepHooks& hooks, double elapsed);
  void computeRates(RatePart part = RatePart::both);
  void holdFrozenParticles();
  // The explicit viscous limit 0.125 dx^2 / nu_max of the owned particles (infinite without
  // viscosity), and whether a step of deltaT solves the viscosity implicitly.
  double explicitViscousLimit() const;
  bool solvesViscosityImplicitly(double deltaT) const;
  void solveViscosity(Real dt);
  // Returns the count of frozen particles with neither melt nor a moving body within two hops
  // (the rate pass skips them).
  std::uint64_t markFrozenNearMelt();
  template <int Dim>
  void computeRatesInDimension(RatePart part);
  template <int Dim, class Interface>
  void computeRatesWithInterface(RatePart part);
  template <int Dim, class Interface, class Viscosity, RatePart Part>
  void computeRatesFor();

  FlowSettings settings_;
  std::unique_ptr<DensityReinitialisation> densityReinitialisation_;  // null unless asked for
  ParticleCloud& fluid_;
  std::vector<const ParticleCloud*> walls_;
  std::unique_ptr<Neighbourhood> ownNeighbourhood_;  // null in a shared one
  Neighbourhood& neighbourhood_;
  bool restarted_ = false;
  std::size_t wallIndex(const ParticleCloud& wall) const;
  void sumWallLoads();
  void sumClearanceImpulses();

  std::vector<std::vector<Real>> wallPressure_;  // per wall cloud, per particle
  // Loads (measureLoadOn): per wall, whether measured, the sums, and per fluid particle the
  // force and torque of its pairs with the wall (summed in particle order: the same on any
  // number of threads)
  std::vector<bool> loadMeasured_;
  std::vector<WallLoad> wallLoads_;
  std::vector<std::vector<Vector>> loadForce_, loadTorque_;
  // dualCriteria: the viscous and force models' acceleration of the advection step, and what its
  // pass put on the measured walls (added to each sub-step's pressure loads)
  std::vector<Vector> priorAcceleration_;
  std::vector<WallLoad> priorLoads_;
  std::vector<Vector> lastTotalAcceleration_;    // the field's, kept across the viscous pass
  std::vector<Vector> clearanceVelocityChange_;  // of the last keepClearOfWalls, with loads
  std::vector<int> clearanceWall_;
  std::vector<Matrix> correction_;       // L_i, with kernelCorrection or deltaSPH
  std::vector<Vector> densityGradient_;  // renormalised grad rho (deltaSPH)
  WallClearanceReport lastClearance_;
  std::vector<FluidForceModel*> forceModels_;
  // where the models that asked for the colour gradient want it, and m / rho for its sum
  std::vector<std::vector<Vector>*> colourGradientBuffers_;
  std::vector<Real> pairVolume_;
  std::vector<std::uint8_t> frozenTouchesMelt_, frozenNearMelt_;  // markFrozenNearMelt
  FlowTimings timings_;
  FlowWork work_;
  ImplicitViscosity implicitViscosity_;
  bool viscosityImplicit_ = false;  // in the rates of the step being taken
  ImplicitViscosityReport lastViscousSolve_;
  IncompressiblePressure incompressiblePressure_;
  IncompressibleReport lastPressureSolve_;
};

}  // namespace sphcast
