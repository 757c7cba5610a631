#include "geometry/FillRegion.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/Error.h"
#include "core/Real.h"
#include "geometry/GmshGeometry.h"
#include "geometry/LatticeSolid.h"
#include "geometry/WallCurves2D.h"

namespace sphcast {

namespace {

const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};
// Points within this fraction of dx of a shape's surface count as inside, so that a lattice
// plane lying on a face is filled whatever the rounding.
constexpr double surfaceTolerance = 1e-9;

Eigen::Vector3d readPoint(const Dictionary& region, const char* key) {
  return region.get<Vector>(key, length).cast<double>();
}

double readPositive(const Dictionary& region, const char* key, bool zeroAllowed = false) {
  const double value = region.get<double>(key, length);
  if (!(value > 0.0) && !(zeroAllowed && value == 0.0)) {
    throw DictionaryError(region.location(key),
                          "'" + std::string(key) + "' must be positive in " + region.name());
  }
  return value;
}

class BoxRegion final : public FillRegion {
 public:
  explicit BoxRegion(const Dictionary& region) {
    region.checkKeys({"type", "min", "max"});
    lower_ = readPoint(region, "min");
    upper_ = readPoint(region, "max");
    if ((upper_ - lower_).minCoeff() < 0) {
      throw DictionaryError(region.location("max"),
                            "box 'max' is below 'min' on some axis in " + region.name());
    }
  }
  bool contains(const Eigen::Vector3d& p) const override {
    return (p.array() >= lower_.array()).all() && (p.array() <= upper_.array()).all();
  }
  Eigen::Vector3d lower() const override { return lower_; }
  Eigen::Vector3d upper() const override { return upper_; }
  double volumeBound() const override { return (upper_ - lower_).prod(); }
  bool sectionAreaIsExact() const override { return true; }

 private:
  Eigen::Vector3d lower_, upper_;
};

// Cylinder (radius1 == radius2) or frustum along point1 -> point2.
class ConeRegion final : public FillRegion {
 public:
  ConeRegion(const Dictionary& region, bool cylinder) {
    if (cylinder) {
      region.checkKeys({"type", "point1", "point2", "radius"});
      radius1_ = radius2_ = readPositive(region, "radius");
    } else {
      region.checkKeys({"type", "point1", "point2", "radius1", "radius2"});
      radius1_ = readPositive(region, "radius1", true);
      radius2_ = readPositive(region, "radius2", true);
    }
    point1_ = readPoint(region, "point1");
    point2_ = readPoint(region, "point2");
    length_ = (point2_ - point1_).norm();
    if (!(length_ > 0.0)) {
      throw DictionaryError(region.location("point2"),
                            "'point2' equals 'point1' in " + region.name() + ": the axis has no length");
    }
    axis_ = (point2_ - point1_) / length_;
  }
  bool contains(const Eigen::Vector3d& p) const override {
    const double along = (p - point1_).dot(axis_);
    const double slack = surfaceTolerance * length_;
    if (along < -slack || along > length_ + slack) return false;
    const double t = std::clamp(along / length_, 0.0, 1.0);
    const double radius = radius1_ + (radius2_ - radius1_) * t;
    return ((p - point1_) - along * axis_).norm() <= radius * (1.0 + surfaceTolerance);
  }
  Eigen::Vector3d lower() const override {
    const double r = std::max(radius1_, radius2_);
    return point1_.cwiseMin(point2_) - Eigen::Vector3d::Constant(r);
  }
  Eigen::Vector3d upper() const override {
    const double r = std::max(radius1_, radius2_);
    return point1_.cwiseMax(point2_) + Eigen::Vector3d::Constant(r);
  }
  double volumeBound() const override {
    return std::numbers::pi * length_ / 3.0 *
           (radius1_ * radius1_ + radius1_ * radius2_ + radius2_ * radius2_);
  }

 private:
  Eigen::Vector3d point1_, point2_, axis_;
  double radius1_ = 0.0, radius2_ = 0.0, length_ = 0.0;
};

class SphereRegion final : public FillRegion {
 public:
  explicit SphereRegion(const Dictionary& region) {
    region.checkKeys({"type", "centre", "radius"});
    centre_ = readPoint(region, "centre");
    radius_ = readPositive(region, "radius");
  }
  bool contains(const Eigen::Vector3d& p) const override {
    return (p - centre_).norm() <= radius_ * (1.0 + surfaceTolerance);
  }
  Eigen::Vector3d lower() const override { return centre_ - Eigen::Vector3d::Constant(radius_); }
  Eigen::Vector3d upper() const override { return centre_ + Eigen::Vector3d::Constant(radius_); }
  double volumeBound() const override { return 4.0 / 3.0 * std::numbers::pi * std::pow(radius_, 3); }
  double sectionAreaBound() const override {
    return std::numbers::pi * std::max(0.0, radius_ * radius_ - centre_.z() * centre_.z());
  }
  bool sectionAreaIsExact() const override { return true; }

