#include "geometry/WallCurves2D.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/Error.h"
#include "geometry/LatticeSolid.h"

namespace sphcast {

namespace {

using Point = Eigen::Vector2d;

constexpr double thinningDistance = 0.7;  // in dx: see WallCurves2D.h

Point leftNormal(const Point& direction) { return Point(-direction.y(), direction.x()); }

struct Foot {
  Point point = Point::Zero();
  double distance = std::numeric_limits<double>::max();
};

Foot closestOnSegment(const Point& a, const Point& b, const Point& p) {
  const Point ab = b - a;
  const double lengthSquared = ab.squaredNorm();
  const double s =
      lengthSquared > 0.0 ? std::clamp((p - a).dot(ab) / lengthSquared, 0.0, 1.0) : 0.0;
  const Point foot = a + s * ab;
  return {foot, (p - foot).norm()};
}

Foot closestOnPolyline(const std::vector<Point>& points, const Point& p) {
  Foot best;
  for (std::size_t j = 0; j + 1 < points.size(); ++j) {
    const Foot foot = closestOnSegment(points[j], points[j + 1], p);
    if (foot.distance < best.distance) best = foot;
  }
  return best;
}

// Priority in the thinning: exact lattices first, then what fills around them.
enum class Source { straightLayer = 0, cornerSquare = 1, curvedLayer = 2, cornerArc = 3 };

struct Candidate {
  Point position;
  Point normal;  // into the cavity
  double wallDistance;
  double volume;
  int owner;
  std::size_t curve;  // the curve it was made from (or one of the two at a corner)
  Source source;
};

// The side of each curve away from the cavity: +1 when it is the polyline's left side.
double outwardSide(const WallCurve& curve, const PlaneRegion& cavity, double spacing) {
  const std::size_t middle = (curve.points.size() - 1) / 2;
  const Point a = curve.points[middle], b = curve.points[middle + 1];
  const Point centre = 0.5 * (a + b);
  const Point left = leftNormal((b - a).normalized());
  const bool cavityLeft = cavity.contains(centre + 1e-3 * spacing * left);
  const bool cavityRight = cavity.contains(centre - 1e-3 * spacing * left);
  if (cavityLeft == cavityRight) {
    throw Error("cannot tell which side of the wall curve through (" + std::to_string(centre.x()) +
                " " + std::to_string(centre.y()) +
                ") is the cavity: " + (cavityLeft ? "both sides are" : "neither side is") +
                " inside it; the shell goes on the side away from the cavity");
  }
  return cavityLeft ? -1.0 : 1.0;
}

bool closed(const WallCurve& curve) {
  return curve.points.size() > 2 && (curve.points.front() - curve.points.back()).norm() == 0.0;
}

// Outward normal at polyline vertex j of a curved curve: the mean of its two chords' normals
// inside, a one-sided second-order tangent (-3 x0 + 4 x1 - x2) at an open end (the end chord's
// own normal is off by s / (2 R)).
Point vertexNormal(const WallCurve& curve, std::size_t j, double side) {
  const auto& x = curve.points;
  const std::size_t last = x.size() - 1;
  if (closed(curve) && (j == 0 || j == last)) {
    return side * (leftNormal((x[1] - x[0]).normalized()) +
                   leftNormal((x[last] - x[last - 1]).normalized()))
                      .normalized();
  }
  if (j == 0) return side * leftNormal((-3.0 * x[0] + 4.0 * x[1] - x[2]).normalized());
  if (j == last)
    return side * leftNormal((3.0 * x[last] - 4.0 * x[last - 1] + x[last - 2]).normalized());
  return side *
         (leftNormal((x[j] - x[j - 1]).normalized()) + leftNormal((x[j + 1] - x[j]).normalized()))
             .normalized();
}

void addLayers(const WallCurve& curve, std::size_t index, double side, double spacing, int layers,
               std::vector<Candidate>& candidates) {
  for (int k = 0; k < layers; ++k) {
    const double depth = (k + 0.5) * spacing;
    if (curve.straight()) {
      const Point a = curve.points[0], b = curve.points[1];
      const double length = (b - a).norm();
      const Point tangent = (b - a) / length;
      const Point outward = side * leftNormal(tangent);
      const auto count = std::max<long>(1, std::lround(length / spacing));
      const double step = length / static_cast<double>(count);
      for (long i = 0; i < count; ++i) {
        candidates.push_back({a + (static_cast<double>(i) + 0.5) * step * tangent + depth * outward,
                              -outward, depth, step * spacing, curve.owner, index,
                              Source::straightLayer});
      }
      continue;
    }
    // The curve offset by `depth`, then sampled at equal arc length.
    std::vector<Point> offset(curve.points.size());
    for (std::size_t j = 0; j < offset.size(); ++j) {
      offset[j] = curve.points[j] + depth * vertexNormal(curve, j, side);
    }
    std::vector<double> arc(offset.size(), 0.0);
    for (std::size_t j = 1; j < offset.size(); ++j)
      arc[j] = arc[j - 1] + (offset[j] - offset[j - 1]).norm();
    const double length = arc.back();
    const auto count = std::max<long>(1, std::lround(length / spacing));
    const double step = length / static_cast<double>(count);
    std::size_t j = 0;
    for (long i = 0; i < count; ++i) {
      const double s = (static_cast<double>(i) + 0.5) * step;
      while (j + 2 < arc.size() && arc[j + 1] < s) ++j;
      const double w = (s - arc[j]) / std::max(arc[j + 1] - arc[j], 1e-300);
      const Point p = offset[j] + w * (offset[j + 1] - offset[j]);
      const Foot foot = closestOnPolyline(curve.points, p);
      // Behind a curve bent more tightly than the layer's depth the offset folds over: skip it.
      if (foot.distance < depth - 0.25 * spacing) continue;
      // The normal interpolated between the vertices' along the offset chord (the chord's own
      // normal is off by s / (2 R), and so is one interpolated at the foot on the curve's chord).
      const Point outward =
          ((1.0 - w) * vertexNormal(curve, j, side) + w * vertexNormal(curve, j + 1, side))
              .normalized();
      candidates.push_back(
          {p, -outward, foot.distance, step * spacing, curve.owner, index, Source::curvedLayer});
    }
  }
}

// An end of a curve: the end point, the unit tangent leading away from it along the curve, and
// the outward normal there.
struct CurveEnd {
  Point point, away, outward;
};

CurveEnd endOf(const WallCurve& curve, bool atStart, double side) {
  const auto& x = curve.points;
  const Point end = atStart ? x.front() : x.back();
  const Point next = atStart ? x[1] : x[x.size() - 2];
  const Point away = (next - end).normalized();
  // Along the polyline's direction at the start, against it at the end.
  const Point outward = side * leftNormal(atStart ? away : Point(-away));
  return {end, away, outward};
}

// Fills the wedge between the layers of two curves meeting at a convex corner of the cavity.
void addCorner(const CurveEnd& one, const CurveEnd& other, int owner, std::size_t curve,
               double spacing, int layers, std::vector<Candidate>& candidates) {
  const Point& corner = one.point;
  const double cosine = std::clamp(one.outward.dot(other.outward), -1.0, 1.0);
  if (std::abs(cosine) < 1e-9) {  // a right angle: both lattices continued into the square
    for (int a = 0; a < layers; ++a) {
      for (int b = 0; b < layers; ++b) {
        const Point offset =
            (a + 0.5) * spacing * one.outward + (b + 0.5) * spacing * other.outward;
        candidates.push_back({corner + offset, -offset.normalized(), offset.norm(),
                              spacing * spacing, owner, curve, Source::cornerSquare});
      }
    }
    return;
  }
  const double angle = std::acos(cosine);
  const Point across = (other.outward - cosine * one.outward).normalized();
  for (int k = 0; k < layers; ++k) {
    const double radius = (k + 0.5) * spacing;
    const long count = std::lround(radius * angle / spacing);
    for (long i = 0; i < count; ++i) {
      const double theta = (static_cast<double>(i) + 0.5) * angle / static_cast<double>(count);
      const Point direction = std::cos(theta) * one.outward + std::sin(theta) * across;
      candidates.push_back({corner + radius * direction, -direction, radius,
                            radius * angle * spacing / static_cast<double>(count), owner, curve,
                            Source::cornerArc});
    }
  }
}

// Distance from p to the nearest curve other than `own`, or max when none is nearer than `limit`.
double distanceToOtherCurves(const std::vector<WallCurve>& walls,
                             const std::vector<Eigen::AlignedBox2d>& boxes, std::size_t own,
                             const Point& p, double limit) {
  double nearest = std::numeric_limits<double>::max();
  for (std::size_t c = 0; c < walls.size(); ++c) {
    if (c == own || boxes[c].exteriorDistance(p) >= limit) continue;
    nearest = std::min(nearest, closestOnPolyline(walls[c].points, p).distance);
  }
  return nearest;
}

struct CellKey {
  std::int64_t i, j;
  bool operator==(const CellKey&) const = default;
};
struct CellHash {
  std::size_t operator()(const CellKey& key) const {
    return std::hash<std::int64_t>()(key.i * 73856093LL ^ key.j * 19349663LL);
  }
};

}  // namespace

double WallCurve::length() const {
  double sum = 0.0;
  for (std::size_t j = 0; j + 1 < points.size(); ++j) sum += (points[j + 1] - points[j]).norm();
  return sum;
}

void PlaneRegion::add(const std::vector<Eigen::Vector2d>& polyline) {
  for (std::size_t j = 0; j + 1 < polyline.size(); ++j)
    edges_.emplace_back(polyline[j], polyline[j + 1]);
}

std::pair<Eigen::Vector2d, double> PlaneRegion::closest(const Eigen::Vector2d& p) const {
  Foot nearest;
  for (const auto& [a, b] : edges_) {
    const Foot foot = closestOnSegment(a, b, p);
    if (foot.distance < nearest.distance) nearest = foot;
  }
  return {nearest.point, nearest.distance};
}

bool PlaneRegion::contains(const Eigen::Vector2d& p) const {
  // Crossings of the ray from p towards +x; the half-open test counts a vertex on the ray once.
  bool inside = false;
  for (const auto& [a, b] : edges_) {
    if ((a.y() > p.y()) == (b.y() > p.y())) continue;
    const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
    if (x > p.x()) inside = !inside;
  }
  return inside;
}

double PlaneRegion::area() const {
  double twiceArea = 0.0;
  for (const auto& [a, b] : edges_) {
    const double length = (b - a).norm();
    if (length == 0.0) continue;
    const Point probe = 0.5 * (a + b) + 1e-6 * length * leftNormal((b - a) / length);
    const double cross = a.x() * b.y() - b.x() * a.y();
    twiceArea += contains(probe) ? cross : -cross;
  }
  return 0.5 * twiceArea;
}

WallParticles generateShellParticles2D(const std::vector<WallCurve>& walls,
                                       const PlaneRegion& cavity, double spacing, int layers) {
  std::vector<double> sides;
  std::vector<Candidate> candidates;
  for (std::size_t c = 0; c < walls.size(); ++c) {
    sides.push_back(outwardSide(walls[c], cavity, spacing));
    addLayers(walls[c], c, sides[c], spacing, layers, candidates);
  }
  // Corners: every pair of curve ends at the same point (a closed curve's two ends included).
  const double sameEnd = 1e-9 * spacing;
  for (std::size_t c = 0; c < walls.size(); ++c) {
    for (const bool cStart : {true, false}) {
      for (std::size_t d = c; d < walls.size(); ++d) {
        for (const bool dStart : {true, false}) {
          if (d == c && (cStart || !dStart)) continue;  // (c, end) with (c, start) once
          const CurveEnd one = endOf(walls[c], cStart, sides[c]);
          const CurveEnd other = endOf(walls[d], dStart, sides[d]);
          if ((one.point - other.point).norm() > sameEnd) continue;
          // Convex corner of the cavity: the layers part, leaving a wedge between them.
          if (one.outward.dot(other.away) < -1e-9) {
            addCorner(one, other, walls[c].owner, c, spacing, layers, candidates);
          }
        }
      }
    }
  }

  std::vector<Eigen::AlignedBox2d> boxes;
  for (const auto& curve : walls) {
    Eigen::AlignedBox2d box;
    for (const Point& p : curve.points) box.extend(p);
    boxes.push_back(box);
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) {
                     return static_cast<int>(a.source) < static_cast<int>(b.source);
                   });
  const double cell = thinningDistance * spacing;
  std::unordered_map<CellKey, std::vector<Point>, CellHash> kept;
  auto keyOf = [cell](const Point& p) {
    return CellKey{static_cast<std::int64_t>(std::floor(p.x() / cell)),
                   static_cast<std::int64_t>(std::floor(p.y() / cell))};
  };
  WallParticles shell;
  for (const Candidate& candidate : candidates) {
    const Point& p = candidate.position;
    if (cavity.contains(p)) continue;
    if (distanceToOtherCurves(walls, boxes, candidate.curve, p, candidate.wallDistance) <
        candidate.wallDistance - 1e-9 * spacing) {
      continue;  // in the layers of another curve (a re-entrant corner)
    }
    const CellKey key = keyOf(p);
    bool crowded = false;
    for (std::int64_t di = -1; di <= 1 && !crowded; ++di) {
      for (std::int64_t dj = -1; dj <= 1 && !crowded; ++dj) {
        const auto found = kept.find({key.i + di, key.j + dj});
        if (found == kept.end()) continue;
        for (const Point& q : found->second) crowded = crowded || (q - p).norm() < cell;
      }
    }
    if (crowded) continue;
    kept[key].push_back(p);
    shell.positions.emplace_back(p.x(), p.y(), 0.0);
    shell.normals.emplace_back(candidate.normal.x(), candidate.normal.y(), 0.0);
    shell.wallDistances.push_back(candidate.wallDistance);
    shell.volumes.push_back(candidate.volume);
    shell.owners.push_back(candidate.owner);
  }
  return shell;
}

