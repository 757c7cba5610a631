#include "particles/FieldNames.h"
#include "sph/WeaklyCompressibleFlow.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <type_traits>

#include <Eigen/Geometry>

#include "core/Error.h"
#include "sph/EquationOfState.h"
#include "sph/FlowRates.h"

// The flow's pair loops: the walls' pressure, the kernel correction, the rates (density rate and
// acceleration, with the force models after them) and the frozen metal they skip. The step, its
// integration and the walls' loads and clearance are in WeaklyCompressibleFlow.cpp, its limits
// in WeaklyCompressibleFlowStepLimits.cpp.

namespace sphcast {

template <int Dim>
void WeaklyCompressibleFlow::extrapolateWallPressure() {
  const WendlandC2Kernel<Dim> kernel(settings_.supportRadius);
  const PeriodicBox periodic = settings_.periodic;
  const auto& x = fluid_.positions();
  const auto& rho = fluid_.scalarField(field::rho);
  const auto& p = fluid_.scalarField(field::p);
  const Vector gravity = settings_.gravity;
  // as in computeRatesFor: the minimum image only when an axis is periodic, chosen once
  auto extrapolateWith = [&](auto separation) {
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      const auto& wallX = walls_[w]->positions();
      const NeighbourList& fluidAround = fluidAroundWall(w);
      wallPressure_[w].resize(wallX.size());  // a decomposed run's walls change with a re-balance
      Real* wallPressure = wallPressure_[w].data();
      // a moving wall's particles feel g - a_wall (eq. (27))
      const Vector* wallAcceleration = walls_[w]->hasVectorField(field::acceleration)
                                           ? walls_[w]->vectorField(field::acceleration).data()
                                           : nullptr;
#pragma omp parallel for schedule(static)
      for (std::size_t k = 0; k < wallX.size(); ++k) {
        WallPressureSums sums;
        for (const std::uint32_t f : fluidAround.of(k)) {
          const Vector xkf = separation(wallX[k], x[f]);
          sums.add(kernel.value(xkf.norm()), p[f], rho[f], xkf);
        }
        wallPressure[k] =
            sums.wallPressure(wallAcceleration ? Vector(gravity - wallAcceleration[k]) : gravity);
      }
    }
  };
  if (periodic.anyPeriodic()) {
    extrapolateWith(
        [periodic](const Vector& a, const Vector& b) { return periodic.separation(a, b); });
  } else {
    extrapolateWith([](const Vector& a, const Vector& b) { return Vector(a - b); });
  }
  // a halo wall particle's fluid lies partly beyond the halo: its pressure is its owner's
  for (std::size_t w = 0; w < walls_.size(); ++w)
    neighbourhood_.syncHalo(*walls_[w], wallPressure_[w]);
}

