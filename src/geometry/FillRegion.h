#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <memory>

#include "core/dictionary/Dictionary.h"

namespace sphcast {

// A region of space that setCastFields fills with particles or sets fields in, read from a
// sub-dictionary of system/setCastFieldsDict:
//
//   { type box;          min (x y z); max (x y z); }
//   { type cylinder;     point1 (..); point2 (..); radius r; }          // axis point1 -> point2
//   { type cone;         point1 (..); point2 (..); radius1 r1; radius2 r2; }  // a frustum
//   { type sphere;       centre (..); radius r; }
//   { type gmshVolume;   file "cavity.geo"; group cavity; }    // a physical volume, constant/geometry
//   { type union;        regions { a { .. } b { .. } } }      // also intersection, difference
//                                                              // (the first minus the others)
// A point on the surface of a shape counts as inside.
class FillRegion {
 public:
  virtual ~FillRegion() = default;
  // p is a point of the fill lattice (LatticeSolid.h): gmsh volumes are classified on it.
  virtual bool contains(const Eigen::Vector3d& p) const = 0;
  virtual Eigen::Vector3d lower() const = 0;
  virtual Eigen::Vector3d upper() const = 0;
  // The region's volume, or an upper bound of it (to refuse too fine a spacing beforehand).
  virtual double volumeBound() const = 0;
  // Whether volumeBound() is the region's volume (true but for booleans).
  virtual bool volumeIsExact() const { return true; }
};

// Reads a region; gmsh volumes are meshed and classified on the lattice of `spacing`. Every
// mistake is a DictionaryError at its key; an unknown type lists the valid ones.
std::unique_ptr<FillRegion> readFillRegion(const Dictionary& region, double spacing,
                                           const std::filesystem::path& geometryFolder);

}  // namespace sphcast
