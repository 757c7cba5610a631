#pragma once

#include <vector>

#include "geometry/TriangleMesh.h"
#include "geometry/WallParticles.h"

namespace sphcast {

// How much of the wall surface each mold particle's foot must stand for, so that the flow's
// estimate of the surface (particles/WallSurfaceDistance.h) has a plane under every point of it.
//
// The flow reads the surface from the feet s_k = x_k + d_k n_k of the wall particles: a point
// is read against the tangent plane of a foot whose patch (a disc on the plane, about the foot)
// lies under it. On a face on the lattice, discs of 0.75 dx about the feet cover the face to its
// edges. On a face off the lattice they do not: the first layer sits anywhere up to a spacing
// behind the face, the last row of feet up to a spacing short of a convex edge, and a strip of
// face beside the edge had no disc over it: metal there was not seen behind the face (measured
// at crossDitchPress's ditch at dx = 4.5 mm, and on every mold of tests/unit/geometry/
// MoldWallSurfaceTest.cpp: 1.0 to 6.2 % of the points inside the material left in it).
//
// So each foot's disc is sized to cover its share of the surface: the surface is sampled every
// dx/8, each sample is given to its nearest foot of the same face (normal within 25 degrees,
// foot within dx/4 of the sample's tangent plane and 2 dx of the sample, of a particle at most
// 1.5 dx deep; a foot whose normal is within 10 degrees is taken instead if it lies at most dx/2
// farther, so that the fanned normals along an edge do not stand for a face), and a foot's
// radius is the farthest of its samples along its plane, plus 0.09 dx (a point of the surface
// lies within 0.088 dx of a sample, and its nearest foot no farther than that sample's). A foot
// no sample chose gets radius 0: its plane is read nowhere. A foot that stands for a piece of an
// open rim (an edge of one triangle only) is marked: its disc reaches as far past the rim as it
// covers inside, and the flow sets its plane aside over the rim (WallSurfaceDistance.h).
//
// A sample whose foot's particle lies more than 2 dx away (so that metal half a spacing in
// front of the sample, with a support radius of 2.5 dx, would not see it) has no first foot
// that counts: a part of the mold thinner than about two spacings (its lattice points all nearer
// the other face), the sliver of an acute edge. The nearest particle within 2 dx behind that
// face (on the material's side, as the face's first feet within 3 dx say) whose second foot is
// free, or on the same face, and whose projection on the face's plane lies on the surface, takes
// a second foot at its nearest point of the face and stands for those samples as above. The
// results go to `particles` (patchRadii, patchesAtRim where a rim is, and the second feet when
// any particle has one).
void addWallSurfacePatches(WallParticles& particles, const TriangleMesh& surface, double spacing);

}  // namespace sphcast