// L_i of every fluid particle from its fluid and wall neighbours (walls complete the kernel
// there, so a particle on a wall is corrected as an interior one) and, for deltaSPH, the
// renormalised density gradient L_i sum_j V_j (rho_j - rho_i) grad_i W_ij of Antuono et al.
// (2010), wall particles taking the density of their extrapolated pressure.
template <int Dim>
void WeaklyCompressibleFlow::computeCorrection() {
  const WendlandC2Kernel<Dim> kernel(settings_.supportRadius);
  const LinearEquationOfState eos{settings_.soundSpeed};
  const PeriodicBox periodic = settings_.periodic;
  const bool densityGradient = settings_.densityScheme == "deltaSPH";
  const auto& x = fluid_.positions();
  const auto& rho = fluid_.scalarField(field::rho);
  const auto& mass = fluid_.scalarField(field::mass);
  const auto& restDensity = fluid_.scalarField(field::restDensity);
  correction_.resize(x.size());
  densityGradient_.resize(densityGradient ? x.size() : 0);
  std::vector<const Real*> wallVolume;  // looked up once, not per particle
  for (const ParticleCloud* wall : walls_)
    wallVolume.push_back(wall->scalarField(field::volume).data());
  const NeighbourList& fluidList = fluidPairs();
  std::vector<const NeighbourList*> wallLists;
  for (std::size_t w = 0; w < walls_.size(); ++w) wallLists.push_back(&wallPairs(w));
  // as in computeRatesFor: the minimum image only when an axis is periodic, chosen once
  // the owned particles: a decomposed run's halo takes its owners' L (syncHalo below)
  const std::size_t owned = fluid_.ownedSize();
  auto correctWith = [&](auto separation) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < owned; ++i) {
      CorrectionMoment moment;
      Vector gradientSum = Vector::Zero();
      for (const std::uint32_t j : fluidList.of(i)) {
        const Vector xij = separation(x[i], x[j]);
        const Real factor = kernel.derivativeOverDistance(xij.norm());
        const Real volumeJ = mass[j] / rho[j];
        moment.add(volumeJ, factor, xij);
        gradientSum += (volumeJ * (rho[j] - rho[i]) * factor) * xij;
      }
      for (std::size_t w = 0; w < walls_.size(); ++w) {
        const auto& wallX = walls_[w]->positions();
        const Real* volume = wallVolume[w];
        for (const std::uint32_t k : wallLists[w]->of(i)) {
          const Vector xik = separation(x[i], wallX[k]);
          const Real factor = kernel.derivativeOverDistance(xik.norm());
          moment.add(volume[k], factor, xik);
          const Real wallDensity = eos.density(wallPressure_[w][k], restDensity[i]);
          gradientSum += (volume[k] * (wallDensity - rho[i]) * factor) * xik;
        }
      }
      correction_[i] = correctionMatrix(moment.sum, Dim);
      if (densityGradient) densityGradient_[i] = correction_[i] * gradientSum;
    }
  };
  if (periodic.anyPeriodic()) {
    correctWith([periodic](const Vector& a, const Vector& b) { return periodic.separation(a, b); });
  } else {
    correctWith([](const Vector& a, const Vector& b) { return Vector(a - b); });
  }
  // the rates read L_j and the density gradient at the neighbours: a halo's from its owners
  if (settings_.kernelCorrection) neighbourhood_.syncHalo(fluid_, correction_);
  if (densityGradient) neighbourhood_.syncHalo(fluid_, densityGradient_);
}

