#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "boundaries/PeriodicBox.h"
#include "core/Real.h"

namespace sphcast {

// The pairs of a cloud whose particles have spacings of their own (a mold particleized at
// graded spacing, geometry/GradedVolume.h: the field localSpacing l_i), each pair within its own
// support radius h_ij = (h_i + h_j) / 2, h_i = (h / dx) l_i: symmetric, so a pair sum over them
// can move a quantity between particles without making any. The neighbourhood's lists, of one
// radius h, cannot hold them: a particle of 4 dx has no neighbour within h = 3 dx.
//
// Found once (the cloud keeps its shape: a mold at rest or moving as a rigid body) on a grid per
// spacing, each binned in cells of its own support radius; rows in the neighbours' index
// order, each neighbour once (a periodic axis's image counted once), so that sums over a row do
// not depend on the search.
struct GradedPairs {
  std::vector<std::size_t> rowStart;      // row i: [rowStart[i], rowStart[i + 1])
  std::vector<std::uint32_t> neighbours;  // j
  std::vector<Real> supportRadii;         // h_ij (or h_i, PairSupport::row)
  std::size_t entryCount() const { return neighbours.size(); }
};

// Which support a pair takes: the mean of its two particles' (symmetric: a pair sum that moves
// a quantity), or its row's own h_i (a gather, each particle summing with its own kernel).
enum class PairSupport { mean, row };

// positions: where the particles are (their body-frame places for a rigid mold); wanted: null
// for every row, else the rows to find (the others stay empty). Throws Error when a periodic
// axis is shorter than twice the coarsest support radius.
GradedPairs findGradedPairs(const std::vector<Vector>& positions,
                            const std::vector<Real>& localSpacing, Real supportRadiusOverSpacing,
                            const PeriodicBox& periodic,
                            const std::vector<std::uint8_t>* wanted = nullptr,
                            PairSupport support = PairSupport::mean);

// Each particle's reach: the largest support radius h_i = (h / dx) l_i among the particles i
// whose support holds it (|x_i - x_j| < h_i), its own included. A pair of the cloud, of either
// support, is never longer than the reach of both its particles, so a halo that sends each
// particle as far as its reach (plus the lists' skin) holds every pair a rank's rows need.
std::vector<Real> gradedSupportReach(const std::vector<Vector>& positions,
                                     const std::vector<Real>& localSpacing,
                                     Real supportRadiusOverSpacing, const PeriodicBox& periodic);

}  // namespace sphcast