 private:
  Eigen::Vector3d centre_;
  double radius_ = 0.0;
};

// The `file` of a gmsh region (in constant/geometry), which must exist.
std::filesystem::path gmshFile(const Dictionary& region,
                               const std::filesystem::path& geometryFolder) {
  region.checkKeys({"type", "file", "group"});
  const auto file = geometryFolder / region.get<std::string>("file");
  if (!std::filesystem::is_regular_file(file)) {
    throw DictionaryError(region.location("file"),
                          "geometry file '" + file.string() + "' does not exist");
  }
  return file;
}

// The region's `group` in the geometry, of the given dimension ("volume" 3, "surface" 2); else
// an error at the key listing the groups of that dimension present.
const PhysicalGroup& gmshGroup(const Dictionary& region, const GmshGeometry& geometry,
                               int dimension, const std::string& kind) {
  const auto name = region.get<std::string>("group");
  const PhysicalGroup* group = geometry.findGroup(name);
  if (group == nullptr || group->dimension != dimension) {
    std::string present;
    for (const auto& g : geometry.groups()) {
      if (g.dimension == dimension) present += " " + g.name;
    }
    throw DictionaryError(region.location("group"),
                          "'" + name + "' is not a physical " + kind + " of '" +
                              geometry.file().string() + "'; the physical " + kind +
                              "s present are (" + present + " )");
  }
  return *group;
}

class GmshVolumeRegion final : public FillRegion {
 public:
  GmshVolumeRegion(const Dictionary& region, double spacing,
                   const std::filesystem::path& geometryFolder) {
    const auto file = gmshFile(region, geometryFolder);
    const auto groupName = region.get<std::string>("group");
    TriangleMesh boundary;
    {
      const GmshGeometry geometry(file, 0.5 * spacing);
      const PhysicalGroup& group = gmshGroup(region, geometry, 3, "volume");
      boundary = geometry.boundaryOfVolumes(geometry.volumesOf(group));
    }
    if (boundary.size() == 0 || boundary.freeEdgeCount() > 0) {
      throw DictionaryError(region.location("group"),
                            "physical volume '" + groupName + "' of '" + file.string() +
                                "' is not closed: " + std::to_string(boundary.freeEdgeCount()) +
                                " edges of its boundary mesh belong to one triangle only");
    }
    lower_ = boundary.lower();
    upper_ = boundary.upper();
    volume_ = boundary.enclosedVolume();
    solid_ = std::make_unique<LatticeSolid>(boundary, spacing);
  }
  bool contains(const Eigen::Vector3d& p) const override { return solid_->contains(p); }
  Eigen::Vector3d lower() const override { return lower_; }
  Eigen::Vector3d upper() const override { return upper_; }
  double volumeBound() const override { return volume_; }

 private:
  std::unique_ptr<LatticeSolid> solid_;
  Eigen::Vector3d lower_, upper_;
  double volume_ = 0.0;
};

// A physical surface of a gmsh file lying in the plane z = 0 (a 2D case's cavity, drawn as
// particleizeMold's 2D molds are): inside by the parity of crossings of its boundary curves.
class GmshSurfaceRegion final : public FillRegion {
 public:
  GmshSurfaceRegion(const Dictionary& region, double spacing,
                    const std::filesystem::path& geometryFolder) {
    const auto file = gmshFile(region, geometryFolder);
    const auto groupName = region.get<std::string>("group");
    const GmshGeometry geometry(file, 0.0);
    const PhysicalGroup& group = gmshGroup(region, geometry, 2, "surface");
    try {
      // chords of dx/16 on curved boundaries, as particleizeMold follows 2D walls
      for (const int curve : geometry.boundaryCurvesOf(geometry.entitiesOf(group))) {
        section_.add(geometry.planarCurve(curve, spacing / 16.0));
      }
    } catch (const Error& error) {
      throw DictionaryError(region.location("group"), error.what());
    }
    if (section_.edges().empty()) {
      throw DictionaryError(region.location("group"), "physical surface '" + groupName + "' of '" +
                                                          file.string() + "' has no boundary");
    }
    lower_ = upper_ = Eigen::Vector3d(section_.edges().front().first.x(),
                                      section_.edges().front().first.y(), 0.0);
    for (const auto& [a, b] : section_.edges()) {
      for (const Eigen::Vector2d& q : {a, b}) {
        lower_ = lower_.cwiseMin(Eigen::Vector3d(q.x(), q.y(), 0.0));
        upper_ = upper_.cwiseMax(Eigen::Vector3d(q.x(), q.y(), 0.0));
      }
    }
    area_ = std::abs(section_.area());
  }
  bool contains(const Eigen::Vector3d& p) const override {
    return std::abs(p.z()) <= surfaceTolerance * (upper_ - lower_).norm() &&
           section_.contains(p.head<2>());
  }
  Eigen::Vector3d lower() const override { return lower_; }
  Eigen::Vector3d upper() const override { return upper_; }
  double volumeBound() const override { return 0.0; }  // a plane section has no volume
  double sectionAreaBound() const override { return area_; }
  bool sectionAreaIsExact() const override { return true; }