WallParticles fillAreaParticles(const PlaneRegion& region, double spacing, int patch) {
  WallParticles area;
  if (region.edges().empty()) return area;
  Eigen::AlignedBox2d box;
  for (const auto& [a, b] : region.edges()) box.extend(a).extend(b);
  for (std::int64_t j = latticeIndex(box.min().y(), spacing);
       j <= latticeIndex(box.max().y(), spacing); ++j) {
    for (std::int64_t i = latticeIndex(box.min().x(), spacing);
         i <= latticeIndex(box.max().x(), spacing); ++i) {
      const Point p(latticeCoordinate(i, spacing), latticeCoordinate(j, spacing));
      if (!region.contains(p)) continue;
      const auto [point, distance] = region.closest(p);
      const Point outward = (point - p) / std::max(distance, 1e-300);
      area.positions.emplace_back(p.x(), p.y(), 0.0);
      area.normals.emplace_back(outward.x(), outward.y(), 0.0);
      area.wallDistances.push_back(distance);
      area.volumes.push_back(spacing * spacing);
      area.owners.push_back(patch);
    }
  }
  return area;
}

double estimateShellParticleCount2D(const std::vector<WallCurve>& walls, double spacing,
                                    int layers) {
  double length = 0.0;
  for (const auto& curve : walls) length += curve.length();
  return length * layers / spacing;
}

}  // namespace sphcast
