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
// MoldWallSurfaceTest.cpp: 0.6 to 12.9 % of the points inside the material not read behind).
//
// So each foot's disc is sized to cover its share of the surface: the surface is sampled every
// dx/8, each sample is given to its nearest foot of the same face (normal within 25 degrees,
// foot within dx/4 of the sample's tangent plane, of a particle at most 1.5 dx deep), and a
// foot's radius is the farthest of its samples along its plane, plus 0.09 dx (a point of the
// surface lies within 0.088 dx of a sample, and its nearest foot no farther than that sample's).
// A foot no sample chose gets radius 0: its plane is read nowhere.
//
// A sample whose nearest foot of its face, or that foot's particle, lies more than 1.5 dx away
// has no first foot that metal there would see: a part of the mold thinner than about two
// spacings (its lattice points all nearer the other face), the sliver of an acute edge, a face
// the first layer misses. The nearest particle within 1.5 dx whose second foot is free, or on
// the same face, takes a second foot on the sample's tangent plane (x_k's projection on it) and
// stands for those samples as above. The results go to `particles` (patchRadii, and the second
// feet when any particle has one).
void addWallSurfacePatches(WallParticles& particles, const TriangleMesh& surface, double spacing);

}  // namespace sphcast
