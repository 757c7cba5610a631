#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/Real.h"
#include "parallel/Communicator.h"
#include "particles/CellGrid.h"  // PeriodicBox

namespace sphcast {

// An axis-aligned box of space; a side may be infinite (the outer subdomains reach to infinity,
// so that every point has an owner).
struct Region {
  std::array<double, 3> lower, upper;
  // The distance from x to the box (0 inside), on a periodic axis to the nearest image of x.
  double distance(const Vector& x, const PeriodicBox& periodic) const;
  // The distance between two boxes, likewise.
  double distance(const Region& other, const PeriodicBox& periodic) const;
};

// The decomposition of space into subdomains by recursive coordinate bisection (Berger and
// Bokhari 1987): the particles' box is cut across its longest axis where the weights below the
// cut are the lower half's share, and each side again, until there is one subdomain per part.
// Any number of parts: a node of n parts gives floor(n/2) to its lower side, with that share of
// the weight. Cheap to build (a few dozen reductions per level), cheap to query (a tree of
// log2(parts) levels), and subdomains are boxes, so that a halo is the particles within a
// distance of a neighbour's box.
//
// Hierarchical cuts (OpenFOAM's hierarchical decomposition) are the same tree with its axes
// prescribed: n[0] slabs along order[0], each cut into n[1] along order[1], then n[2] along
// order[2], every cut at its own particles' weight quantile (a node of k slabs along an axis
// gives floor(k/2) of them to its lower side).
//
// The weights are integers, so that every sum over the ranks is exact: the cuts then depend only
// on the whole set of particles and weights, never on how the ranks held them, and a restart
// onto any number of ranks decomposes the same state the same way.
class RecursiveBisection {
 public:
  struct AxisCuts {
    std::array<int, 3> counts{1, 1, 1};  // subdomains along x, y, z; their product is the parts
    std::array<int, 3> order{0, 1, 2};   // the axes in the order cut
  };

  // One subdomain: everything.
  RecursiveBisection();

  // Collective over comm: points and weights (each >= 0) are this rank's share of the set.
  // dimension 2 never cuts z. With `cuts`, the axes are its (hierarchical cuts). Throws Error
  // for parts < 1, a negative weight, or cuts whose counts do not multiply to parts.
  static RecursiveBisection build(const Communicator& comm, const std::vector<Vector>& points,
                                  const std::vector<std::int64_t>& weights, int parts,
                                  int dimension, const AxisCuts* cuts = nullptr);

  int parts() const { return static_cast<int>(leaves_.size()); }
  // The subdomain of x: below a cut is x[axis] < cut, exactly as build() counted.
  int owner(const Vector& x) const;
  const Region& region(int part) const { return nodes_[leaves_[part]].region; }
  // The weight each subdomain received at the build.
  const std::vector<std::int64_t>& partWeights() const { return partWeights_; }
  // The largest part's weight over the mean (1: perfect balance).
  double imbalance() const;

  // Appends to `near` the parts other than `self` whose box comes closer to x than radius
  // (the ranks a particle at x is a halo particle of), in increasing order.
  void partsNear(const Vector& x, double radius, const PeriodicBox& periodic, int self,
                 std::vector<int>& near) const;
  // The parts other than `part` whose box comes closer than radius to its box: the ranks it
  // exchanges halos with (a symmetric relation).
  std::vector<int> neighbours(int part, double radius, const PeriodicBox& periodic) const;

  // "x < 0.25 (parts 0-1 | 2-3); ..." for the log.
  std::string describe() const;

 private:
  struct Node {
    Region region;
    int firstPart = 0, partCount = 1;
    std::array<int, 3> counts{1, 1, 1};  // hierarchical cuts: the subdomains left per axis
    int axis = -1;  // -1: a leaf
    double cut = 0;
    int lower = -1, upper = -1;  // children
  };
  void collectNear(int node, const Vector& x, double radius, const PeriodicBox& periodic, int self,
                   std::vector<int>& near) const;

  std::vector<Node> nodes_;
  std::vector<int> leaves_;  // node of each part
  std::vector<std::int64_t> partWeights_;
};

}  // namespace sphcast
