// The pressure of implicit incompressible SPH (IncompressiblePressure.h gives the equations).
#include "sph/IncompressiblePressure.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"

namespace sphcast {


template <int Dim>
IncompressibleReport IncompressiblePressure::solve(
    ParticleCloud& fluid, const Neighbourhood& neighbourhood,
    const std::vector<PressureWall>& walls, const std::vector<bool>& measured,
    const std::vector<Vector>& predicted, const Vector& gravity, Real supportRadius, Real spacing,
    const PeriodicBox& periodic, Real dt) {
  const WendlandC2Kernel<Dim> kernel(supportRadius);
  const auto& x = fluid.positions();
  const auto& mass = fluid.scalarField(field::mass);
  const auto& restDensity = fluid.scalarField(field::restDensity);
  auto& rho = fluid.scalarField(field::rho);
  auto& p = fluid.scalarField(field::p);
  const Real* frozen =
      fluid.hasScalarField(field::frozen) ? fluid.scalarField(field::frozen).data() : nullptr;
  auto held = [frozen](std::size_t i) { return frozen && frozen[i] != 0; };
  const NeighbourList& fluidPairs = neighbourhood.pairs(fluid, fluid);
  const std::size_t n = x.size();
  const std::size_t owned = fluid.ownedSize();
  const Real dt2 = dt * dt;
  const Real selfWeight = kernel.value(0);
  // the kernel sum of a particle inside the lattice at dx: 1.0051 (2D) and 1.0031 (3D) at
  // h = 3 dx, not 1; the summed density is read against it, so that the lattice particles are
  // at rest start at rest (Wendland's sum over a finite lattice, exact to round-off)
  const Real latticeSum = latticeKernelSum<Dim>(supportRadius, spacing);
  const Real toDensity = 1 / latticeSum;
  diagonal_.assign(n, 0);
  source_.assign(n, 0);
  pressureAcceleration_.assign(n, Vector::Zero());
  wallForce_.resize(walls.size());
  wallTorque_.resize(walls.size());
  IncompressibleReport report;

  withSeparation(periodic, [&](auto separation) {
  // The summed density, then the advected density's source and the diagonal (they need the
  // neighbours' densities: the halo's from their owners).
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < owned; ++i) {
      Real sum = mass[i] * selfWeight;  // of the fluid and the walls: rho_i times latticeSum
      for (const std::uint32_t j : fluidPairs.of(i)) {
        sum += mass[j] * kernel.value(separation(x[i], x[j]).norm());
      }
      for (const PressureWall& wall : walls) {
        const auto& wallX = *wall.position;
        const auto& volume = *wall.volume;
        for (const std::uint32_t b : wall.pairs->of(i)) {
          sum += restDensity[i] * volume[b] * kernel.value(separation(x[i], wallX[b]).norm());
        }
      }
      rho[i] = std::max(sum * toDensity, restDensity[i]);
      if (!held(i)) p[i] *= Real(0.5);  // the warm start
    }
    neighbourhood.syncHalo(fluid, rho);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < owned; ++i) {
      if (held(i)) {
        p[i] = 0;
        continue;
      }
      const Real rho2 = rho[i] * rho[i];
      Vector fluidGradient = Vector::Zero();  // sum m_j grad W_ij
      Vector wallGradient = Vector::Zero();   // sum psi_b grad W_ib
      Real divergence = 0;                    // of the predicted velocity, times -rho
      Real crossTerms = 0;                    // sum over moving j of m_j |grad W_ij|^2
      for (const std::uint32_t j : fluidPairs.of(i)) {
        const Vector xij = separation(x[i], x[j]);
        const Vector gradient = kernel.derivativeOverDistance(xij.norm()) * xij;
        const Real mj = mass[j] * toDensity;
        fluidGradient += mj * gradient;
        divergence += mj * (predicted[i] - predicted[j]).dot(gradient);
        if (!held(j)) crossTerms += mj * gradient.squaredNorm();
      }
      for (const PressureWall& wall : walls) {
        const auto& wallX = *wall.position;
        const auto& volume = *wall.volume;
        for (const std::uint32_t b : wall.pairs->of(i)) {
          const Vector xib = separation(x[i], wallX[b]);
          const Vector gradient = kernel.derivativeOverDistance(xib.norm()) * xib;
          const Real psi = restDensity[i] * volume[b] * toDensity;
          wallGradient += psi * gradient;
          if (wall.respond) continue;  // its velocity is the iteration's (coupledDivergence)
          const Vector relative =
              wall.velocity ? Vector(predicted[i] - (*wall.velocity)[b]) : predicted[i];
          divergence += psi * relative.dot(gradient);
        }
      }
      source_[i] = restDensity[i] - (rho[i] + dt * divergence);
      diagonal_[i] =
          -dt2 / rho2 *
          ((fluidGradient + wallGradient).squaredNorm() + mass[i] * toDensity * crossTerms);
    }
    neighbourhood.syncHalo(fluid, p);

    // p_b of a pressure q: the fluid's within h of each wall particle, weighted by W, with the
    // hydrostatic term of g - a_wall, at least 0 (a halo wall particle's from its owner).
    // (Unclipped, the squeeze film's Jacobi iteration diverged.)
    wallPressure_.resize(walls.size());
    auto extrapolateWallPressure = [&](const std::vector<Real>& q) {
      for (std::size_t w = 0; w < walls.size(); ++w) {
        const auto& wallX = *walls[w].position;
        const NeighbourList& around = *walls[w].around;
        const Vector* wallAcceleration =
            walls[w].acceleration ? walls[w].acceleration->data() : nullptr;
        wallPressure_[w].resize(wallX.size());
        Real* wallPressure = wallPressure_[w].data();
#pragma omp parallel for schedule(static)
        for (std::size_t b = 0; b < wallX.size(); ++b) {
          Real weight = 0, pressure = 0;
          Vector densityMoment = Vector::Zero();
          for (const std::uint32_t f : around.of(b)) {
            const Vector xbf = separation(wallX[b], x[f]);
            const Real wbf = kernel.value(xbf.norm());
            weight += wbf;
            pressure += q[f] * wbf;
            densityMoment += (rho[f] * wbf) * xbf;
          }
          const Vector felt = wallAcceleration ? Vector(gravity - wallAcceleration[b]) : gravity;
          wallPressure[b] = weight > 0
                                ? std::max((pressure + felt.dot(densityMoment)) / weight, Real(0))
                                : Real(0);
        }
        neighbourhood.syncHalo(*walls[w].cloud, wallPressure_[w]);
      }
    };

    // the per-particle loads of the walls measured (every pass for a responding wall's)
    for (std::size_t w = 0; w < walls.size(); ++w) {
      if (!measured[w]) continue;
      wallForce_[w].assign(n, Vector::Zero());
      wallTorque_[w].assign(n, Vector::Zero());
    }
    // a^p of a pressure q (the owned; the halo's from their owners)
    auto pressureAccelerations = [&](const std::vector<Real>& q, bool withLoads) {
      extrapolateWallPressure(q);
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < owned; ++i) {
        if (held(i)) {  // no pressure force, none on the walls
          pressureAcceleration_[i].setZero();
          continue;
        }
        const Real pi = q[i] / (rho[i] * rho[i]);
        Vector a = Vector::Zero();
        for (const std::uint32_t j : fluidPairs.of(i)) {
          const Vector xij = separation(x[i], x[j]);
          a -= (mass[j] * toDensity * (pi + q[j] / (rho[j] * rho[j])) *
                kernel.derivativeOverDistance(xij.norm())) *
               xij;
        }
        for (std::size_t w = 0; w < walls.size(); ++w) {
          const auto& wallX = *walls[w].position;
          const auto& volume = *walls[w].volume;
          const Real* wallPressure = wallPressure_[w].data();
          const bool load = measured[w] && (withLoads || walls[w].respond);
          Vector force = Vector::Zero(), torque = Vector::Zero();
          for (const std::uint32_t b : walls[w].pairs->of(i)) {
            const Vector xib = separation(x[i], wallX[b]);
            const Real pb = wallPressure[b] / (rho[i] * rho[i]);  // the mirror's density rho_i
            const Vector term = (restDensity[i] * volume[b] * toDensity * (pi + pb) *
                                 kernel.derivativeOverDistance(xib.norm())) *
                                xib;
            a -= term;
            if (load) {  // what the fluid particle puts on the wall particle
              force += mass[i] * term;
              torque += wallX[b].cross(Vector(mass[i] * term));
            }
          }
          if (load) {
            wallForce_[w][i] = force;
            wallTorque_[w][i] = torque;
          }
        }
        pressureAcceleration_[i] = a;
      }
      neighbourhood.syncHalo(fluid, pressureAcceleration_);
    };

