#pragma once

#include <vector>

#include "core/CaseFolder.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// What system/setCastFieldsDict asks for, read and checked in full before anything is built:
//
//   spacing       0.005;          // lattice spacing of the filled particles, m
//   maxParticles  20000000;       // optional: refuse a spacing that would make more
//   clouds
//   {
//       metal
//       {
//           regions { ingot { type box; min (0 0 0); max (0.1 0.05 0.1); } }
//           fields  { U (0 0 -1); T 953; }      // initial values: U (m/s), T (K), rho (kg/m^3)
//       }
//   }
//
// Region types other than box (gmsh volumes, cylinder, cone, sphere, booleans) arrive with
// issue #4; an unknown type is an error that lists the valid ones.
std::vector<ParticleCloud> buildCastClouds(const CaseFolder& caseFolder);

}  // namespace sphcast
