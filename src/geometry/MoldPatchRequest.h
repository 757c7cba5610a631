#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/dictionary/SourceLocation.h"
#include "geometry/GmshModel.h"
#include "geometry/MoldParticleization.h"

namespace sphcast {

// particleizeMold's own pieces, shared by its 3D (MoldParticleization.cpp) and 2D
// (MoldParticleization2D.cpp) halves.

// A patch of the dictionary and where it was written, for errors.
struct PatchRequest {
  MoldPatch patch;
  SourceLocation where;
};

// A geometry file and the patches (indices into the requests) whose groups it holds.
struct GeometryFilePatches {
  std::filesystem::path path;
  std::vector<std::size_t> patches;
};

// " a b c": the names of the groups, for errors that list them.
std::string groupNames(const std::vector<PhysicalGroup>& groups);

// 2D: the cavity the shells go around, `cavity <Physical Surface>;` (name empty: the surfaces
// the shell curves bound).
struct CavityRequest {
  std::string name;
  SourceLocation where;
};

// The particles of the 2D patches (WallCurves2D.h): shells behind Physical Curves, volumes
// filling Physical Surfaces (graded where the patch asks: GradedVolume.h's quadtree), all in
// the plane z = 0.
WallParticles particleizePlaneMold(const std::vector<GeometryFilePatches>& files,
                                   const std::vector<PatchRequest>& requests,
                                   const CavityRequest& cavity, double spacing, int layers);

}  // namespace sphcast
