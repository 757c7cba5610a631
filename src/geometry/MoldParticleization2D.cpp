// particleizeMold in 2D (`dimension 2;`): the geometry lies in the plane z = 0; shell patches
// are Physical Curves, volume patches Physical Surfaces (WallCurves2D.h makes the particles).
#include <algorithm>

#include "core/Error.h"
#include "core/Log.h"
#include "geometry/GmshGeometry.h"
#include "geometry/GradedVolume.h"
#include "geometry/MoldPatchRequest.h"
#include "geometry/WallCurves2D.h"

namespace sphcast {

namespace {

// Curved curves are followed with chords of dx/16: the sag of a chord s on a radius R is
// s^2 / (8 R), 1e-4 dx on R = 5 dx.
double curveSampling(double spacing) { return spacing / 16.0; }

PlaneRegion regionBoundedBy(const GmshGeometry& geometry, const std::vector<int>& surfaces,
                            double spacing) {
  PlaneRegion region;
  for (const int curve : geometry.boundaryCurvesOf(surfaces)) {
    region.add(geometry.planarCurve(curve, curveSampling(spacing)));
  }
  return region;
}

// The area patch's particles graded (GradedVolume.h, the quadtree of the lattice): dx within
// fineDepth of the grading's fineSurfaces (Physical Curves in 2D; none named: the region's
// whole boundary), coarser inward.
WallParticles gradeSurfaceGroup(const GmshGeometry& geometry, const PlaneRegion& region,
                                const MoldPatch& patch, WallParticles filled, double spacing,
                                double areaPerParticle) {
  const VolumeGrading& grading = patch.grading;
  std::vector<double> depth = filled.wallDistances;
  if (!grading.fineSurfaces.empty()) {
    PlaneRegion fine;
    for (const std::string& name : grading.fineSurfaces) {
      const PhysicalGroup* curves = geometry.findGroup(name);
      if (curves == nullptr || curves->dimension != 1) {
        throw Error("grading's fineSurfaces names '" + name +
                    "', which is not a Physical Curve of the 2D geometry; the groups present "
                    "are (" +
                    groupNames(geometry.groups()) + " )");
      }
      for (const int curve : geometry.entitiesOf(*curves)) {
        fine.add(geometry.planarCurve(curve, curveSampling(spacing)));
      }
    }
    for (std::size_t p = 0; p < depth.size(); ++p) {
      depth[p] = fine.closest(filled.positions[p].head<2>()).second;
    }
  }
  const std::size_t uniform = filled.size();
  filled = gradeLatticeParticles(
      filled, depth,
      [&region](const Eigen::Vector3d& x) {
        const auto [point, distance] = region.closest(x.head<2>());
        return std::make_pair(Eigen::Vector3d(point.x(), point.y(), 0.0), distance);
      },
      spacing, areaPerParticle, grading, 2);
  info() << "    graded: " << filled.size() << " particles for the " << uniform << " at dx ("
         << static_cast<double>(uniform) /
                static_cast<double>(std::max<std::size_t>(filled.size(), 1))
         << " times fewer), dx within " << grading.fineDepth << " m of "
         << (grading.fineSurfaces.empty() ? "its boundary" : "its fineSurfaces")
         << ", coarser inward up to " << grading.maxSpacing << " m\n";
  return filled;
}

// The particles filling a surface group, their volumes sharing the group's exact area.
WallParticles fillSurfaceGroup(const GmshGeometry& geometry, const PhysicalGroup& group,
                               const MoldPatch& patch, double spacing) {
  const PlaneRegion region = regionBoundedBy(geometry, geometry.entitiesOf(group), spacing);
  WallParticles filled = fillAreaParticles(region, spacing, patch.id);
  const double area = region.area();
  const double areaPerParticle =
      area / static_cast<double>(std::max<std::size_t>(filled.size(), 1));
  info() << "Surface " << patch.name << ": " << filled.size()
         << " lattice points x dx^2 = " << static_cast<double>(filled.size()) * spacing * spacing
         << " m^2 of the geometry's " << area << " m^2; particle volume (area) set to "
         << areaPerParticle << " m^2\n";
  std::fill(filled.volumes.begin(), filled.volumes.end(), areaPerParticle);
  if (gradingLevels(patch.grading, spacing) > 0) {
    return gradeSurfaceGroup(geometry, region, patch, std::move(filled), spacing, areaPerParticle);
  }
  return filled;
}

}  // namespace

WallParticles particleizePlaneMold(const std::vector<GeometryFilePatches>& files,
                                   const std::vector<PatchRequest>& requests,
                                   const CavityRequest& cavity, double spacing, int layers) {
  WallParticles all;
  for (const auto& [path, patchesOfFile] : files) {
    if (patchesOfFile.empty()) continue;
    const GmshGeometry geometry(path, 0.0);
    std::vector<WallCurve> walls;
    std::vector<int> cavitySurfaces;
    const SourceLocation* firstShell = nullptr;
    for (const std::size_t p : patchesOfFile) {
      const PhysicalGroup& group = *geometry.findGroup(requests[p].patch.name);
      const MoldPatch& patch = requests[p].patch;
      try {
        if (patch.mode == "shell") {
          if (firstShell == nullptr) firstShell = &requests[p].where;
          for (const int curve : geometry.entitiesOf(group)) {
            walls.push_back({geometry.planarCurve(curve, curveSampling(spacing)), patch.id});
          }
          if (cavity.name.empty()) {
            const auto bounded = geometry.surfacesBoundedBy(group);
            cavitySurfaces.insert(cavitySurfaces.end(), bounded.begin(), bounded.end());
          }
        } else {
          all.append(fillSurfaceGroup(geometry, group, patch, spacing));
        }
      } catch (const DictionaryError&) {
        throw;
      } catch (const Error& error) {
        throw DictionaryError(requests[p].where, error.what());
      }
    }
    if (walls.empty()) continue;
    if (!cavity.name.empty()) {
      const PhysicalGroup* group = geometry.findGroup(cavity.name);
      if (group == nullptr || group->dimension != 2) {
        throw DictionaryError(
            cavity.where, "cavity '" + cavity.name + "' is not a physical surface of '" +
                              path.string() + "', which holds the shell patches; its groups are (" +
                              groupNames(geometry.groups()) + " )");
      }
      cavitySurfaces = geometry.entitiesOf(*group);
    }
    std::sort(cavitySurfaces.begin(), cavitySurfaces.end());
    cavitySurfaces.erase(std::unique(cavitySurfaces.begin(), cavitySurfaces.end()),
                         cavitySurfaces.end());
    try {
      const PlaneRegion cavityRegion = regionBoundedBy(geometry, cavitySurfaces, spacing);
      info() << "Shell walls (2D): " << walls.size() << " curves around a cavity of "
             << cavityRegion.area() << " m^2\n";
      all.append(generateShellParticles2D(walls, cavityRegion, spacing, layers));
    } catch (const DictionaryError&) {
      throw;
    } catch (const Error& error) {
      throw DictionaryError(cavity.name.empty() ? *firstShell : cavity.where, error.what());
    }
  }
  return all;
}

}  // namespace sphcast