    // The responding walls' velocities at the step's end under the last pass's loads (each
    // body's summed in particle order, then over the ranks: every rank predicts alike).
    wallVelocity_.resize(walls.size());
    std::vector<double> bodyLoads;
    auto respond = [&]() {
      for (std::size_t w = 0; w < walls.size(); ++w) {
        if (!walls[w].respond) continue;
        Vector force = Vector::Zero(), torque = Vector::Zero();
        for (std::size_t i = 0; i < owned; ++i) {
          force += wallForce_[w][i];
          torque += wallTorque_[w][i];
        }
        bodyLoads.assign({force[0], force[1], force[2], torque[0], torque[1], torque[2]});
        neighbourhood.sumOverRanks(bodyLoads);
        walls[w].respond(Vector(Real(bodyLoads[0]), Real(bodyLoads[1]), Real(bodyLoads[2])),
                         Vector(Real(bodyLoads[3]), Real(bodyLoads[4]), Real(bodyLoads[5])),
                         wallVelocity_[w]);
      }
    };
    // -dt sum_b psi_b (v*_i - u_b) . grad W_ib over the responding walls: the part of rho0 -
    // rho*_i that the walls' predicted velocities make
    auto coupledSource = [&](std::size_t i) {
      Real divergence = 0;
      for (std::size_t w = 0; w < walls.size(); ++w) {
        if (!walls[w].respond) continue;
        const auto& wallX = *walls[w].position;
        const auto& volume = *walls[w].volume;
        const Vector* u = wallVelocity_[w].data();
        for (const std::uint32_t b : walls[w].pairs->of(i)) {
          const Vector xib = separation(x[i], wallX[b]);
          divergence += restDensity[i] * volume[b] * toDensity *
                        (predicted[i] - u[b]).dot(kernel.derivativeOverDistance(xib.norm()) * xib);
        }
      }
      return -dt * divergence;
    };
    const bool coupled = std::any_of(walls.begin(), walls.end(),
                                     [](const PressureWall& wall) { return bool(wall.respond); });

