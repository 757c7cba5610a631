// The flow's step limits (doc/physics.md §9): each limit of a kick-drift-kick step, of
// dualCriteria's advection step and of the incompressible step, and which binds.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <utility>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast {

double FlowStepLimits::smallest(std::string& limiter) const {
  const std::pair<double, const char*> limits[] = {
      {acoustic, "acoustic CFL"},    {viscous, "viscous"},
      {bodyForce, "body force"},     {acceleration, "acceleration"},
      {densityRate, "density rate"}, {forceModel, forceModelName.c_str()},
      {advection, "advection"}};
  const auto* smallest = std::min_element(  // of equal limits the first, as before
      std::begin(limits), std::end(limits),
      [](const auto& a, const auto& b) { return a.first < b.first; });
  limiter = smallest->second;
  return smallest->first;
}

FlowStepLimits WeaklyCompressibleFlow::stepLimits(double maxCo, bool advectionStep) const {
  FlowStepLimits limits = allStepLimits(maxCo);
  const double infinite = std::numeric_limits<double>::max();
  if (settings_.incompressible) advectionStep = true;  // no sound speed, no sub-steps
  if (advectionStep) {  // the sub-steps' (acousticSubStepLimit)
    limits.acoustic = limits.acceleration = limits.densityRate = infinite;
  } else {
    limits.advection = infinite;
  }
  // A viscosity solved implicitly sets no limit: always (implicit), or where its explicit limit
  // is below every other (auto: solvesViscosityImplicitly then takes the step's length for it).
  if (settings_.viscositySolver == ViscositySolver::implicitForm) {
    limits.viscous = infinite;
  } else if (settings_.viscositySolver == ViscositySolver::automatic && !settings_.incompressible) {
    // (the incompressible step keeps the explicit limit under auto: its viscous solve comes
    // before the pressure's, and over steps many diffusion times long that splitting let a
    // squeezed film out twice as fast as Reynolds' (doc/physics.md §9.2))
    const double others = std::min({limits.acoustic, limits.bodyForce, limits.acceleration,
                                    limits.densityRate, limits.forceModel, limits.advection});
    // (an incompressible flow at rest without gravity has no other limit: its first step is
    // the viscous one, and the flow speed sets the next)
    if (limits.viscous < others && others < infinite) limits.viscous = infinite;
  }
  if (advectionStep && !settings_.incompressible) {
    // A whole number of acoustic sub-steps: a step of 1.1 sub-steps' length would take two
    // sub-steps of 0.55, a search and a viscous pass for 1.1 sub-steps of flow; one of 1.0
    // takes one (Koshizuka & Oka's dam break at a/dx = 40: 809 advection steps of 1,930
    // sub-steps became 1,083 of 1,467, the run 5.29 s against 5.55 s, the front the same).
    // (Collective: the sub-step's limit is every rank's.)
    std::string limiter;
    const double acoustic = acousticSubStepLimit(limiter);
    const double step =
        std::min({limits.advection, limits.viscous, limits.bodyForce, limits.forceModel});
    const double whole = std::floor(step / acoustic);
    if (whole >= 1 && whole * acoustic < limits.advection) limits.advection = whole * acoustic;
  }
  return limits;
}

FlowStepLimits WeaklyCompressibleFlow::allStepLimits(double maxCo) const {
  const auto& v = fluid_.vectorField(field::U);
  const auto& rho = fluid_.scalarField(field::rho);
  const auto& mu = fluid_.scalarField(field::viscosity);
  const auto& a = fluid_.vectorField(field::acceleration);
  const auto& densityRate = fluid_.scalarField(field::densityRate);
  double fastest = 0;
  double largestAcceleration = 0;
  double largestRelativeDensityRate = 0;
  double largestKinematicViscosity = 0;
  const std::size_t owned = fluid_.ownedSize();  // a decomposed run's halo is its owners'
#pragma omp parallel for reduction(max                                                         \
                                   : fastest, largestAcceleration, largestRelativeDensityRate, \
                                     largestKinematicViscosity)
  for (std::size_t i = 0; i < owned; ++i) {
    fastest = std::max(fastest, static_cast<double>(v[i].norm()));
    largestAcceleration = std::max(largestAcceleration, static_cast<double>(a[i].norm()));
    largestRelativeDensityRate = std::max(largestRelativeDensityRate,
                                          static_cast<double>(std::abs(densityRate[i] / rho[i])));
    largestKinematicViscosity =
        std::max(largestKinematicViscosity, static_cast<double>(mu[i] / rho[i]));
  }
  for (const ParticleCloud* wall : walls_) {  // a moving mold's speed counts as the fluid's
    if (!wall->hasVectorField(field::U)) continue;
    for (const Vector& u : wall->vectorField(field::U)) {
      fastest = std::max(fastest, static_cast<double>(u.norm()));
    }
  }
  const auto spacing = fluid_.attributes().find("spacing");
  if (spacing == fluid_.attributes().end()) {
    throw Error("cloud '" + fluid_.name() + "' has no 'spacing' attribute (the particle spacing)");
  }
  // The viscous and body-force limits (Morris et al. 1997; Monaghan 1992) are written for a
  // smoothing length of about one particle spacing, so they take dx, not the support radius
  // (with h = 3 dx, 0.125 h^2 / nu is 9 times too long and the Poiseuille test blows up).
  const double dx = spacing->second;
  const double g = static_cast<double>(settings_.gravity.norm());
  const double infinite = std::numeric_limits<double>::max();
  // The density-rate limit: at a collision of two streams faster than about c/3 (the torus of
  // issue #9: 2.5 m/s against 2.5 m/s at c = 16 m/s) the Riemann interface dissipates at its
  // full strength and the densities change by 8 % a step; at maxCo 0.25 the run then blew up
  // within 0.015 s (density -30 .. +85 %), at maxCo 0.1 it recovered from the same state to
  // within 1 %. No density changing by more than 2 % a step binds only there (0.2 % a step is
  // typical: the same torus before the collision, 1.9 % at its onset).
  const double maxDensityChange = 0.02;
  // The force criterion of Monaghan (1992) on the total acceleration: an impact on a wall
  // accelerates the front particles far beyond g for a few steps, and a step that lets them
  // travel more than dx / 32 under that acceleration lets them into the wall (the acoustic limit
  // alone does not see it: |v| is still small when |a| is large).
  double forceLimit = infinite;
  std::string forceLimiter = "force model";
  for (const FluidForceModel* model : forceModels_) {
    const double limit = model->stableDeltaT();
    if (limit < forceLimit) {
      forceLimit = limit;
      forceLimiter = model->limitName();
    }
  }
  FlowStepLimits limits{
      maxCo * dx / (settings_.soundSpeed + fastest),
      largestKinematicViscosity > 0 ? 0.125 * dx * dx / largestKinematicViscosity : infinite,
      g > 0 ? 0.25 * std::sqrt(dx / g) : infinite,
      largestAcceleration > 0 ? 0.25 * std::sqrt(dx / largestAcceleration) : infinite,
      largestRelativeDensityRate > 0 ? maxDensityChange / largestRelativeDensityRate : infinite,
      forceLimit, forceLimiter,
      // dualCriteria: no particle moves more than advectionCo dx between two searches
      fastest > 0 ? (settings_.incompressible ? settings_.pressureSolver.advectionCo
                                              : settings_.advectionCo) *
                        dx / fastest
                  : infinite};
  return limits;
}

}  // namespace sphcast
