#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "boundaries/PeriodicBox.h"
#include "core/Real.h"
#include "particles/NeighbourList.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// pressureSolverCoeffs in system/sphSchemes (flow { model incompressible; }).
struct IncompressibleSettings {
  // The solve stops once the mean compression the pressure leaves, sum max(rho* - rho0, 0) /
  // rho0 over the moving particles divided by their count, is below this (Ihmsen et al.'s
  // eta: 0.1 % by default), after at least minIterations ...
  Real densityTolerance = Real(1e-3);
  // ... and the largest compression of one particle below this (1 %): over a pour's stream the
  // mean hides an impact (crossDitchPress: one particle 59 % compressed at a mean of 0.06 %)
  Real largestCompression = Real(1e-2);
  int minIterations = 2;
  int maxIterations = 200;      // a solve left above the tolerance goes on (the log counts it)
  Real relaxation = Real(0.5);  // omega of the relaxed Jacobi iteration (Ihmsen et al.: 0.5)
  // The step's Courant number on the flow speed: dt <= advectionCo dx / |v|max (no sound
  // speed); the body-force, viscous and force-model limits still apply.
  Real advectionCo = Real(0.4);
};

// What a solve did, for the log and the tests.
struct IncompressibleReport {
  int iterations = 0;
  double meanCompression = 0;     // the stopping measure above, at the end
  double largestCompression = 0;  // the largest max(rho* - rho0, 0) / rho0 at the end
  bool converged = true;
};

// A wall as the solve sees it: its particles' volumes V_b fill the fluid's kernel sums with the
// fluid's rest density (Akinci et al. 2012's psi_b = rho0 V_b), and move with U when present.
struct PressureWall {
  const ParticleCloud* cloud;
  const std::vector<Vector>* position;
  const std::vector<Real>* volume;
  const std::vector<Vector>* velocity;      // null: at rest
  const std::vector<Vector>* acceleration;  // null: at rest
  const NeighbourList* pairs;               // fluid particle -> wall particles within h
  const NeighbourList* around;              // wall particle -> fluid particles within h
  // A body that answers the pressure within the solve (strong coupling): given the pressure's
  // load on it (force, torque about the origin) it writes its particles' velocities at the
  // step's end, which the iteration's density source takes. Null: the wall keeps `velocity`.
  // Needs the wall measured.
  std::function<void(const Vector& force, const Vector& torque, std::vector<Vector>& velocity)>
      respond;
};

// Implicit incompressible SPH (Ihmsen, Cornelis, Solenthaler, Horvath & Teschner 2014, IEEE
// TVCG 20:426, eqs. (4)-(13)): the pressure that makes the density at the step's end the rest
// density,
//   dt^2 sum_j m_j (a^p_i - a^p_j) . grad W_ij + dt^2 sum_b psi_b a^p_i . grad W_ib
//                                                     = rho0_i - rho*_i,                  (1)
//   rho*_i = rho_i + dt sum_j m_j (v*_i - v*_j) . grad W_ij
//                  + dt sum_b psi_b (v*_i - v_b) . grad W_ib,
//   a^p_i  = -sum_j m_j (p_i / rho_i^2 + p_j / rho_j^2) grad W_ij
//            -sum_b psi_b (p_i + p_b) / rho_i^2 grad W_ib,
// with rho_i = max(sum_j m_j W_ij + sum_b psi_b W_ib, rho0_i) the density summed over the
// fluid and the walls (a particle short of neighbours, at a free surface, counts as at rest),
// v* the velocity after every other force of the step, psi_b = rho0_i V_b (Akinci et al. 2012)
// and p >= 0 (a free surface pulls nothing). A wall particle's pressure p_b is extrapolated
// from the fluid's present p with the hydrostatic term, as the weakly compressible flow's (Adami
// et al. 2012, eq. (27); Band et al. 2018, ACM TOG 37:14, do so for this solve), and lagged by
// an iteration (it enters a_ii as if it were 0). With p_b = 0 (Akinci's) a particle beside a wall
// carries twice the hydrostatic pressure to hold itself off it (measured: the tank's wall column
// at 2.0 to 2.4 times rho g (H - y)); with p_b = p_i in a_ii too (mirroring) the tank at rest
// went unstable. Every m_j and psi_b is divided by the kernel's sum on the lattice
// (latticeKernelSum, particles/WendlandKernel.h), so that particles at rest on the lattice read
// rho0, not 0.5 % more.
// Solved by the relaxed Jacobi iteration of the paper,
//   p_i <- max(0, p_i + omega (rho0_i - rho*_i - (A p)_i) / a_ii),
// each iteration two passes over the pairs (a^p, then A p), matrix-free; a_ii is eq. (1)'s
// coefficient of p_i. Started from half the last step's pressure. A frozen particle (frozen != 0)
// is held: its a^p is zero, it has no row, and it enters its neighbours' rows as a wall at rest
// of its own mass. Each particle's sums run in its pairs' order and the stopping measure is
// summed in particle order, so the result is the same bits on any number of threads.
//
// A body (PressureWall::respond) answers within the iteration: each iterate's load on it gives
// its particles' velocities at the step's end, which the density source takes (a body lighter
// than the liquid it moves, taken with the loads after the solve, swings without settling).
//
// Decomposed: each rank solves its owned particles' rows, the halo's a^p and p refreshed from
// their owners after each pass, the stopping measure summed over the ranks.
class IncompressiblePressure {
 public:
  explicit IncompressiblePressure(IncompressibleSettings settings = {}) : settings_(settings) {}

  // Writes the fluid's p (Pa, gauge) and rho (the summed density above) and returns the
  // pressure's acceleration a^p in pressureAcceleration(). `predicted` is v* (indexed like the
  // fluid), `dt` the step. Fields read: positions, mass, restDensity, p (the start), frozen.
  // The walls' per-particle reactions are in wallForce(w) (N, on wall w from fluid particle i)
  // when measured[w].
  template <int Dim>
  IncompressibleReport solve(ParticleCloud& fluid, const Neighbourhood& neighbourhood,
                             const std::vector<PressureWall>& walls,
                             const std::vector<bool>& measured,
                             const std::vector<Vector>& predicted, const Vector& gravity,
                             Real supportRadius, Real spacing, const PeriodicBox& periodic,
                             Real dt);

  const std::vector<Vector>& pressureAcceleration() const { return pressureAcceleration_; }
  // The pressure force fluid particle i put on wall w's particles, and its torque about the
  // origin (each pair's at its wall particle), after the last solve.
  const std::vector<Vector>& wallForce(std::size_t w) const { return wallForce_[w]; }
  const std::vector<Vector>& wallTorque(std::size_t w) const { return wallTorque_[w]; }
  const IncompressibleSettings& settings() const { return settings_; }

 private:
  IncompressibleSettings settings_;
  std::vector<Real> diagonal_;  // a_ii
  std::vector<Real> source_;    // rho0_i - rho*_i
  std::vector<Vector> pressureAcceleration_;
  std::vector<std::vector<Vector>> wallForce_, wallTorque_;
  std::vector<std::vector<Real>> wallPressure_;    // p_b, per wall
  std::vector<std::vector<Vector>> wallVelocity_;  // a responding wall's, per wall
};

}  // namespace sphcast
