#pragma once

#include <algorithm>

#include "core/Real.h"

namespace sphcast {

// The thermal conditions of a mold with a surface (particleizeMold's `normal` and
// `wallDistance`: each particle's depth d_k behind the surface), as conductances of the pair
// between a particle f in front of the surface (at d_f) and a mold particle k. The conduction's
// pair loop (thermal/HeatConduction.cpp) takes the one the mold particle's state asks for: a
// held temperature (heldTemperature > 0) or a conducting wall. A new thermal wall condition
// joins here with its conductance.

// A free particle f against a held particle k of a mold with a surface (normal n_k out of the
// mold, depth d_k behind the surface): k stands for the surface held at T_k. The free side's
// temperature is extended linearly through the surface, T_k' = T_k - (T_f - T_k) d_k / d_f, with
// d_f = max(x_fk . n_k - d_k, dx/4) the free particle's distance in front of it (the flow's
// wall clearance keeps a fluid particle a quarter spacing off a surface), so the pair's
// difference is beta (T_f - T_k), beta = 1 + d_k / d_f, and both sides conduct with kappa_f (the
// held surface takes the mold's place). Returns 2 kappa_f beta: the pair's 4 kappa_i kappa_j /
// (kappa_i + kappa_j) with the ghost's kappa.
inline Real ghostConductance(Real kappaFree, Real freeDistance, Real heldDepth, Real closest) {
  return Real(2) * kappaFree * (Real(1) + heldDepth / std::max(freeDistance, closest));
}

// A particle f of another cloud against a particle k of a mold with a surface that conducts
// (not held): the two conductivities in series over the pair's two sides of the surface, d_f in
// front of it and d_k behind, kappa = kappa_f kappa_k (d_f + d_k) / (d_f kappa_k + d_k kappa_f),
// so that the jump of kappa lies on the mold's wall (the harmonic mean puts it midway between the
// two particles: the same where d_f = d_k, as on a lattice parallel to the wall). Returns twice
// that: the pair's 4 kappa_f kappa_k / (kappa_f + kappa_k) in series.
inline Real seriesConductance(Real kappaFree, Real kappaMold, Real freeDistance, Real moldDepth,
                              Real closest) {
  const Real front = std::max(freeDistance, closest);
  const Real behind = std::max(moldDepth, closest);
  return Real(2) * kappaFree * kappaMold * (front + behind) /
         (front * kappaMold + behind * kappaFree);
}

}  // namespace sphcast
