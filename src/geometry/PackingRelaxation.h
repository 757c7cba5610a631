#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <vector>

#include "core/Real.h"

namespace sphcast {

// Particles that take part in the kernel sums of a relaxation but never move: the wall
// particles of constant/particles, and the lattice continued beyond a free surface.
struct FixedNeighbours {
  std::vector<Vector> positions;
  std::vector<Real> volumes;
};

// Uniformity of a packing, over the moving particles only: the particle number density
// sigma_i = sum_j V_j W_ij (all particles, i itself and the fixed ones included; 1 for a
// perfect packing with a complete kernel) and the nearest-neighbour distance.
struct PackingStatistics {
  double densityMean = 0.0;
  double densityDeviation = 0.0;  // standard deviation of sigma / mean
  double densityMin = 0.0, densityMax = 0.0;
  double nearestMin = 0.0, nearestMean = 0.0, nearestMax = 0.0;  // m
};

struct RelaxationSettings {
  int iterations = 0;
  double spacing = 0.0;        // dx; every moving particle has volume dx^3
  double supportRadius = 0.0;  // h of the Wendland C2 kernel
  // No move brings two moving particles closer than this (0: no limit); setCastFields uses its
  // wallClearance, so that metal keeps from metal what it keeps from walls.
  double closestApproach = 0.0;
};

// Packing relaxation under a uniform background pressure (Colagrossi et al., "Particle packing
// algorithm for SPH schemes", Comput. Phys. Commun. 183 (2012) 1641; Zhu et al., "CAD-compatible
// body-fitted particle generator for arbitrarily complex geometry and its application to
// wave-structure interaction", J. Hydrodyn. 33 (2021) 195): each moving particle is pushed by
//   a_i = -sum_j V_j grad W_ij,
// the force a uniform pressure exerts on particle i. It vanishes where the neighbours are
// placed evenly around i, and points from crowded into empty space, so the iteration
//   x_i <- x_i + gamma a_i
// descends on the unevenness of sigma. K = 20 alpha dx^3 / h^2 is the restoring stiffness of
// one particle displaced in a perfect lattice (the Hessian of W summed over a full kernel
// vanishes but for the particle's own term), so gamma = 1 / K would put it back in one step;
// gamma = 0.25 / K leaves room for collective modes, stiffer by a factor of order 2, and a
// step is also capped at dx / 10. Measured on the closed cone of the tests (2,421 particles,
// h = 2.5 dx), deviation of sigma 0.0288 on the lattice, then after 10 / 25 / 50 / 100 / 200 /
// 1000 iterations: 0.0122 / 0.0075 / 0.0060 / 0.0055 / 0.0048 / 0.0031 (no oscillation).
// A move to a place where `allowed` is false (outside the fill region, closer than the
// clearance to a wall particle) is not made: the particle stays for that iteration; so is a
// move that ends closer than closestApproach to another moving particle (where the fill has a
// corner no kernel sees filled, e.g. a mold's open rim, the push would otherwise pile particles
// up there: 0.53 dx apart on the open cone). Neighbours
// from the cell grid of the particles (CellGrid, NeighbourList), rebuilt each iteration.
// Returns the statistics before [0] and after [1] the iterations.
std::array<PackingStatistics, 2> relaxPacking(
    std::vector<Vector>& positions, const FixedNeighbours& fixed,
    const std::function<std::vector<bool>(const std::vector<Vector>&)>& allowed,
    const RelaxationSettings& settings);

// The statistics of a packing as relaxPacking measures them.
PackingStatistics packingStatistics(const std::vector<Vector>& positions,
                                    const FixedNeighbours& fixed, double spacing,
                                    double supportRadius);

}  // namespace sphcast