template <int Dim, class Interface, class Viscosity, WeaklyCompressibleFlow::RatePart Part>
void WeaklyCompressibleFlow::computeRatesFor() {
  constexpr bool wantsDensityRate = Part == RatePart::both || Part == RatePart::densityRate;
  constexpr bool wantsAcceleration = Part != RatePart::densityRate;
  // the viscous pass of dualCriteria leaves gravity to the pressure's (no pair term needs it)
  constexpr bool withGravity = Part != RatePart::viscous;
  // the colour gradient is the force models', which dualCriteria evaluates with the viscosity
  constexpr bool withForceModels = wantsAcceleration && Part != RatePart::pressure;
  // dualCriteria's density pass follows its pressure pass with the same densities: the walls'
  // pressures are those it extrapolated (the fluid moved by half a sub-step since)
  if (!(Part == RatePart::densityRate && settings_.dualCriteria)) extrapolateWallPressure<Dim>();
  if (needsCorrectionMatrix(Part)) computeCorrection<Dim>();
  const LinearEquationOfState eos{settings_.soundSpeed};
  const WendlandC2Kernel<Dim> kernel(settings_.supportRadius);
  const Real spacing = static_cast<Real>(fluid_.attributes().at("spacing"));
  // a melt with a cavitation floor: its wall pairs carry its tension down to the floor
  const bool tensionFloored = settings_.cavitationPressure > std::numeric_limits<Real>::lowest();
  const FlowConstants constants{settings_.soundSpeed, settings_.gravity,
                                Real(0.01) * spacing * spacing,
                                tensionFloored ? settings_.cavitationPressure : Real(0)};
  const PeriodicBox periodic = settings_.periodic;
  const auto& x = fluid_.positions();
  const auto& v = fluid_.vectorField(field::U);
  const auto& rho = fluid_.scalarField(field::rho);
  const auto& p = fluid_.scalarField(field::p);
  const auto& mass = fluid_.scalarField(field::mass);
  const auto& mu = fluid_.scalarField(field::viscosity);
  const auto& restDensity = fluid_.scalarField(field::restDensity);
  auto& densityRate = fluid_.scalarField(field::densityRate);
  auto& acceleration = fluid_.vectorField(field::acceleration);
  struct WallArrays {
    const Vector* position;
    const Real* volume;
    const Vector* normal;
    const Real* depth;
    const Real* pressure;
    const NeighbourList* neighbours;
    const Vector* velocity;  // null: at rest
    Vector* loadForce;       // per fluid particle, null unless the load is measured
    Vector* loadTorque;
    WallCondition condition;
  };
  std::vector<WallArrays> walls;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const bool measured = loadMeasured_[w] && wantsAcceleration;
    if (measured) {
      loadForce_[w].resize(x.size());
      loadTorque_[w].resize(x.size());
    }
    walls.push_back(
        {walls_[w]->positions().data(), walls_[w]->scalarField(field::volume).data(),
         walls_[w]->vectorField(field::normal).data(),
         walls_[w]->scalarField(field::wallDistance).data(), wallPressure_[w].data(), &wallPairs(w),
         walls_[w]->hasVectorField(field::U) ? walls_[w]->vectorField(field::U).data() : nullptr,
         measured ? loadForce_[w].data() : nullptr, measured ? loadTorque_[w].data() : nullptr,
         settings_.walls.of(walls_[w]->name())});
  }
  const Real halfSpacing = Real(0.5) * spacing;
  const Vector gravity = settings_.gravity;
  const bool corrected = settings_.kernelCorrection;
  const Matrix* correction = correction_.data();
  // deltaSPH: diffusion delta h c and artificial viscosity alpha h c, with h the smoothing
  // length, half the Wendland support radius (Antuono et al. 2010 write W with support 2h)
  const bool diffusive = settings_.densityScheme == "deltaSPH";
  // the density gradient exists only where the pass computed it (not for the acceleration)
  const bool diffusiveDensity = diffusive && wantsDensityRate;
  const Real smoothingLength = Real(0.5) * settings_.supportRadius;
  const Real diffusion = settings_.deltaSPHDiffusion * smoothingLength * settings_.soundSpeed;
  const Real artificialViscosity =
      diffusive ? settings_.deltaSPHViscosity * smoothingLength * settings_.soundSpeed : Real(0);
  const Vector* densityGradient = densityGradient_.data();
  const std::uint64_t* fluidBegins = fluidPairs().offsets().data();
  const std::uint64_t* fluidEnds = fluidPairs().ends().data();
  const std::uint32_t* fluidNeighbours = fluidPairs().neighbours().data();
  // Frozen particles with no melt within two neighbour hops (solidified metal away from the
  // melt) have nothing to compute: no acceleration (they are held), and a density that only the
  // melt moving against them would change. One hop is not enough: the melt feels the pressure of
  // the frozen particles within h, and theirs depends on their own frozen neighbours (measured:
  // with one hop a pocket of melt in frozen metal settled 0.7 dx lower, its particles to 0.44 dx).
  // (decided by the field, not by its storage: a rank that has held no metal yet has none, and
  // every rank must take part in markFrozenNearMelt's halo refresh)
  const bool solidifies = fluid_.hasScalarField(field::frozen);
  const Real* frozen = solidifies ? fluid_.scalarField(field::frozen).data() : nullptr;
  const std::uint8_t* nearMelt = nullptr;
  std::uint64_t skipped = 0;
  if (solidifies) {
    skipped = markFrozenNearMelt();
    nearMelt = frozenNearMelt_.data();
  }
  if constexpr (wantsAcceleration && Part != RatePart::viscous) {  // once per flow step
    ++work_.flowSteps;
    work_.particleSteps += x.size();
    work_.skippedFrozen += skipped;
  }

  // The pair loop, given how it takes x_i - x_j: the minimum image only when an axis is
  // periodic, chosen once per pass (with no periodic axis separation() is x_i - x_j).
  // The fluid neighbours of i are taken in chunks: first the geometry of every pair of the
  // chunk (x_ij, r, dW/dr / r), a loop whose pairs do not depend on each other, so the square
  // roots and kernel polynomials of many pairs are in flight at once (measured: a step 11 %
  // faster than one pair at a time); then the physics, pair by pair in list order. The values
  // are those of kernel.gradient(xij, r), bit for bit.
  constexpr std::size_t chunk = 64;
  // A fluid particle at least h inside every periodic face, of a fluid whose particles all lie
  // in the periodic box (the grid checked it: imagesByCell), has no neighbour across a face:
  // for each of its neighbours |x_i - x_j| < h < period / 2, where separation() subtracts
  // nothing. Its pairs take the plain difference, chosen once per particle.
  const bool inBox = periodic.anyPeriodic() && neighbourhood_.grid(fluid_).imagesByCell();
  Vector interiorLower = Vector::Constant(-std::numeric_limits<Real>::max());
  Vector interiorUpper = Vector::Constant(std::numeric_limits<Real>::max());
  for (int a = 0; a < 3; ++a) {
    if (!periodic.isPeriodic(a)) continue;
    const Real margin = settings_.supportRadius * Real(1.000001);  // round-off in x_i +- h
    interiorLower[a] = periodic.lower(a) + margin;
    interiorUpper[a] = periodic.lower(a) + periodic.period(a) - margin;
  }
  // The colour gradient a force model asked for (FluidForceModel::colourGradientBuffer), summed
  // here beside the pressure, with the grad W the pair loop has anyway. A flag that never
  // changes within the pass, not another type: a type would double the pass's instantiations
  // for one multiply-add per pair (3 % of a flow step when on, tests/benchmarks/README.md).
  Vector* colourGradient = nullptr;
  const Real* pairVolume = nullptr;
  if constexpr (withForceModels) {
    if (!colourGradientBuffers_.empty()) {
      colourGradientBuffers_.front()->resize(x.size());
      colourGradient = colourGradientBuffers_.front()->data();
      pairVolume_.resize(x.size());
      for (std::size_t j = 0; j < x.size(); ++j) pairVolume_[j] = mass[j] / rho[j];
      pairVolume = pairVolume_.data();
    }
  }
  auto plainDifference = [](const Vector& a, const Vector& b) { return Vector(a - b); };
  // The owned particles only: a decomposed run's halo lacks its far neighbours, so its rates
  // would be wrong. Nothing reads them: the kicks refresh the halo's velocity and density from
  // the owners (syncHalo), and the search its every field.
  const std::size_t owned = fluid_.ownedSize();
  auto ratesWith = [&](auto separation) {
    auto ratesOf = [&](std::size_t i) {
      if (frozen && frozen[i] != 0 && !nearMelt[i]) {
        if constexpr (wantsDensityRate) densityRate[i] = 0;
        if constexpr (wantsAcceleration) acceleration[i] = Vector::Zero();
        for (const WallArrays& wall : walls) {
          if (wall.loadForce) wall.loadForce[i] = wall.loadTorque[i] = Vector::Zero();
        }
        if (colourGradient) {
          colourGradient[i] = Vector::Constant(std::numeric_limits<Real>::quiet_NaN());
        }
        return;
      }
      const Vector xi = x[i];
      const Vector vi = v[i];
      const Real muI = mu[i];
      const InterfaceSide self{rho[i], p[i], vi};
      Real rate = 0;
      Vector accel = withGravity ? gravity : Vector::Zero();
      Vector colour = Vector::Zero();  // the colour gradient, when asked for
      const bool interior = inBox && (xi.array() >= interiorLower.array()).all() &&
                            (xi.array() <= interiorUpper.array()).all();
      const Matrix correctionI = corrected ? correction[i] : Matrix::Identity();
      const Vector densityGradientI = diffusiveDensity ? densityGradient[i] : Vector::Zero();
      const Real viscousScale = artificialViscosity * restDensity[i] / rho[i];
      // frozen metal near the melt: held, so only its density rate counts among fluid pairs
      // (its wall pairs stay whole: a body's load includes them)
      // (and every particle in a pass of the density rate alone, without deltaSPH's terms)
      const bool densityOnly = wantsDensityRate && !diffusive &&
                               (Part == RatePart::densityRate || (frozen && frozen[i] != 0));
      Real xijX[chunk], xijY[chunk], xijZ[chunk], distance[chunk], gradientFactor[chunk];
      for (std::uint64_t first = fluidBegins[i]; first < fluidEnds[i]; first += chunk) {
        const std::size_t pairs = std::min<std::uint64_t>(chunk, fluidEnds[i] - first);
        const std::uint32_t* neighbourJ = fluidNeighbours + first;
        auto geometryWith = [&](auto pairSeparation) {
          for (std::size_t n = 0; n < pairs; ++n) {
            const Vector xij = pairSeparation(xi, x[neighbourJ[n]]);
            const Real r = xij.norm();
            xijX[n] = xij[0], xijY[n] = xij[1], xijZ[n] = xij[2];
            distance[n] = r;
            gradientFactor[n] = kernel.derivativeOverDistance(r);  // grad W = this x_ij
          }
        };
        if (interior) {
          geometryWith(plainDifference);
        } else {
          geometryWith(separation);
        }
        for (std::size_t n = 0; n < pairs; ++n) {
          const std::uint32_t j = neighbourJ[n];
          const Vector xij(xijX[n], xijY[n], xijZ[n]);
          const Vector gradW = gradientFactor[n] * xij;
          // 0.5 (L_i + L_j) grad_i W_ij stays antisymmetric: momentum is conserved exactly
          const Vector pairGradW =
              corrected ? Vector(Real(0.5) * (correctionI * gradW + correction[j] * gradW)) : gradW;
          if (densityOnly) {
            FluidPair<Dim, Interface, Viscosity>::accumulateDensityRate(
                self, {rho[j], p[j], v[j]}, mass[j], xij, distance[n], pairGradW, constants, rate);
          } else {
            FluidPair<Dim, Interface, Viscosity>::accumulate(
                self, {rho[j], p[j], v[j]}, mass[j], muI, mu[j], vi - v[j], xij, distance[n],
                pairGradW, constants, rate, accel);
          }
          if (colourGradient) colour -= (pairVolume[j] * gradientFactor[n]) * xij;
          if (diffusive) {
            DeltaSPHPair::accumulate(rho[i], rho[j], densityGradientI,
                                     diffusiveDensity ? densityGradient[j] : Vector::Zero(),
                                     mass[j] / rho[j], vi - v[j], xij, distance[n], gradW,
                                     diffusion, viscousScale, constants, rate, accel);
          }
        }
      }
      for (const WallArrays& wall : walls) {
        // a measured wall's pairs are summed apart, so that the wall gets their exact negative
        Vector wallForce = Vector::Zero(), wallTorque = Vector::Zero();
        for (const std::uint32_t k : wall.neighbours->of(i)) {
          const Vector xik = separation(xi, wall.position[k]);
          const Real r = xik.norm();
          const Vector wallVelocity = wall.velocity ? wall.velocity[k] : Vector::Zero();
          const WallParticle particle{
              wallVelocity,  wall.normal[k],   wall.volume[k],
              wall.depth[k], wall.pressure[k], eos.density(wall.pressure[k], restDensity[i])};
          const Vector gradW = kernel.gradient(xik, r);
          if (colourGradient) colour -= (wall.volume[k] * kernel.derivativeOverDistance(r)) * xik;
          Vector pairAcceleration = Vector::Zero();
          Vector& target = wall.loadForce ? pairAcceleration : accel;
          accumulateWallPair<Dim, Interface, Viscosity>(
              self, muI, particle, halfSpacing, xik, r,
              corrected ? Vector(correctionI * gradW) : gradW, constants, wall.condition, rate,
              target);
          if (diffusive) {
            // deltaSPH's artificial viscosity against the mirror velocity 2 v_wall - v_i:
            // without it a means interface has no dissipation at an impact on a wall
            const Real etaSquared = constants.viscosityRegularisation;
            const Vector relative =
                wall.condition.artificialViscosityVelocity(vi - wallVelocity, wall.normal[k]);
            target += (viscousScale * wall.volume[k] * Real(2) * relative.dot(xik) /
                       (r * r + etaSquared)) *
                      gradW;
          }
          if (wall.loadForce) {
            accel += pairAcceleration;
            const Vector onWall = -mass[i] * pairAcceleration;
            wallForce += onWall;
            wallTorque += wall.position[k].cross(onWall);
          }
        }
        if (wall.loadForce) {
          wall.loadForce[i] = wallForce;
          wall.loadTorque[i] = wallTorque;
        }
      }
      if constexpr (wantsDensityRate) densityRate[i] = rate;
      if constexpr (wantsAcceleration) acceleration[i] = accel;
      if (colourGradient) colourGradient[i] = colour;
    };
    // Where frozen metal is skipped it lies in runs of the cell order, and equal static shares
    // leave a thread idle: shared out dynamically then (conicalMold's whole run 7 % faster on 2
    // threads), statically where nothing is skipped. Each particle's rates are its own: the same
    // bits either way.
    if (skipped > 0) {
#pragma omp parallel for schedule(dynamic, 64)
      for (std::size_t i = 0; i < owned; ++i) ratesOf(i);
    } else {
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < owned; ++i) ratesOf(i);
    }
  };
  if (periodic.anyPeriodic()) {
    ratesWith([periodic](const Vector& a, const Vector& b) { return periodic.separation(a, b); });
  } else {
    ratesWith(plainDifference);
  }
  if constexpr (wantsAcceleration) sumWallLoads();
  if (colourGradient) {
    for (std::size_t m = 1; m < colourGradientBuffers_.size(); ++m) {
      *colourGradientBuffers_[m] = *colourGradientBuffers_.front();
    }
  }
}

