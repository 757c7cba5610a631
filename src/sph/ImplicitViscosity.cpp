#include "sph/ImplicitViscosity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Geometry>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "particles/WendlandKernel.h"

namespace sphcast {
namespace {

// Sums are taken per block of this many particles, each block in particle order, then over the
// blocks in order: the same bits on any number of threads.
constexpr std::size_t blockSize = 1024;

}  // namespace

std::string describeViscositySolver(ViscositySolver solver,
                                    const ImplicitViscositySettings& settings) {
  std::ostringstream text;
  switch (solver) {
    case ViscositySolver::explicitForm:
      return "explicit";
    case ViscositySolver::implicitForm:
      text << "implicit";
      break;
    case ViscositySolver::automatic:
      text << "auto (implicit in the steps longer than the explicit viscous limit)";
      break;
  }
  text << ", tolerance " << settings.tolerance << ", relTol " << settings.relativeTolerance
       << ", maxIter " << settings.maxIterations;
  return text.str();
}

template <int Dim>
ImplicitViscosityReport ImplicitViscosity::solve(ParticleCloud& fluid,
                                                 const Neighbourhood& neighbourhood,
                                                 const std::vector<ViscousWall>& walls,
                                                 Real supportRadius, Real spacing, Real dt) {
  const WendlandC2Kernel<Dim> kernel(supportRadius);
  const PeriodicBox periodic = neighbourhood.periodicBox();
  const NeighbourList& fluidPairs = neighbourhood.pairs(fluid, fluid);
  const Real etaSquared = Real(0.01) * spacing * spacing;
  const Real halfSpacing = Real(0.5) * spacing;
  const auto& x = fluid.positions();
  auto& v = fluid.vectorField(field::U);
  const auto& rho = fluid.scalarField(field::rho);
  const auto& mass = fluid.scalarField(field::mass);
  const auto& mu = fluid.scalarField(field::viscosity);
  const Real* frozen =
      fluid.hasScalarField(field::frozen) ? fluid.scalarField(field::frozen).data() : nullptr;
  // a decomposed run's rank solves for its own particles; the halo's values are their owners'
  const std::size_t count = x.size();
  const std::size_t owned = fluid.ownedSize();
  const std::uint64_t* begins = fluidPairs.offsets().data();
  const std::uint64_t* ends = fluidPairs.ends().data();
  const std::uint32_t* neighbours = fluidPairs.neighbours().data();
  pairWeight_.resize(fluidPairs.neighbours().size());
  diagonal_.resize(count);
  rightSide_.resize(count);
  rowSum_.resize(count);
  auto isFrozen = [frozen](std::size_t i) { return frozen && frozen[i] != 0; };
  // b_ik of a no-slip wall pair (without dt)
  auto wallWeight = [&](std::size_t i, const ViscousWall& wall, std::uint32_t k) {
    const Vector xik = periodic.separation(x[i], (*wall.position)[k]);
    const Real r2 = xik.squaredNorm();
    const Real depth = (*wall.depth)[k];
    const Real fluidDistance = std::max(xik.dot((*wall.normal)[k]) - depth, halfSpacing);
    const Real beta = Real(1) + depth / fluidDistance;
    return Real(-2) * mass[i] * (*wall.volume)[k] * mu[i] / rho[i] *
           kernel.derivativeOverDistance(std::sqrt(r2)) * r2 / (r2 + etaSquared) * beta;
  };

  // The start: the velocity after the kick, frozen particles at rest, the halo its owners'.
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < owned; ++i) {
    if (isFrozen(i)) v[i].setZero();
  }
  neighbourhood.syncHalo(fluid, v);

