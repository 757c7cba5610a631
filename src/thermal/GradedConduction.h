#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "boundaries/PeriodicBox.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// Conduction within a mold particleized at graded spacing (geometry/GradedVolume.h: the field
// localSpacing, l_i), eq. (13) in Cleary & Monaghan's form through the Kirchhoff transform
// (HeatConduction.h) with each pair's own kernel:
//
//   m_i du_i/dt = sum_j G_ij (phi_j - phi_i),
//   G_ij = -2 V_i V_j (dW/dr)(r_ij, h_ij) / r_ij  r_ij^2 / (r_ij^2 + eta_ij^2),
//   h_ij = (h_i + h_j) / 2,  h_i = h l_i / dx,  eta_ij^2 = 0.01 ((l_i + l_j) / 2)^2,
//
// the same as HeatConduction's pair sum where l_i = l_j = dx. G is symmetric, so heat only
// moves: sum_i m_i du_i/dt = 0 to round-off. On each level's lattice the sum is the Laplacian's;
// where two levels meet, the first moment sum_j G_ij (x_j - x_i) no longer vanishes, so a
// linear phi (steady conduction) would not be steady. The weights are therefore corrected once:
//
//   G'_ij = G_ij (1 + (lambda_j - lambda_i) . (x_j - x_i) / l_ij),   l_ij = (l_i + l_j) / 2,
//
// symmetric still, with the vectors lambda_i solved (conjugate gradients, block-Jacobi
// preconditioned) so that sum_j G'_ij (x_j - x_i) = 0 at every particle whose own support lies in
// the material (wallDistance at least h_i; lambda = 0 at the others, whose moment is the
// surface's): a linear profile is then exact there and the books still close to round-off. (Held
// only where the widest pair's support lay inside, the correction reached 256 of a 100 mm die's
// 14,719 particles, and its casting solidified 1.7 % early with the air's losses; at h_i, 3,571.)
// The mold moves, if at all, as a rigid body, so the pairs and weights are made from the
// body-frame positions (restPosition) where the cloud has them, and a restart makes the same.
// Decomposed (-parallel), each rank makes the rows of its own particles, over its halo (which
// reaches the coarsest support: DomainDecomposition::Cloud::haloRadius), the correction by
// conjugate gradients over every rank's particles, and again whenever the cloud's particles
// changed places (a re-balance; a moving mold's migration); serial, once.
class GradedConduction {
 public:
  // periodic: the case's periodic axes (pairs across them by the minimum image).
  // correctFirstMoments false: the plain pair sum (for measuring what the correction does).
  // decomposition: a decomposed run's neighbourhood (its halo refreshes and sums over the
  // ranks), null for a serial run; the constructor is then collective.
  GradedConduction(const ParticleCloud& cloud, int dimension, Real supportRadius, Real spacing,
                   const PeriodicBox& periodic = {}, bool correctFirstMoments = true,
                   const Neighbourhood* decomposition = nullptr);

  // Adds sum_j G'_ij (phi_j - phi_i) / m_i to energyRate (indexed like the cloud; the owned
  // particles' rows).
  void addEnergyRates(const Real* phi, const Real* mass, Real* energyRate) const;

  // "graded conduction in 'die': 41,300 particles at 4 spacings, 2.1e6 pairs; ..." for the log.
  const std::string& description() const { return description_; }
  std::size_t pairCount() const { return neighbours_.size() / 2; }
  // The largest |sum_j G'_ij (x_j - x_i)| of a particle held to zero, over sum_j G'_ij l_ij.
  double largestFirstMoment() const { return largestFirstMoment_; }
  // The least G'_ij / G_ij (positive: the corrected pairs still conduct from hot to cold).
  double leastWeightRatio() const { return leastWeightRatio_; }

 private:
  template <int Dim>
  void build(const ParticleCloud& cloud, Real supportRadius, Real spacing,
             const PeriodicBox& periodic, bool correctFirstMoments,
             const Neighbourhood* decomposition);

  std::vector<std::size_t> rowStart_;  // CSR: row i holds [rowStart_[i], rowStart_[i + 1])
  std::vector<std::uint32_t> neighbours_;
  std::vector<double> weights_;  // G'_ij
  double largestFirstMoment_ = 0;
  double leastWeightRatio_ = 1;
  std::string description_;
};

}  // namespace sphcast
