#pragma once

#include <vector>

#include "core/CaseFolder.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// What system/setCastFieldsDict asks for, read and checked in full before anything is built:
//
//   spacing       0.005;          // lattice spacing of the filled particles, m
//   maxParticles  20000000;       // optional: refuse a spacing that would make more
//   wallClearance 0.00375;        // optional, m: default 0.75 spacing (see below)
//   clouds                        // new clouds, filled on the lattice
//   {
//       metal
//       {
//           regions { ingot { type box; min (0 0 0); max (0.1 0.05 0.1); } }  // FillRegion.h
//           fields  { U (0 0 -1); T 953; }      // initial values: U (m/s), T (K), rho (kg/m^3)
//       }
//   }
//   setFields                     // optional: fields on the existing clouds of constant/particles
//   {
//       mold { fields { T 300; } regions { ... } }   // regions optional: only particles inside
//   }
//
// Regions of a cloud are filled one after the other. A box at the top level keeps its own
// lattice, centred in the box (so the filled volume is exact when its sides are multiples of
// the spacing); every other region is filled on the shared lattice ((i + 1/2) dx, LatticeSolid.h)
// that particleizeMold also uses.
// Fluid particles closer than wallClearance to a particle of constant/particles/*.vtp are left
// out. 0.75 dx: the first wall layer lies dx/2 behind the wall, so fluid centres stay at least
// dx/4 inside it: a fluid particle's cube of side dx overlaps the wall layer by at most dx/4
// (no clump, no pressure spike at start) while the gap it leaves is at most 3/4 dx, and on a
// lattice parallel to a flat wall it keeps exactly the layers at dx/2, 3dx/2, ... from it.
// Every filled particle gets `volume` dx^3 and `id`. Initial density from the material tables
// (rho_s(T), hydrostatic) awaits those tables; `rho` sets a uniform value.
// Returns the new clouds followed by the clouds whose fields were set, all for 0/.
std::vector<ParticleCloud> buildCastClouds(const CaseFolder& caseFolder);

}  // namespace sphcast
