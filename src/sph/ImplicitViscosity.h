#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "boundaries/WallCondition.h"
#include "core/Real.h"
#include "particles/NeighbourList.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// How the flow steps the viscous term of eq. (2) (viscositySolver in system/sphSchemes):
//   explicit  in the rates, as every other term: stable below 0.125 dx^2 / nu (Morris et al.
//             1997), which for a mush (Table 1: 186 to 4.9e4 Pa s) is hundreds to 1e5 times
//             shorter than the acoustic step;
//   implicit  every flow step solves it backward in time after the second kick
//             (ImplicitViscosity), with no step limit;
//   auto      (the default) implicit in the steps whose explicit viscous limit would be shorter
//             than the step the other limits allow, explicit otherwise (a liquid metal's
//             limit is thousands of times longer than the acoustic step: nothing to solve).
enum class ViscositySolver { explicitForm, implicitForm, automatic };

// The log's words for the choice: "auto (implicit in the steps ...; tolerance 1e-06, maxIter
// 1000)".
struct ImplicitViscositySettings;
std::string describeViscositySolver(ViscositySolver solver,
                                    const ImplicitViscositySettings& settings);

// Settings of the implicit solve (viscositySolverCoeffs in system/sphSchemes).
struct ImplicitViscositySettings {
  // The conjugate gradient stops for a velocity component when its residual's norm is below
  // tolerance times the right side's (m v, the momentum) or relTol times the residual's at the
  // start (the explicit viscous impulse of the step), as OpenFOAM's tolerance and relTol.
  Real tolerance = Real(1e-6);
  Real relativeTolerance = Real(1e-4);
  int maxIterations = 1000;
};

// What one solve did, for the log and the tests.
struct ImplicitViscosityReport {
  int iterations = 0;
  double residual = 0;  // the largest component's ||r|| / ||b|| at the end
  bool converged = true;
};

// A wall as the viscous solve sees it: a no-slip wall holds the fluid at its velocity through
// its mirror particles, a slip wall holds nothing.
struct ViscousWall {
  const std::vector<Vector>* position;
  const std::vector<Vector>* velocity;  // null: at rest
  const std::vector<Real>* volume;
  const std::vector<Vector>* normal;
  const std::vector<Real>* depth;
  const NeighbourList* pairs;  // fluid particle -> wall particles within h
  WallCondition condition;
};

// The viscous term of eq. (2) in the Morris form (FlowRates.h, MorrisViscosity) stepped
// backward in time over dt (Peer, Ihmsen, Cornelis & Teschner 2015; Weiler, Koschier, Brand &
// Bender 2018, Comput. Graph. Forum 37:145, who solve it likewise with a conjugate gradient):
// for every fluid particle i that is not frozen,
//   m_i v_i' + dt sum_j a_ij (v_i' - v_j') + dt sum_k b_ik (v_i' - v_k) = m_i v_i,
//   a_ij = -2 m_i m_j mu_ij / (rho_i rho_j) (x_ij . grad W_ij) / (|x_ij|^2 + eta^2) >= 0,
//   b_ik = -2 m_i V_k mu_i / rho_i (x_ik . grad W_ik) / (|x_ik|^2 + eta^2) beta_ik,
// with the harmonic mu_ij of the explicit form, eta^2 = 0.01 dx^2, and a no-slip wall's
// mirror particles k with the explicit form's extension beta_ik = 1 + d_k / max(d_i, dx/2)
// (a slip wall adds nothing). a_ij = a_ji: the matrix is symmetric positive definite, and the
// pair terms cancel in sum_i m_i v_i' (momentum changes only by the walls' shear). A frozen
// particle keeps v = 0 and enters its neighbours' rows as a no-slip wall at rest. The kernel
// gradient is the plain one (a corrected gradient would make a_ij != a_ji).
//
// Solved matrix-free, with the pair weights computed once per solve in the pair lists' order,
// by a Jacobi-preconditioned conjugate gradient on the three components at once (one pass over
// the pairs per iteration for all three). Hand-written rather than Eigen's ConjugateGradient:
// the matrix is the neighbour lists' CSR with the weights beside it, the three right sides share
// it, every sum is taken in fixed blocks so that the result is the same bits on any number of
// threads (a run restarted on other threads continues bit for bit), and a decomposed run needs
// a halo refresh and a sum over the ranks per iteration, which Eigen's solvers do not make.
//
// Decomposed: each rank solves for its owned particles, the halo's copies of the search
// direction refreshed from their owners at every iteration and the sums taken over the ranks
// (Neighbourhood::syncHalo, sumOverRanks); the result is the serial one to the tolerance.
class ImplicitViscosity {
 public:
  explicit ImplicitViscosity(ImplicitViscositySettings settings = {}) : settings_(settings) {}

  // Steps the fluid's U (frozen particles left at rest) by the viscous term over dt, with the
  // fluid's pairs of `neighbourhood`. Fields read: positions, U, rho, mass, viscosity, frozen
  // (when present). `spacing` is dx.
  // Throws Error naming the residual when the solve does not converge in maxIterations.
  template <int Dim>
  ImplicitViscosityReport solve(ParticleCloud& fluid, const Neighbourhood& neighbourhood,
                                const std::vector<ViscousWall>& walls, Real supportRadius,
                                Real spacing, Real dt);

  // The viscous force each wall took from the fluid in the last solve (N), and its torque about
  // the origin, in the order of the walls given: minus what the fluid received.
  const std::vector<Vector>& wallForces() const { return wallForces_; }
  const std::vector<Vector>& wallTorques() const { return wallTorques_; }

 private:
  ImplicitViscositySettings settings_;
  std::vector<Real> pairWeight_;   // dt a_ij, in fluidPairs' layout
  std::vector<Real> diagonal_;     // m_i + dt sum a_ij + dt sum b_ik (1 for a frozen row)
  std::vector<Vector> rightSide_;  // m_i v_i + dt sum b_ik v_k
  std::vector<Real> rowSum_;       // m_i + dt sum b_ik (0 for a frozen row)
  std::vector<Vector> residual_, direction_, product_, preconditioned_;
  std::vector<Vector> blockSums_;  // two per block of particles, for sums in a fixed order
  std::vector<Vector> wallForces_, wallTorques_;
};

}  // namespace sphcast