// The numerics are chosen by type once per pass, never by `if` inside the pair loop.
template <int Dim, class Interface>
void WeaklyCompressibleFlow::computeRatesWithInterface(RatePart part) {
  // dualCriteria's sub-step: the pressure alone (its viscosity is in the prior acceleration);
  // deltaSPH takes its own Stormer-Verlet step, never this one
  if constexpr (!std::is_same_v<Interface, DeltaSPHInterface>) {
    if (part == RatePart::pressure) {
      computeRatesFor<Dim, Interface, ImplicitlySolvedViscosity, RatePart::pressure>();
      return;
    }
  }
  auto withViscosity = [&]<class Viscosity>() {
    switch (part) {
      case RatePart::both:
        computeRatesFor<Dim, Interface, Viscosity, RatePart::both>();
        break;
      case RatePart::densityRate:
        computeRatesFor<Dim, Interface, Viscosity, RatePart::densityRate>();
        break;
      case RatePart::acceleration:
        computeRatesFor<Dim, Interface, Viscosity, RatePart::acceleration>();
        break;
      case RatePart::pressure:  // above (deltaSPH refuses dualCriteria)
      case RatePart::viscous:   // computeRatesInDimension
        throw Error(std::string("flow: no such pass for densityScheme ") + Interface::name);
    }
  };
  if (viscosityImplicit_ && part != RatePart::densityRate) {
    withViscosity.template operator()<ImplicitlySolvedViscosity>();
  } else if (settings_.viscousForm == "Morris") {
    withViscosity.template operator()<MorrisViscosity>();
  } else {
    withViscosity.template operator()<ClearyViscosity>();
  }
}