    // The residual of eq. (1) at a pressure q, r_i = rho0_i - rho*_i - (A q)_i = rho0_i minus
    // the density q leaves (with the walls' p_b of q and the bodies' answer to q's loads); 0 for
    // a held particle.
    auto residualOf = [&](const std::vector<Real>& q, std::vector<Real>& r) {
      pressureAccelerations(q, false);
      if (coupled) respond();
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < owned; ++i) {
        if (held(i)) {
          r[i] = 0;
          continue;
        }
        Real product = 0;  // (A q)_i
        for (const std::uint32_t j : fluidPairs.of(i)) {
          const Vector xij = separation(x[i], x[j]);
          product += mass[j] * toDensity *
                     (pressureAcceleration_[i] - pressureAcceleration_[j])
                         .dot(kernel.derivativeOverDistance(xij.norm()) * xij);
        }
        for (const PressureWall& wall : walls) {
          const auto& wallX = *wall.position;
          const auto& volume = *wall.volume;
          for (const std::uint32_t b : wall.pairs->of(i)) {
            const Vector xib = separation(x[i], wallX[b]);
            product +=
                restDensity[i] * volume[b] * toDensity *
                pressureAcceleration_[i].dot(kernel.derivativeOverDistance(xib.norm()) * xib);
          }
        }
        r[i] = (coupled ? source_[i] + coupledSource(i) : source_[i]) - dt2 * product;
      }
    };
    // The stopping measure of a residual: the mean and largest compression it leaves over the
    // moving particles, max(-r_i, 0) / rho0_i (summed in particle order, then over the ranks).
    std::vector<double> sums(2);
    auto measure = [&](const std::vector<Real>& r) {
      double total = 0, largest = 0, moving = 0;
      for (std::size_t i = 0; i < owned; ++i) {
        if (held(i)) continue;
        const double compression = std::max<double>(-r[i], 0) / restDensity[i];
        total += compression;
        largest = std::max(largest, compression);
        moving += 1;
      }
      sums[0] = total;
      sums[1] = moving;
      neighbourhood.sumOverRanks(sums);
      report.meanCompression = sums[1] > 0 ? sums[0] / sums[1] : 0;
      report.largestCompression = neighbourhood.maxOverRanks(largest);
      return report.meanCompression <= settings_.densityTolerance &&
             report.largestCompression <= settings_.largestCompression;
    };

    std::vector<Real> r(n, 0);
    // Ihmsen et al.'s relaxed Jacobi, p >= 0 at every iteration. Where neighbours are compressed
    // together (a stream landing) the simultaneous updates overshoot, and the clip at 0 turns
    // that into a cycle of period two that never converges (crossDitchPress's pour: a particle's
    // p 0, 1336, 0, 1336, ... at a mean compression fixed at 0.157 %): a mean compression that
    // has not fallen by 1 % in 10 iterations halves omega for the rest of the solve.
    Real omega = settings_.relaxation;
    double checkpoint = std::numeric_limits<double>::infinity();
    for (report.iterations = 0; report.iterations < settings_.maxIterations;) {
      residualOf(p, r);
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < owned; ++i) {
        if (held(i)) continue;
        p[i] = diagonal_[i] < 0 ? std::max(p[i] + omega * r[i] / diagonal_[i], Real(0)) : 0;
      }
      neighbourhood.syncHalo(fluid, p);
      ++report.iterations;
      // (the measure is of the pressure before this iteration's update)
      if (measure(r) && report.iterations >= settings_.minIterations) break;
      if (report.iterations % 10 == 0) {
        if (report.meanCompression > 0.99 * checkpoint && omega > settings_.relaxation / 16) {
          omega *= Real(0.5);
        }
        checkpoint = report.meanCompression;
      }
    }
    report.converged = report.meanCompression <= settings_.densityTolerance &&
                       report.largestCompression <= settings_.largestCompression;
    pressureAccelerations(p, true);  // of the p the step takes, with the walls' loads
  });
  return report;
}

template IncompressibleReport IncompressiblePressure::solve<2>(ParticleCloud&, const Neighbourhood&,
                                                               const std::vector<PressureWall>&,
                                                               const std::vector<bool>&,
                                                               const std::vector<Vector>&,
                                                               const Vector&, Real, Real,
                                                               const PeriodicBox&, Real);
template IncompressibleReport IncompressiblePressure::solve<3>(ParticleCloud&, const Neighbourhood&,
                                                               const std::vector<PressureWall>&,
                                                               const std::vector<bool>&,
                                                               const std::vector<Vector>&,
                                                               const Vector&, Real, Real,
                                                               const PeriodicBox&, Real);

}  // namespace sphcast
