// Recursive coordinate bisection (Berger and Bokhari 1987, IEEE Trans. Comput. C-36 570), built
// level by level over all ranks: each level finds every node's cut by bisection on the
// coordinate, counting the exact integer weight below a trial cut on every rank.
#include "parallel/RecursiveBisection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/Error.h"

namespace sphcast {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// On a periodic axis a subdomain is its part of the period: the outer ones reach to infinity
// otherwise, and an infinite interval holds an image of every point.
void clipToPeriod(double& lower, double& upper, const PeriodicBox& periodic, int axis) {
  if (!periodic.isPeriodic(axis)) return;
  lower = std::max(lower, static_cast<double>(periodic.lower(axis)));
  upper = std::min(upper, static_cast<double>(periodic.lower(axis) + periodic.period(axis)));
}

// The 1D distance from x to [lower, upper], on a periodic axis to the nearest image of x.
double axisDistance(double x, double lower, double upper, const PeriodicBox& periodic, int axis) {
  clipToPeriod(lower, upper, periodic, axis);
  auto gap = [&](double y) { return std::max({lower - y, 0.0, y - upper}); };
  double distance = gap(x);
  if (periodic.isPeriodic(axis)) {
    const double period = periodic.period(axis);
    distance = std::min({distance, gap(x - period), gap(x + period)});
  }
  return distance;
}

double intervalDistance(double lowerA, double upperA, double lowerB, double upperB,
                        const PeriodicBox& periodic, int axis) {
  clipToPeriod(lowerA, upperA, periodic, axis);
  clipToPeriod(lowerB, upperB, periodic, axis);
  auto gap = [&](double shift) {
    return std::max({lowerB + shift - upperA, 0.0, lowerA - (upperB + shift)});
  };
  double distance = gap(0);
  if (periodic.isPeriodic(axis)) {
    const double period = periodic.period(axis);
    distance = std::min({distance, gap(-period), gap(period)});
  }
  return distance;
}

}  // namespace

double Region::distance(const Vector& x, const PeriodicBox& periodic) const {
  double squared = 0;
  for (int a = 0; a < 3; ++a) {
    const double d = axisDistance(static_cast<double>(x[a]), lower[a], upper[a], periodic, a);
    squared += d * d;
  }
  return std::sqrt(squared);
}

double Region::distance(const Region& other, const PeriodicBox& periodic) const {
  double squared = 0;
  for (int a = 0; a < 3; ++a) {
    const double d =
        intervalDistance(lower[a], upper[a], other.lower[a], other.upper[a], periodic, a);
    squared += d * d;
  }
  return std::sqrt(squared);
}

RecursiveBisection::RecursiveBisection() {
  Node root;
  root.region.lower = {-infinity, -infinity, -infinity};
  root.region.upper = {infinity, infinity, infinity};
  nodes_.push_back(root);
  leaves_.push_back(0);
  partWeights_.push_back(0);
}

