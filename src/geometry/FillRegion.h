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
//   { type gmshSurface;  file "cavity.geo"; group cavity; }    // a physical surface in z = 0 (2D)
//   { type union;        regions { a { .. } b { .. } } }      // also intersection, difference
//                                                              // (the first minus the others)
// A point on the surface of a shape counts as inside. In a 2D case (dimension 2) every region
// is cut by the plane z = 0 and fills that section: a sphere gives a disk, a cylinder along z a
// disk, a box its rectangle; gmsh geometry is a physical surface in the plane (gmshSurface), as
// particleizeMold reads 2D molds.
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
  // The area of the region's section with the plane z = 0 (2D cases), or an upper bound of it:
  // the section of its bounding box unless the shape knows better.
  virtual double sectionAreaBound() const {
    const Eigen::Vector3d l = lower(), u = upper();
    return l.z() <= 0.0 && u.z() >= 0.0 ? (u.x() - l.x()) * (u.y() - l.y()) : 0.0;
  }
  // Whether sectionAreaBound() is the section's area.
  virtual bool sectionAreaIsExact() const { return false; }
};

// Reads a region; gmsh volumes are meshed and classified on the lattice of `spacing`. Every
// mistake is a DictionaryError at its key; an unknown type lists the valid ones. `dimension` 2
// takes gmshSurface and refuses gmshVolume (and the reverse in 3D).
std::unique_ptr<FillRegion> readFillRegion(const Dictionary& region, double spacing,
                                           const std::filesystem::path& geometryFolder,
                                           int dimension = 3);

}  // namespace sphcast