 private:
  PlaneRegion section_;
  Eigen::Vector3d lower_, upper_;
  double area_ = 0.0;
};

class BooleanRegion final : public FillRegion {
 public:
  enum class Operation { unite, intersect, subtract };
  BooleanRegion(const Dictionary& region, Operation operation, double spacing,
                const std::filesystem::path& geometryFolder, int dimension)
      : operation_(operation) {
    region.checkKeys({"type", "regions"});
    const Dictionary& parts = region.subDict("regions");
    for (const std::string& name : parts.keys()) {
      parts_.push_back(readFillRegion(parts.subDict(name), spacing, geometryFolder, dimension));
    }
    if (parts_.empty()) {
      throw DictionaryError(parts.location(), "no regions in " + parts.name());
    }
  }
  bool contains(const Eigen::Vector3d& p) const override {
    switch (operation_) {
      case Operation::unite:
        return std::any_of(parts_.begin(), parts_.end(), [&](const auto& r) { return r->contains(p); });
      case Operation::intersect:
        return std::all_of(parts_.begin(), parts_.end(), [&](const auto& r) { return r->contains(p); });
      case Operation::subtract:
        return parts_.front()->contains(p) &&
               std::none_of(parts_.begin() + 1, parts_.end(), [&](const auto& r) { return r->contains(p); });
    }
    return false;
  }
  Eigen::Vector3d lower() const override {
    Eigen::Vector3d result = parts_.front()->lower();
    for (const auto& part : parts_) {
      result = operation_ == Operation::unite ? result.cwiseMin(part->lower())
               : operation_ == Operation::intersect ? result.cwiseMax(part->lower())
                                                    : result;
    }
    return result;
  }
  Eigen::Vector3d upper() const override {
    Eigen::Vector3d result = parts_.front()->upper();
    for (const auto& part : parts_) {
      result = operation_ == Operation::unite ? result.cwiseMax(part->upper())
               : operation_ == Operation::intersect ? result.cwiseMin(part->upper())
                                                    : result;
    }
    return result;
  }
  double volumeBound() const override { return bound(&FillRegion::volumeBound); }
  bool volumeIsExact() const override { return false; }
  double sectionAreaBound() const override { return bound(&FillRegion::sectionAreaBound); }

 private:
  // A bound of the combined measure from the parts': their sum for a union, the smallest for
  // an intersection, the first's for a difference.
  double bound(double (FillRegion::*measure)() const) const {
    if (operation_ == Operation::subtract) return (parts_.front().get()->*measure)();
    double sum = 0.0, smallest = (parts_.front().get()->*measure)();
    for (const auto& part : parts_) {
      sum += (part.get()->*measure)();
      smallest = std::min(smallest, (part.get()->*measure)());
    }
    return operation_ == Operation::unite ? sum : smallest;
  }

  Operation operation_;
  std::vector<std::unique_ptr<FillRegion>> parts_;
};

}  // namespace

std::unique_ptr<FillRegion> readFillRegion(const Dictionary& region, double spacing,
                                           const std::filesystem::path& geometryFolder,
                                           int dimension) {
  const std::string type =
      region.getChoice("type", {"box", "cylinder", "cone", "sphere", "gmshVolume", "gmshSurface",
                                "union", "intersection", "difference"});
  if (type == "box") return std::make_unique<BoxRegion>(region);
  if (type == "cylinder") return std::make_unique<ConeRegion>(region, true);
  if (type == "cone") return std::make_unique<ConeRegion>(region, false);
  if (type == "sphere") return std::make_unique<SphereRegion>(region);
  if (type == "gmshVolume") {
    if (dimension == 2) {
      throw DictionaryError(region.location("type"),
                            "a 2D case fills gmsh geometry from a physical surface in the plane "
                            "z = 0: give 'type gmshSurface;' in " + region.name());
    }
    return std::make_unique<GmshVolumeRegion>(region, spacing, geometryFolder);
  }
  if (type == "gmshSurface") {
    if (dimension != 2) {
      throw DictionaryError(region.location("type"),
                            "'type gmshSurface' is for 2D cases (dimension 2); a 3D case fills a "
                            "physical volume: give 'type gmshVolume;' in " + region.name());
    }
    return std::make_unique<GmshSurfaceRegion>(region, spacing, geometryFolder);
  }
  const auto operation = type == "union"          ? BooleanRegion::Operation::unite
                         : type == "intersection" ? BooleanRegion::Operation::intersect
                                                  : BooleanRegion::Operation::subtract;
  return std::make_unique<BooleanRegion>(region, operation, spacing, geometryFolder, dimension);
}

}  // namespace sphcast
