#pragma once

#include <string>
#include <vector>

#include "core/CaseFolder.h"
#include "geometry/GradedVolume.h"
#include "geometry/WallParticles.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// What system/particleizeMoldDict asks for, read and checked in full (dictionary, geometry
// files, physical groups, particle count) before a particle is made:
//
//   dimension     3;            // optional: 2 for a geometry in the plane z = 0 (default 3)
//   geometry      ("cone.geo" "press.msh");  // in constant/geometry: .geo (meshed by gmsh) or .msh
//   spacing       0.002;        // particle spacing dx, m
//   supportRadius 0.0045;       // optional: the kernel's support radius h, m
//   wallLayers    3;            // optional: default ceil(h / dx), or 3 without supportRadius
//   maxParticles  2e7;          // optional: refuse a spacing that would make more
//   patches
//   {
//       moldWall   { cloud mold; type fixedTemperature; mode shell; }  // a surface group
//       upperMold  { cloud upperMold; type rigidBody; mode volume; }    // a volume group
//       die        { cloud die; type fixedWall; mode volume;                 // optional, below:
//                    grading { maxSpacing 0.012; fineLayers 6; fineSurfaces (dieCavity); } }
//   }
//
// type: fixedWall | rigidBody | fixedTemperature (how the solver treats the particles);
// mode: shell (default; `wallLayers` layers behind a surface group, on the side away from the
// volume the surfaces bound, the cavity) | volume (the whole of a closed volume group).
// In 2D (`dimension 2;`, WallCurves2D.h) the geometry lies in the plane z = 0: a shell patch is a
// Physical Curve, its layers on the side away from the cavity, the surface its curves bound or
// the Physical Surface named by `cavity name;`; a volume patch is a Physical Surface filled on
// the square lattice. A .geo's curves are followed by their parametrisation, a .msh's along
// their line elements (mesh curved ones finely, dx/8 or less); particle volumes are areas (m^2).
// grading (volume patches, 3D and 2D; GradedVolume.h): the particles within fineLayers dx of the
// volume's surface keep the spacing dx (default fineLayers 2 wallLayers, at least wallLayers:
// the flow's walls and the contact see those only, and with 2 wallLayers a face's exposed area
// is the uniform mold's), and deeper in the material the spacing doubles every layersPerLevel
// (default wallLayers, at least 2) of its own spacings, up to maxSpacing (at least 2 dx). fineSurfaces (optional: Physical Surfaces of
// the same file; in 2D Physical Curves) keeps dx near those surfaces only, the ones the metal meets; the others, faces
// to the air, may then be coarse (their area: sph/ExposedArea.h). The particles carry their
// spacing (field localSpacing), by which the solver's conduction sizes each pair's kernel
// (thermal/GradedConduction.h).
// wallLayers = ceil(h / dx): the first layer sits dx/2 behind the wall and layer k at
// (k + 1/2) dx, so the layers reach wallLayers dx >= h behind it, and a fluid particle touching
// the wall has a complete kernel.
struct MoldPatch {
  std::string name;
  int id = 0;
  std::string cloud;
  std::string type;
  std::string mode;
  VolumeGrading grading;  // maxSpacing 0: every particle at dx
  std::size_t particleCount = 0;
  SpacingStatistics spacing;  // nearest neighbour among all mold particles
};

struct ParticleizedMold {
  double spacing = 0.0;
  int wallLayers = 0;
  std::vector<MoldPatch> patches;
  std::vector<ParticleCloud> clouds;  // fields volume, normal, wallDistance, patch, id
};

// Reads the dictionary and the geometry and makes the particles; every problem is an Error
// naming the file, line and key. Logs the groups found and what it does.
ParticleizedMold particleizeMold(const CaseFolder& caseFolder);

// constant/particles/patches: one sub-dictionary per patch (id, cloud, type, mode, particles).
std::string patchesDictionaryText(const ParticleizedMold& mold);

}  // namespace sphcast