template <int Dim>
void WeaklyCompressibleFlow::computeRatesInDimension(RatePart part) {
  if (part == RatePart::viscous) {  // dualCriteria's prior acceleration
    using Viscous = ViscousTermOnlyInterface;
    if (viscosityImplicit_) {
      computeRatesFor<Dim, Viscous, ImplicitlySolvedViscosity, RatePart::viscous>();
    } else if (settings_.viscousForm == "Morris") {
      computeRatesFor<Dim, Viscous, MorrisViscosity, RatePart::viscous>();
    } else {
      computeRatesFor<Dim, Viscous, ClearyViscosity, RatePart::viscous>();
    }
    return;
  }
  if (settings_.densityScheme == "riemann") {
    computeRatesWithInterface<Dim, AcousticRiemannInterface>(part);
  } else if (settings_.densityScheme == "standard") {
    computeRatesWithInterface<Dim, ArithmeticMeanInterface>(part);
  } else {  // deltaSPH, whose extra terms are added in the same pass
    computeRatesWithInterface<Dim, DeltaSPHInterface>(part);
  }
}

void WeaklyCompressibleFlow::computeRates(RatePart part) {
  if (settings_.dimension == 2) {
    computeRatesInDimension<2>(part);
  } else {
    computeRatesInDimension<3>(part);
  }
  if (part == RatePart::densityRate || part == RatePart::pressure) return;
  for (FluidForceModel* model : forceModels_) model->addAcceleration();
  holdFrozenParticles();
}