RecursiveBisection RecursiveBisection::build(const Communicator& comm,
                                             const std::vector<Vector>& points,
                                             const std::vector<std::int64_t>& weights, int parts,
                                             int dimension, const AxisCuts* cuts) {
  if (parts < 1) throw Error("recursive bisection: the number of subdomains must be >= 1");
  if (weights.size() != points.size()) {
    throw Error("recursive bisection: one weight per point expected");
  }
  if (std::any_of(weights.begin(), weights.end(), [](std::int64_t w) { return w < 0; })) {
    throw Error("recursive bisection: a weight is negative");
  }
  if (cuts != nullptr && cuts->counts[0] * cuts->counts[1] * cuts->counts[2] != parts) {
    throw Error("hierarchical cuts: the counts along x, y and z must multiply to the subdomains");
  }
  RecursiveBisection result;
  result.nodes_[0].partCount = parts;
  if (cuts != nullptr) result.nodes_[0].counts = cuts->counts;
  std::vector<std::vector<std::size_t>> members(1);
  members[0].resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) members[0][i] = i;
  auto coordinate = [&](std::size_t i, int axis) { return static_cast<double>(points[i][axis]); };

  std::vector<int> level{0};
  while (true) {
    std::vector<int> splitting;
    for (int n : level) {
      if (result.nodes_[n].partCount > 1) splitting.push_back(n);
    }
    if (splitting.empty()) break;
    const std::size_t k = splitting.size();
    // the nodes' boxes and weights over all ranks
    std::vector<double> low(3 * k, infinity), high(3 * k, -infinity);
    std::vector<std::int64_t> total(k, 0);
    for (std::size_t s = 0; s < k; ++s) {
      for (std::size_t i : members[splitting[s]]) {
        for (int a = 0; a < 3; ++a) {
          low[3 * s + a] = std::min(low[3 * s + a], coordinate(i, a));
          high[3 * s + a] = std::max(high[3 * s + a], coordinate(i, a));
        }
        total[s] += weights[i];
      }
    }
    comm.min(low);
    comm.max(high);
    comm.sum(total);
    // each node's axis (its box's longest), target weight below the cut, and bracket [lo, hi):
    // W(x < lo) <= target < W(x < hi)
    std::vector<int> axis(k, 0);
    std::vector<std::int64_t> target(k), below(k, 0);
    std::vector<double> lo(k), hi(k);
    std::vector<std::vector<std::size_t>> candidates(k);
    std::vector<char> searching(k, 0);
    for (std::size_t s = 0; s < k; ++s) {
      const Node& node = result.nodes_[splitting[s]];
      const bool empty = !(low[3 * s] <= high[3 * s]);
      double longest = -1;
      for (int a = 0; a < dimension; ++a) {
        const double extent =
            empty ? node.region.upper[a] - node.region.lower[a] : high[3 * s + a] - low[3 * s + a];
        if (extent > longest) {
          longest = extent;
          axis[s] = a;
        }
      }
      if (cuts != nullptr) {  // the first axis of the order still to be cut
        for (int a : cuts->order) {
          if (node.counts[a] > 1) {
            axis[s] = a;
            break;
          }
        }
      }
      const int lowerParts =
          cuts != nullptr ? node.counts[axis[s]] / 2 * (node.partCount / node.counts[axis[s]])
                          : node.partCount / 2;
      target[s] = total[s] / node.partCount * lowerParts +
                  total[s] % node.partCount * lowerParts / node.partCount;
      if (empty || total[s] == 0) {  // nothing to share: cut the region (or the box) in its middle
        const int a = axis[s];
        const double l = empty ? node.region.lower[a] : low[3 * s + a];
        const double u = empty ? node.region.upper[a] : high[3 * s + a];
        lo[s] = hi[s] = std::isfinite(l) && std::isfinite(u) ? 0.5 * (l + u)
                        : std::isfinite(l)                   ? l
                        : std::isfinite(u)                   ? u
                                                             : 0.0;
        continue;
      }
      lo[s] = low[3 * s + axis[s]];
      hi[s] = std::nextafter(high[3 * s + axis[s]], infinity);
      candidates[s] = members[splitting[s]];
      searching[s] = 1;
    }
    // bisection on the coordinate; only the candidates in [lo, hi) are counted again
    while (std::any_of(searching.begin(), searching.end(), [](char c) { return c != 0; })) {
      std::vector<double> mid(k);
      std::vector<std::int64_t> count(k, 0);
      for (std::size_t s = 0; s < k; ++s) {
        if (!searching[s]) continue;
        mid[s] = lo[s] + 0.5 * (hi[s] - lo[s]);
        for (std::size_t i : candidates[s]) {
          if (coordinate(i, axis[s]) < mid[s]) count[s] += weights[i];
        }
      }
      comm.sum(count);
      for (std::size_t s = 0; s < k; ++s) {
        if (!searching[s]) continue;
        const bool goUp = below[s] + count[s] <= target[s];
        if (goUp) {
          lo[s] = mid[s];
          below[s] += count[s];
        } else {
          hi[s] = mid[s];
        }
        auto& c = candidates[s];
        c.erase(std::remove_if(c.begin(), c.end(),
                               [&](std::size_t i) {
                                 const double x = coordinate(i, axis[s]);
                                 return goUp ? x < lo[s] : x >= hi[s];
                               }),
                c.end());
        // adjacent doubles: [lo, hi) holds the one coordinate value lo
        const double next = lo[s] + 0.5 * (hi[s] - lo[s]);
        if (next <= lo[s] || next >= hi[s]) searching[s] = 0;
      }
    }
    // the candidates now sit at lo: the cut goes below them (weight below[s]) or above them,
    // whichever is nearer the target, halfway to the next coordinate on that side
    std::vector<std::int64_t> atLo(k, 0);
    std::vector<double> under(k, -infinity), over(k, infinity);
    for (std::size_t s = 0; s < k; ++s) {
      if (hi[s] == lo[s]) continue;  // nothing to share
      for (std::size_t i : candidates[s]) atLo[s] += weights[i];
      for (std::size_t i : members[splitting[s]]) {
        const double x = coordinate(i, axis[s]);
        if (x < lo[s]) under[s] = std::max(under[s], x);
        if (x > lo[s]) over[s] = std::min(over[s], x);
      }
    }
    comm.sum(atLo);
    comm.max(under);
    comm.min(over);
    std::vector<int> next;
    for (std::size_t s = 0; s < k; ++s) {
      const int n = splitting[s];
      double cut = lo[s];
      if (hi[s] != lo[s]) {
        const bool cutBelow = target[s] - below[s] <= below[s] + atLo[s] - target[s];
        const double a = cutBelow ? under[s] : lo[s];
        const double b = cutBelow ? lo[s] : over[s];
        cut = std::isfinite(a) && std::isfinite(b) ? a + 0.5 * (b - a) : b;
        if (!std::isfinite(cut)) cut = std::nextafter(a, infinity);
        if (!(cut > a && cut <= b)) cut = b;
      }
      Node lower, upper;
      lower.region = upper.region = result.nodes_[n].region;
      lower.region.upper[axis[s]] = cut;
      upper.region.lower[axis[s]] = cut;
      lower.firstPart = result.nodes_[n].firstPart;
      lower.counts = upper.counts = result.nodes_[n].counts;
      lower.counts[axis[s]] = result.nodes_[n].counts[axis[s]] / 2;
      upper.counts[axis[s]] = result.nodes_[n].counts[axis[s]] - lower.counts[axis[s]];
      lower.partCount = cuts != nullptr ? lower.counts[0] * lower.counts[1] * lower.counts[2]
                                        : result.nodes_[n].partCount / 2;
      upper.firstPart = lower.firstPart + lower.partCount;
      upper.partCount = result.nodes_[n].partCount - lower.partCount;
      result.nodes_[n].axis = axis[s];
      result.nodes_[n].cut = cut;
      result.nodes_[n].lower = static_cast<int>(result.nodes_.size());
      result.nodes_.push_back(lower);
      result.nodes_[n].upper = static_cast<int>(result.nodes_.size());
      result.nodes_.push_back(upper);
      members.resize(result.nodes_.size());
      for (std::size_t i : members[n]) {
        members[coordinate(i, axis[s]) < cut ? result.nodes_[n].lower : result.nodes_[n].upper]
            .push_back(i);
      }
      members[n].clear();
      members[n].shrink_to_fit();
      next.push_back(result.nodes_[n].lower);
      next.push_back(result.nodes_[n].upper);
    }
    for (int n : level) {
      if (result.nodes_[n].partCount == 1) next.push_back(n);
    }
    level = std::move(next);
  }
  result.leaves_.assign(static_cast<std::size_t>(parts), -1);
  result.partWeights_.assign(static_cast<std::size_t>(parts), 0);
  for (std::size_t n = 0; n < result.nodes_.size(); ++n) {
    const Node& node = result.nodes_[n];
    if (node.axis >= 0) continue;
    result.leaves_[node.firstPart] = static_cast<int>(n);
    for (std::size_t i : members[n]) result.partWeights_[node.firstPart] += weights[i];
  }
  comm.sum(result.partWeights_);
  return result;
}

