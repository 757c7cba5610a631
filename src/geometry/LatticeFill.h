#pragma once

#include <cstddef>
#include <vector>

#include "core/Real.h"

namespace sphcast {

// Particle centres on a cubic lattice of the given spacing inside the box [lower, upper]: each
// particle stands for the cube of side `spacing` around it, so the cubes tile the box and the
// filled volume is exact when the box sides are multiples of the spacing. An axis on which the
// box has zero extent (a 2D case) gets one layer at that coordinate.
std::vector<Vector> fillBoxOnLattice(const Vector& lower, const Vector& upper, double spacing);

// The count fillBoxOnLattice would produce, computed without allocating (to refuse a spacing
// that would make 10^9 particles before trying).
double latticeCountInBox(const Vector& lower, const Vector& upper, double spacing);

}  // namespace sphcast