// For each particle, whether a melt (not frozen) particle, or a wall whose load is measured (a
// moving body), lies within two neighbour hops: 1 for melt and the frozen particles it reaches
// that way (computeRatesFor skips the others). A body resting on solidified metal is carried by
// it: without its pairs the frozen metal gave the body no force, and a punch sank through the
// casting to its end stop (tutorials/semiSolidPress).
std::uint64_t WeaklyCompressibleFlow::markFrozenNearMelt() {
  const auto& frozen = fluid_.scalarField(field::frozen);
  const std::uint64_t* begins = fluidPairs().offsets().data();
  const std::uint64_t* ends = fluidPairs().ends().data();
  const std::uint32_t* neighbours = fluidPairs().neighbours().data();
  const std::size_t count = frozen.size();
  frozenTouchesMelt_.assign(count, 0);
  frozenNearMelt_.assign(count, 0);
  std::vector<const NeighbourList*> bodyPairs;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (loadMeasured_[w]) bodyPairs.push_back(&wallPairs(w));
  }
  // Each hop is taken from the smaller side. Where the melt is the smaller part, it marks its
  // neighbours (scattered: only the melt's rows are read, not every frozen row to its end;
  // conicalMold, mostly frozen: 6.2 % of the run on one thread to 2.4 %); where the frozen metal
  // is, each frozen particle looks for the melt in its own row (gathered: a melt particle reads
  // nothing; crossDitchPress's pour, mostly melt: flow rates 61 s scattered, 60 s so). The pair
  // lists are symmetric (j lies in i's row when i lies in j's), so both give the same marks; the
  // halo's rows hold the rank's own particles, so an owned particle's marks are complete.
  auto mark = [](std::uint8_t& flag) {
    std::atomic_ref<std::uint8_t>(flag).store(1, std::memory_order_relaxed);
  };
  // the next hop's marks in `to` from the particles `from` marks (sources: marked, not spreading)
  auto spread = [&](auto from, std::vector<std::uint8_t>& to, auto isSource) {
    std::size_t marked = 0;
#pragma omp parallel for schedule(static) reduction(+ : marked)
    for (std::size_t i = 0; i < count; ++i) marked += from(i) ? 1 : 0;
    if (2 * marked < count) {
#pragma omp parallel for schedule(dynamic, 256)
      for (std::size_t i = 0; i < count; ++i) {
        if (!from(i) && !isSource(i)) continue;
        mark(to[i]);
        if (!from(i)) continue;
        for (std::uint64_t k = begins[i]; k < ends[i]; ++k) mark(to[neighbours[k]]);
      }
    } else {
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < count; ++i) {
        bool near = from(i) || isSource(i);
        for (std::uint64_t k = begins[i]; k < ends[i] && !near; ++k) near = from(neighbours[k]);
        to[i] = near ? 1 : 0;
      }
    }
  };
  spread([&](std::size_t i) { return frozen[i] == 0; }, frozenTouchesMelt_,
         [&](std::size_t i) {
           for (const NeighbourList* pairs : bodyPairs) {
             if (i < pairs->particleCount() && !pairs->of(i).empty()) return true;
           }
           return false;
         });
  neighbourhood_.syncHalo(fluid_, frozenTouchesMelt_);  // the second hop reads the neighbours
  spread([&](std::size_t i) { return frozenTouchesMelt_[i] != 0; }, frozenNearMelt_,
         [](std::size_t) { return false; });
  std::uint64_t skipped = 0;
#pragma omp parallel for schedule(static) reduction(+ : skipped)
  for (std::size_t i = 0; i < count; ++i) skipped += frozenNearMelt_[i] == 0 ? 1 : 0;
  return skipped;
}

}  // namespace sphcast