int RecursiveBisection::owner(const Vector& x) const {
  int n = 0;
  while (nodes_[n].axis >= 0) {
    n = static_cast<double>(x[nodes_[n].axis]) < nodes_[n].cut ? nodes_[n].lower : nodes_[n].upper;
  }
  return nodes_[n].firstPart;
}

double RecursiveBisection::imbalance() const {
  std::int64_t total = 0, largest = 0;
  for (std::int64_t w : partWeights_) {
    total += w;
    largest = std::max(largest, w);
  }
  return total > 0 ? static_cast<double>(largest) * parts() / static_cast<double>(total) : 1.0;
}

void RecursiveBisection::collectNear(int node, const Vector& x, double radius,
                                     const PeriodicBox& periodic, int self,
                                     std::vector<int>& near) const {
  const Node& n = nodes_[node];
  if (!(n.region.distance(x, periodic) < radius)) return;
  if (n.axis < 0) {
    if (n.firstPart != self) near.push_back(n.firstPart);
    return;
  }
  collectNear(n.lower, x, radius, periodic, self, near);
  collectNear(n.upper, x, radius, periodic, self, near);
}

void RecursiveBisection::partsNear(const Vector& x, double radius, const PeriodicBox& periodic,
                                   int self, std::vector<int>& near) const {
  collectNear(0, x, radius, periodic, self, near);
}

std::vector<int> RecursiveBisection::neighbours(int part, double radius,
                                                const PeriodicBox& periodic) const {
  std::vector<int> result;
  for (int p = 0; p < parts(); ++p) {
    if (p != part && region(part).distance(region(p), periodic) < radius) result.push_back(p);
  }
  return result;
}

std::string RecursiveBisection::describe() const {
  std::ostringstream text;
  text.precision(6);
  const char* names = "xyz";
  bool first = true;
  for (const Node& node : nodes_) {
    if (node.axis < 0) continue;
    const Node& lower = nodes_[node.lower];
    const Node& upper = nodes_[node.upper];
    auto range = [](const Node& n) {
      return n.partCount == 1 ? std::to_string(n.firstPart)
                              : std::to_string(n.firstPart) + "-" +
                                    std::to_string(n.firstPart + n.partCount - 1);
    };
    text << (first ? "" : "; ") << names[node.axis] << " < " << node.cut << " (" << range(lower)
         << " | " << range(upper) << ")";
    first = false;
  }
  return first ? "one subdomain" : text.str();
}

}  // namespace sphcast
