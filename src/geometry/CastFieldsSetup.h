#pragma once

#include <vector>

#include "case/CaseDescription.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// What system/setCastFieldsDict asks for, read and checked in full before anything is built:
//
//   dimension     2;              // optional: constant/physicsModels' (3 without it); 2 for a
//                                 // case in the plane z = 0
//   spacing       0.005;          // lattice spacing of the filled particles, m
//   maxParticles  20000000;       // optional: refuse a spacing that would make more
//   moldClearance 0.00375;        // optional, m: default 0.75 spacing (see below; its former
//                                 // name wallClearance is read with a warning)
//   relaxation    { iterations 200; }   // optional, for every new cloud (off by default)
//   clouds                        // new clouds, filled on the lattice
//   {
//       metal
//       {
//           material   metal;     // optional: sub-dictionary of constant/physicalProperties
//                                 // (default: constant/physicsModels' `materials` map, else
//                                 // the cloud's name, as the solver reads it; the two files
//                                 // may not name different materials)
//           regions { ingot { type box; min (0 0 0); max (0.1 0.05 0.1); } }  // FillRegion.h
//           fields  { U (0 0 -1); T 953; rho hydrostatic; }
//           relaxation { iterations 200; }   // optional: overrides the global one
//       }
//   }
//   setFields                     // optional: fields on the existing clouds of constant/particles
//   {
//       mold { fields { T 300; } regions { ... } }   // regions optional: only particles inside
//   }
//
// fields: U (m/s), T (K), rho: a number (kg/m^3), `standard` (rho_s(T) of the material) or
// `hydrostatic` (rho_s (1 + |g| d / c^2) at depth d below the cloud's free surface,
// InitialDensity.h; c is soundSpeed of system/sphSchemes, g is constant/g). rho_s is the
// material's `density` in constant/physicalProperties, a number or a table in T
// (materials/TemperatureTable.h); with a table, T must be given and lie inside it. Without `rho`
// none is written (the solver then starts at its rest density).
//
// Regions of a cloud are filled one after the other; a lattice point that an earlier region of
// the cloud holds is not filled again (no doubled particles where regions overlap). A box at the
// top level keeps its own lattice, centred in the box (so the filled volume is exact when its sides
// are multiples of the spacing); every other region is filled on the shared lattice ((i + 1/2) dx,
// LatticeSolid.h) that particleizeMold also uses. Fluid particles closer than moldClearance to a
// particle of constant/particles are left out. 0.75 dx: the first wall layer lies dx/2 behind the
// wall, so fluid centres stay at least dx/4 inside it: a fluid particle's cube of side dx overlaps
// the wall layer by at most dx/4 (no clump, no pressure spike at start) while the gap it leaves is
// at most 3/4 dx, and on a lattice parallel to a flat wall it keeps exactly the layers at dx/2,
// 3dx/2, ... from it.
//
// relaxation (PackingRelaxation.h): the lattice cut by a curved wall leaves gaps and clumps
// along it; `iterations` steps of background-pressure relaxation even them out, with the mold
// particles as fixed neighbours (kernel support h: supportRadius of system/sphSchemes, else
// 3 dx). A particle may not leave its regions nor come closer than moldClearance to a mold
// particle or to the fixed lattice beyond the free surface (such a move is not made). Where the
// metal has a free surface (no wall), the fill lattice continued beyond the regions is held fixed
// as neighbours: the surface stays where the fill put it instead of swelling into the empty kernel
// half, which is what the metal's own surface tension and the run will decide.
//
// Every filled particle gets `volume` dx^3 (dx^2 with `dimension 2`, where every region is cut
// by the plane z = 0 and fills its section on the lattice ((i + 1/2) dx, (j + 1/2) dx, 0);
// FillRegion.h) and `id`. The log reports for each new cloud the count, the filled volume
// (count dx^3) against the regions' volume (exact for shapes and gmsh volumes that do not
// overlap, else the bound; areas in 2D) and the nearest-neighbour spacing.
// An empty fill is an error naming the cloud and the region, and why: a region holding no
// lattice point (thinner than a spacing, or off the plane of a 2D case), a region whose points
// all lie within moldClearance of the mold (inside it), a cloud wholly outside the domain (the
// mold particles' box grown by half).
// moldClouds are the clouds of constant/particles (setCastFields reads them): obstacles for the
// fill, fixed neighbours for the relaxation, and the clouds `setFields` works on.
// Returns the new clouds followed by the clouds whose fields were set, all for 0/.
std::vector<ParticleCloud> buildCastClouds(const CaseDescription& description,
                                           const std::vector<ParticleCloud>& moldClouds);

}  // namespace sphcast
