#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "particles/FieldNames.h"
#include "particles/ParticleCloud.h"

namespace sphcast::testing {

// A rectangular body of wall particles on a lattice of spacing dx, cell centres from lower
// (2D: one layer at z = 0, nz = 1 and depth `dx` per particle's volume dx^2). Each particle's
// normal points out of the body through its nearest face, its wallDistance is its depth behind
// that face, as particleizeMold writes a filled volume.
inline ParticleCloud boxBody(int nx, int ny, int nz, Real dx, const Vector& lower, bool plane,
                             const std::string& name = "body") {
  ParticleCloud body(name);
  body.addScalarField(field::volume);
  body.addVectorField(field::normal);
  body.addScalarField(field::wallDistance);
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const std::size_t p = body.size();
        body.resize(p + 1);
        body.positions()[p] = lower + Vector((i + Real(0.5)) * dx, (j + Real(0.5)) * dx,
                                             plane ? Real(0) : (k + Real(0.5)) * dx);
        // the nearest face: distance in cells to each of the faces
        const int toFace[6] = {i,          nx - 1 - i,          j,
                               ny - 1 - j, plane ? 1 << 20 : k, plane ? 1 << 20 : nz - 1 - k};
        const int nearest = static_cast<int>(std::min_element(toFace, toFace + 6) - toFace);
        Vector n = Vector::Zero();
        n[nearest / 2] = nearest % 2 == 0 ? -1 : 1;
        body.scalarField(field::volume)[p] = plane ? dx * dx : dx * dx * dx;
        body.vectorField(field::normal)[p] = n;
        body.scalarField(field::wallDistance)[p] = (toFace[nearest] + Real(0.5)) * dx;
      }
    }
  }
  body.attributes()["spacing"] = dx;
  return body;
}

}  // namespace sphcast::testing
