// flow { model incompressible; } (doc/physics.md §9.2): the step of implicit incompressible SPH
// (Ihmsen et al. 2014), the pressure solved for the rest density (IncompressiblePressure.h) over
// the pair lists of the last search, every other force of the flow's rates as they are.
#include <cmath>

#include "core/Error.h"
#include "core/Log.h"
#include "particles/FieldNames.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {

void WeaklyCompressibleFlow::incompressibleStep(double deltaT, const SubStepHooks& hooks) {
  if (!settings_.incompressible) {
    throw Error("flow: incompressibleStep() is flow { model incompressible; }'s");
  }
  const Real dt = static_cast<Real>(deltaT);
  holdFrozenParticles();  // those frozen since the last step (by a heat step) too
  viscosityImplicit_ = solvesViscosityImplicitly(deltaT);
  auto& x = fluid_.positions();
  auto& v = fluid_.vectorField(field::U);
  auto& acceleration = fluid_.vectorField(field::acceleration);
  auto& densityRate = fluid_.scalarField(field::densityRate);
  const Real* frozen =
      fluid_.hasScalarField(field::frozen) ? fluid_.scalarField(field::frozen).data() : nullptr;
  const Vector gravity = settings_.gravity;
  // the viscous term (explicit) and the force models, with their loads on the walls
  addWallTime(timings_.rates, [&] { computePriorAcceleration(); });
  addWallTime(timings_.integration, [&] {
#pragma omp parallel for
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (frozen && frozen[i] != 0) continue;  // held (holdFrozenParticles)
      v[i] += dt * (priorAcceleration_[i] + gravity);
    }
    neighbourhood_.syncHalo(fluid_, {field::U});
  });
  if (viscosityImplicit_) solveViscosity(dt);  // v* from the implicit viscous solve
  // the loads of the step's other passes on the measured walls, every rank's: a body's
  // prediction adds the pressure's to them
  std::vector<double> otherLoads;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    for (int a = 0; a < 3; ++a) otherLoads.push_back(wallLoads_[w].force[a]);
    for (int a = 0; a < 3; ++a) otherLoads.push_back(wallLoads_[w].torque[a]);
  }
  if (hooks.predict) neighbourhood_.sumOverRanks(otherLoads);
  std::vector<PressureWall> walls;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const ParticleCloud& wall = *walls_[w];
    walls.push_back({&wall, &wall.positions(), &wall.scalarField(field::volume),
                     wall.hasVectorField(field::U) ? &wall.vectorField(field::U) : nullptr,
                     wall.hasVectorField(field::acceleration)
                         ? &wall.vectorField(field::acceleration)
                         : nullptr,
                     &wallPairs(w), &fluidAroundWall(w), nullptr});
    if (!hooks.predict || !loadMeasured_[w]) continue;
    const Vector otherForce(Real(otherLoads[6 * w]), Real(otherLoads[6 * w + 1]),
                            Real(otherLoads[6 * w + 2]));
    const Vector otherTorque(Real(otherLoads[6 * w + 3]), Real(otherLoads[6 * w + 4]),
                             Real(otherLoads[6 * w + 5]));
    walls.back().respond = [&, w, otherForce, otherTorque](const Vector& force,
                                                           const Vector& torque,
                                                           std::vector<Vector>& velocity) {
      if (hooks.predict(*walls_[w], force + otherForce, torque + otherTorque, deltaT, velocity)) {
        return;
      }
      const ParticleCloud& mold = *walls_[w];  // no body: as it moves
      velocity = mold.hasVectorField(field::U) ? mold.vectorField(field::U)
                                               : std::vector<Vector>(mold.size(), Vector::Zero());
    };
  }
  const Real spacing = static_cast<Real>(fluid_.attributes().at("spacing"));
  addWallTime(timings_.rates, [&] {
    lastPressureSolve_ =
        settings_.dimension == 2
            ? incompressiblePressure_.solve<2>(fluid_, neighbourhood_, walls, loadMeasured_, v,
                                               settings_.gravity, settings_.supportRadius, spacing,
                                               settings_.periodic, dt)
            : incompressiblePressure_.solve<3>(fluid_, neighbourhood_, walls, loadMeasured_, v,
                                               settings_.gravity, settings_.supportRadius, spacing,
                                               settings_.periodic, dt);
  });
  ++work_.pressureSolves;
  work_.pressureIterations += static_cast<std::uint64_t>(lastPressureSolve_.iterations);
  ++work_.flowSteps;
  work_.particleSteps += fluid_.ownedSize();
  // a solve left above its tolerance goes on (the run's health checks watch the density); the
  // log counts them
  if (!lastPressureSolve_.converged) ++work_.unconvergedPressureSolves;
  const auto& pressureAcceleration = incompressiblePressure_.pressureAcceleration();
  addWallTime(timings_.integration, [&] {
#pragma omp parallel for
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (frozen && frozen[i] != 0) {
        acceleration[i].setZero();
        v[i].setZero();
      } else {
        acceleration[i] = priorAcceleration_[i] + gravity + pressureAcceleration[i];
        v[i] += dt * pressureAcceleration[i];
      }
      densityRate[i] = 0;  // the density is summed, not integrated
    }
  });
  // the loads of the step: the viscous pass's (and the implicit solve's) and the pressure's
  const std::size_t owned = fluid_.ownedSize();
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (!loadMeasured_[w]) continue;
    Vector force = Vector::Zero(), torque = Vector::Zero();
    for (std::size_t i = 0; i < owned; ++i) {  // in particle order: the same on any threads
      force += incompressiblePressure_.wallForce(w)[i];
      torque += incompressiblePressure_.wallTorque(w)[i];
    }
    wallLoads_[w].force += force;
    wallLoads_[w].torque += torque;
  }
  if (hooks.kick) hooks.kick(deltaT, deltaT);
  const PeriodicBox periodic = settings_.periodic;
  addWallTime(timings_.integration, [&] {
#pragma omp parallel for
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = periodic.wrap(x[i] + dt * v[i]);
    neighbourhood_.syncHalo(fluid_, {field::U});
  });
  if (hooks.drift) hooks.drift(deltaT, deltaT);
}

}  // namespace sphcast