  // The weights dt a_ij, the diagonal and the right side (the walls' velocities in it).
  // a_ij is computed alike from either side (the products commute): a_ij == a_ji in bits.
  // (dynamic here and in the blocks: frozen rows, which cost nothing, lie in runs of the cell
  // order; a row's and a block's sums are their own, so the bits are the same either way)
#pragma omp parallel for schedule(dynamic, 64)
  for (std::size_t i = 0; i < owned; ++i) {
    if (isFrozen(i)) {
      diagonal_[i] = 1;
      rowSum_[i] = 0;
      rightSide_[i].setZero();
      continue;
    }
    Real diagonal = mass[i];
    Real rowSum = mass[i];  // A's row sum: m_i + dt sum_k b_ik (the pair weights cancel)
    Vector right = mass[i] * v[i];
    for (std::uint64_t n = begins[i]; n < ends[i]; ++n) {
      const std::uint32_t j = neighbours[n];
      const Vector xij = periodic.separation(x[i], x[j]);
      const Real r2 = xij.squaredNorm();
      // (two inviscid particles: no coupling, not 0 / 0)
      const Real harmonic =
          Real(2) * (mu[i] * mu[j]) / std::max(mu[i] + mu[j], std::numeric_limits<Real>::min());
      const Real weight = dt * Real(-2) * (mass[i] * mass[j]) * harmonic / (rho[i] * rho[j]) *
                          kernel.derivativeOverDistance(std::sqrt(r2)) * r2 / (r2 + etaSquared);
      pairWeight_[n] = weight;
      diagonal += weight;  // a frozen j: a wall at rest (its v_j' = 0 adds nothing on the right)
    }
    for (const ViscousWall& wall : walls) {
      if (wall.condition.slip()) continue;
      for (const std::uint32_t k : wall.pairs->of(i)) {
        const Real weight = dt * wallWeight(i, wall, k);
        diagonal += weight;
        rowSum += weight;
        if (wall.velocity) right += weight * (*wall.velocity)[k];
      }
    }
    diagonal_[i] = diagonal;
    rowSum_[i] = rowSum;
    rightSide_[i] = right;
  }

  // The conjugate gradient in passes over blocks of owned particles: each block's sums are
  // taken in particle order, then summed over the blocks in order and over the ranks.
  const std::size_t blocks = (owned + blockSize - 1) / blockSize;
  blockSums_.assign(2 * blocks, Vector::Zero());
  auto sumBlocks = [&] {  // (the first sums, the second sums) of every block, over the ranks
    std::vector<double> total(6, 0.0);
    for (std::size_t b = 0; b < blocks; ++b) {
      for (int c = 0; c < 3; ++c) {
        total[std::size_t(c)] += double(blockSums_[2 * b][c]);
        total[std::size_t(3 + c)] += double(blockSums_[2 * b + 1][c]);
      }
    }
    neighbourhood.sumOverRanks(total);
    return std::make_pair(Vector(Real(total[0]), Real(total[1]), Real(total[2])),
                          Vector(Real(total[3]), Real(total[4]), Real(total[5])));
  };
  // first(i) and second(i) summed over the owned particles
  auto sumOwned = [&](auto first, auto second) {
#pragma omp parallel for schedule(static)
    for (std::size_t b = 0; b < blocks; ++b) {
      Vector a = Vector::Zero(), c = Vector::Zero();
      for (std::size_t i = b * blockSize; i < std::min(owned, (b + 1) * blockSize); ++i) {
        a += first(i);
        c += second(i);
      }
      blockSums_[2 * b] = a;
      blockSums_[2 * b + 1] = c;
    }
    return sumBlocks();
  };
  residual_.resize(count);
  direction_.resize(count);
  product_.resize(count);
  preconditioned_.resize(count);
  // q = A p for the unknowns (frozen rows hold p = 0 throughout), and the sum of p . q
  auto multiply = [&](const std::vector<Vector>& p) {
#pragma omp parallel for schedule(dynamic, 1)
    for (std::size_t b = 0; b < blocks; ++b) {
      Vector pq = Vector::Zero();
      for (std::size_t i = b * blockSize; i < std::min(owned, (b + 1) * blockSize); ++i) {
        if (isFrozen(i)) {
          product_[i].setZero();
          continue;
        }
        Vector sum = diagonal_[i] * p[i];
        for (std::uint64_t n = begins[i]; n < ends[i]; ++n) {
          sum -= pairWeight_[n] * p[neighbours[n]];
        }
        product_[i] = sum;
        pq += p[i].cwiseProduct(sum);
      }
      blockSums_[2 * b] = pq;
      blockSums_[2 * b + 1].setZero();
    }
    return sumBlocks().first;
  };

