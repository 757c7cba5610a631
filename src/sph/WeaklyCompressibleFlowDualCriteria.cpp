// timeStepping dualCriteria (doc/physics.md §9.1; Zhang, Hu & Adams 2017, J. Comput. Phys.
// 335:605, §2.3, as SPHinXsys steps): an advection step of the pair lists of the last search, the
// viscous term and the force models once at its start, then acoustic sub-steps, each a Verlet
// step of the pressure and the density,
//   rho += dt/2 Drho;  x += dt/2 v;  v += dt (a_p + g + a_prior);  x += dt/2 v;  rho += dt/2 Drho.
// The step's limits are in WeaklyCompressibleFlowStepLimits.cpp, the pair passes in
// WeaklyCompressibleFlowRates.cpp.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>

#include "core/Error.h"
#include "core/Log.h"
#include "particles/FieldNames.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {

// The viscous term and the force models at the start of an advection step, into
// priorAcceleration_ (the acceleration field keeps the last sub-step's total, which the first
// sub-step's limit reads), with what the pass put on the measured walls into priorLoads_.
void WeaklyCompressibleFlow::computePriorAcceleration() {
  auto& acceleration = fluid_.vectorField(field::acceleration);
  lastTotalAcceleration_.assign(acceleration.begin(), acceleration.end());
  computeRates(RatePart::viscous);
  priorAcceleration_.assign(acceleration.begin(), acceleration.end());
  acceleration.assign(lastTotalAcceleration_.begin(), lastTotalAcceleration_.end());
  priorLoads_ = wallLoads_;
}

void WeaklyCompressibleFlow::advectionStep(double deltaT, const SubStepHooks& hooks) {
  if (settings_.incompressible) {
    incompressibleStep(deltaT, hooks);
    return;
  }
  if (!settings_.dualCriteria) {
    throw Error("flow: advectionStep() is timeStepping dualCriteria's");
  }
  holdFrozenParticles();  // those frozen since the last step (by a heat step) too
  viscosityImplicit_ = solvesViscosityImplicitly(deltaT);
  addWallTime(timings_.rates, [&] {
    if (densityReinitialisation_) {
      densityReinitialisation_->apply(fluid_, walls_, neighbourhood_);
      updatePressure();
    }
    computePriorAcceleration();
  });
  ++work_.advectionSteps;
  double elapsed = 0;
  while (elapsed < deltaT) {
    std::string limiter;
    const double limit = acousticSubStepLimit(limiter);
    if (!(limit > 0) || !std::isfinite(limit)) {
      std::ostringstream problem;
      problem << "the acoustic sub-step's limit (" << limiter << ") is " << limit;
      throw Error(problem.str());
    }
    // equal sub-steps over what is left, none of them longer than the limit (a relative 1e-9
    // of slack, so that round-off in deltaT - elapsed adds no sliver of a sub-step)
    const double remaining = deltaT - elapsed;
    const double count = std::ceil(remaining / limit * (1 - 1e-9));
    const bool last = count <= 1;
    const double dt = last ? remaining : remaining / count;
    elapsed = last ? deltaT : elapsed + dt;
    acousticSubStep(static_cast<Real>(dt), hooks, elapsed);
  }
}

// One Verlet sub-step of the pressure and the density (advectionStep spells it out). The halo
// of a decomposed run drifts with its owners' velocities, so its positions stay theirs to the
// bit; its velocities and densities are refreshed after the passes that change them.
void WeaklyCompressibleFlow::acousticSubStep(Real dt, const SubStepHooks& hooks, double elapsed) {
  const Real halfDt = Real(0.5) * dt;
  auto& x = fluid_.positions();
  auto& v = fluid_.vectorField(field::U);
  auto& rho = fluid_.scalarField(field::rho);
  const auto& densityRate = fluid_.scalarField(field::densityRate);
  auto& acceleration = fluid_.vectorField(field::acceleration);
  const Real* frozen =
      fluid_.hasScalarField(field::frozen) ? fluid_.scalarField(field::frozen).data() : nullptr;
  const PeriodicBox periodic = settings_.periodic;
  addWallTime(timings_.integration, [&] {
#pragma omp parallel for
    for (std::size_t i = 0; i < x.size(); ++i) {
      rho[i] += halfDt * densityRate[i];
      x[i] = periodic.wrap(x[i] + halfDt * v[i]);
    }
    updatePressure();
  });
  if (hooks.drift) hooks.drift(dt, elapsed);
  addWallTime(timings_.rates, [&] { computeRates(RatePart::pressure); });
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (!loadMeasured_[w]) continue;
    wallLoads_[w].force += priorLoads_[w].force;
    wallLoads_[w].torque += priorLoads_[w].torque;
  }
  addWallTime(timings_.integration, [&] {
#pragma omp parallel for
    for (std::size_t i = 0; i < x.size(); ++i) {
      acceleration[i] += priorAcceleration_[i];
      if (frozen && frozen[i] != 0) {  // held (holdFrozenParticles)
        acceleration[i].setZero();
        v[i].setZero();
      }
      v[i] += dt * acceleration[i];
    }
  });
  // a viscosity solved implicitly: U stepped by it over the sub-step, backward in time, as
  // after kick-drift-kick's second kick (one solve over the whole advection step is first order
  // in a step many diffusion times long: a Couette start-up 13 % off at a tenth of L^2 / nu)
  if (viscosityImplicit_) solveViscosity(dt);
  // the halo drifts with its owners' velocities (its own rates lack its far neighbours)
  neighbourhood_.syncHalo(fluid_, {field::U});
  addWallTime(timings_.integration, [&] {
#pragma omp parallel for
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = periodic.wrap(x[i] + halfDt * v[i]);
  });
  addWallTime(timings_.rates, [&] { computeRates(RatePart::densityRate); });
  addWallTime(timings_.integration, [&] {
#pragma omp parallel for
    for (std::size_t i = 0; i < x.size(); ++i) rho[i] += halfDt * densityRate[i];
    neighbourhood_.syncHalo(fluid_, {field::rho, field::densityRate});
    updatePressure();
  });
  ++work_.acousticSubSteps;
  if (hooks.kick) hooks.kick(dt, elapsed);
}

double WeaklyCompressibleFlow::acousticSubStepLimit(std::string& limiter) const {
  const FlowStepLimits limits = allStepLimits(settings_.acousticCo);
  const std::pair<double, const char*> candidates[] = {{limits.acoustic, "acoustic CFL"},
                                                       {limits.acceleration, "acceleration"},
                                                       {limits.densityRate, "density rate"}};
  const auto* smallest =
      std::min_element(std::begin(candidates), std::end(candidates),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
  limiter = smallest->second;
  // every rank takes the same sub-step
  return -neighbourhood_.maxOverRanks(-smallest->first);
}

}  // namespace sphcast