  multiply(v);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < owned; ++i) {
    residual_[i] = rightSide_[i] - product_[i];
    preconditioned_[i] = residual_[i] / diagonal_[i];
    direction_[i] = preconditioned_[i];
  }
  neighbourhood.syncHalo(fluid, direction_);
  auto [rz, startSquared] =
      sumOwned([&](std::size_t i) { return Vector(residual_[i].cwiseProduct(preconditioned_[i])); },
               [&](std::size_t i) { return Vector(residual_[i].cwiseAbs2()); });
  const Vector startNorm = startSquared.cwiseSqrt();
  const Vector rightNorm =
      sumOwned([&](std::size_t i) { return Vector(rightSide_[i].cwiseAbs2()); },
               [](std::size_t) { return Vector(Vector::Zero()); })
          .first.cwiseSqrt();
  // A component has converged when ||r|| <= tolerance ||b|| or ||r|| <= relTol ||r_0|| (as
  // OpenFOAM's solvers' tolerance and relTol); one whose b is zero when r is too.
  auto converged = [&](const Vector& norm, int c) {
    return norm[c] <= settings_.tolerance * rightNorm[c] ||
           norm[c] <= settings_.relativeTolerance * startNorm[c];
  };
  auto relative = [&](const Vector& norm) {
    Vector ratio;
    for (int c = 0; c < 3; ++c) {
      ratio[c] = rightNorm[c] > 0 ? norm[c] / rightNorm[c] : (norm[c] > 0 ? 1 : 0);
    }
    return ratio;
  };
  ImplicitViscosityReport report;
  Vector norm = startNorm;
  std::array<bool, 3> done{converged(norm, 0), converged(norm, 1), converged(norm, 2)};
  while (!(done[0] && done[1] && done[2])) {
    if (report.iterations == settings_.maxIterations) {
      std::ostringstream problem;
      problem << "the implicit viscosity solve did not converge in " << settings_.maxIterations
              << " iterations (residual " << relative(norm).maxCoeff()
              << " of the right side, tolerance " << settings_.tolerance << ", relTol "
              << settings_.relativeTolerance << "; viscositySolverCoeffs in system/sphSchemes)";
      throw Error(problem.str());
    }
    ++report.iterations;
    const Vector pq = multiply(direction_);
    Vector alpha;
    for (int c = 0; c < 3; ++c) alpha[c] = !done[c] && pq[c] > 0 ? rz[c] / pq[c] : Real(0);
    const auto [rzNext, squared] = sumOwned(
        [&](std::size_t i) {
          v[i] += alpha.cwiseProduct(direction_[i]);
          residual_[i] -= alpha.cwiseProduct(product_[i]);
          preconditioned_[i] = residual_[i] / diagonal_[i];
          return Vector(residual_[i].cwiseProduct(preconditioned_[i]));
        },
        [&](std::size_t i) { return Vector(residual_[i].cwiseAbs2()); });
    norm = squared.cwiseSqrt();
    Vector beta;
    for (int c = 0; c < 3; ++c) {
      beta[c] = alpha[c] != 0 && rz[c] > 0 ? rzNext[c] / rz[c] : Real(0);
      done[c] = done[c] || converged(norm, c);
    }
    rz = rzNext;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < owned; ++i) {
      direction_[i] = preconditioned_[i] + beta.cwiseProduct(direction_[i]);
    }
    neighbourhood.syncHalo(fluid, direction_);
  }
  report.residual = relative(norm).maxCoeff();

  // The momentum the residual leaves, sum_i r_i (the pair terms cancel in any iterate: sum_i
  // (A x)_i = sum_i (m_i + dt sum_k b_ik) x_i), taken out by the uniform velocity that zeroes
  // it: momentum is then kept to round-off (less the walls' shear) whatever the tolerance.
  const auto [momentumLeft, rowSums] =
      sumOwned([&](std::size_t i) { return isFrozen(i) ? Vector(Vector::Zero()) : residual_[i]; },
               [&](std::size_t i) { return Vector(rowSum_[i], 0, 0); });
  if (rowSums[0] > 0) {
    const Vector shift = momentumLeft / rowSums[0];
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < owned; ++i) {
      if (!isFrozen(i)) v[i] += shift;
    }
  }
  neighbourhood.syncHalo(fluid, v);

  // What each no-slip wall took from this rank's fluid: minus the shear its mirror particles put
  // on it (a decomposed run's bodies sum the ranks' loads).
  wallForces_.assign(walls.size(), Vector::Zero());
  wallTorques_.assign(walls.size(), Vector::Zero());
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const ViscousWall& wall = walls[w];
    if (wall.condition.slip()) continue;
    Vector force = Vector::Zero(), torque = Vector::Zero();
    for (std::size_t i = 0; i < owned; ++i) {
      if (isFrozen(i)) continue;
      for (const std::uint32_t k : wall.pairs->of(i)) {
        const Vector wallVelocity = wall.velocity ? (*wall.velocity)[k] : Vector::Zero();
        const Vector onWall = wallWeight(i, wall, k) * (v[i] - wallVelocity);
        force += onWall;
        torque += (*wall.position)[k].cross(onWall);
      }
    }
    wallForces_[w] = force;
    wallTorques_[w] = torque;
  }
  return report;
}

template ImplicitViscosityReport ImplicitViscosity::solve<2>(ParticleCloud&, const Neighbourhood&,
                                                             const std::vector<ViscousWall>&, Real,
                                                             Real, Real);
template ImplicitViscosityReport ImplicitViscosity::solve<3>(ParticleCloud&, const Neighbourhood&,
                                                             const std::vector<ViscousWall>&, Real,
                                                             Real, Real);

}  // namespace sphcast
