#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/Smoothstep.h"
#include "particles/GradedPairs.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"
#include "sph/ParticleVolumes.h"

namespace sphcast {

// How the exposed area is estimated (doc/physics.md §10.2.4).
enum class ExposedAreaForm {
  // A_i = R_A V_i |grad s_i| w(cbar_i), grad s_i = sum_j V_j grad_i W_ij: the surface delta
  // function of the continuum surface force (Brackbill, Kothe & Zemach 1992), whose integral
  // across any interface is its area, gated to zero inside the body (interiorGate below); the
  // default.
  gradient,
  // A_i = R_A g(1 - s_i, 1 - s_min,i) V_i^((d-1)/d), eq. (11) of the paper with g of eq. (10):
  // g grows as (1 - s)^3, so particles with few neighbours (edges, the steps of a lattice cut
  // by a curved surface) count far more than their share.
  granularity
};

// The area A_i of each particle exposed to the outside (the air), from its rate of
// granularity s_i, eq. (7) of the paper:
//
//   s_i = sum_j V_j W(|x_i - x_j|, h)          over i itself and every particle of every
//                                              covering cloud (metal and molds alike: a face
//                                              against the mold is not exposed to the air)
//
// by either form above, with V from particleVolumes (ParticleVolumes.h: mass / rho, else volume).
// R_A is calibrated for the form, the dimension and h/dx by calibratedAreaFactor(): the sum of
// A_i over a column of a semi-infinite cubic lattice under a flat free surface is exactly the
// column's cross-section dx^(d-1). At h = 3 dx: R_A = 2.00 (3D) and 2.01 (2D) for the gradient
// form (the particles sample only the inner half of the smoothed interface), 59.2 (3D) and
// 44.3 (2D) for eq. (11), where the paper takes R_A = R_d, the surface-tension constant: its
// R_3 = 41.3 would count 70 % of a flat face, its R_2 = 41.4 94 %.
// Edges, corners and curved surfaces are then approximations, measured in
// tests/unit/thermal/SurfaceHeatLossTest.cpp: the sum over a cube of 10 / 20 / 40 particles
// across is 22 / 11 / 6 % short of 6 L^2 with the gradient form (edges rounded over about h),
// 60 / 31 / 15 % over with eq. (11); over a ball cut from the lattice, 15 / 6.4 / 3.0 % against
// 140 / 99 / 84 %.
//
// The gate: |grad s_i| does not vanish inside a disordered body (particles moved by up to
// +-0.15 dx per coordinate, as any flow leaves them, give every interior particle 0.0955 dx^2 in
// 3D at h = 3 dx, so a jittered cube of 40 across came out 44 % over, the error growing with the
// volume). w(cbar_i) is 1 at the surface and 0 inside, on the fullness
//   c_i = -(1/d) sum_j V_j r_ij dW/dr(r_ij) / c_full     (the trace of the first-moment matrix
//                                                        sum_j V_j x_ji grad_i W_ij over d,
//                                                        c_full its value in a full lattice)
// smoothed by its Shepard mean cbar_i = sum_j V_j W_ij c_j / s_i, whose spread inside a jittered
// body is 0.008 (+-0.15 dx), against 0.026 for s_i itself. The ramp runs from 0.920 to 0.970 at
// h = 3 dx in 3D, above the 0.892 of a flat lattice face's deepest layer with area, so every
// lattice surface keeps its area (the cube's sums are those above to the digit); it is set from
// that layer's value, cbar_L, at other h: from cbar_L + 0.26 (1 - cbar_L) to cbar_L + 0.72
// (1 - cbar_L). Measured at h = 3 dx (tests/unit/thermal/SurfaceHeatLossTest.cpp): the jittered
// cube of 10 / 20 / 40 across -21.0 / -9.4 / -3.5 % (without the gate -18.0 / +7.2 / +44.1 %).
// Clouds that keep their lattice (the solver's walls) are left ungated (the constructor's
// `lattices`): a first version gated the molds too, and the few mold particles whose area it
// changed were enough to change crossDitchPress's pour at 4 mm so that a splash went over the
// lower mold's rim and fell out of the domain (which then stopped the run; metal that leaves
// the domain is now spilled and booked, solver/MetalSpill.h).
//
// A mold particleized at graded spacing (the field localSpacing, geometry/GradedVolume.h): each
// of its coarser particles sums over its own cloud with its own kernel, h_i = (h / dx) l_i
// (GradedPairs.h, PairSupport::row), its s, gradient and fullness, so that a face of particles of
// spacing l shows the area a lattice of l shows (R_A and the gate's ramp depend on h / l only:
// the flat face of 4 dx particles of GradedMoldTest reads its area to 1e-5); its particles at dx
// sum as every particle does. Where two spacings meet, the sums of unlike particles leave a
// gradient that no surface makes (0.73 of a face's area inside GradedMoldTest's block): a particle
// of a graded cloud deeper than its own support radius (its wallDistance, particleizeMold's) is
// given none (decomposed: each rank's own rows, over a halo that reaches the coarsest support).
// Measured on that block: a face crossed by two changes of spacing 0.4 to 0.8 % over
// its area; the faces of the coarser particles lose more at their edges, rounded over their own
// support (a die of 100 mm graded from 2 to 8 mm: 17 % less area to the air than the exact, the
// uniform die 4.5 % less).
//
// Writes the field `exposedArea` (m^2 in 3D, m in 2D) of each exposed cloud, and `granularity`
// (s_i), shared by every model that needs them (atmosphere, radiation; surface tension next).
class ExposedArea {
 public:
  // exposed: the clouds whose A_i is wanted; covering: every cloud whose particles cover
  // (include the exposed ones). Registers the pairs in the neighbourhood. spacing: the lattice
  // spacing dx the calibration assumes (the exposed clouds' `spacing` attribute). lattices:
  // exposed clouds whose particles keep their lattice (walls, fixed or rigid), which have no
  // interior noise to gate: the gradient form leaves them ungated, and they cost no second pass.
  ExposedArea(ExposedAreaForm form, int dimension, Real supportRadius, Real spacing,
              std::vector<ParticleCloud*> exposed, std::vector<const ParticleCloud*> covering,
              Neighbourhood& neighbourhood, std::vector<const ParticleCloud*> lattices = {});

  // s_i and A_i of every exposed particle, for the neighbourhood's last update (particles that
  // do not move keep theirs: the solver computes it once without a flow).
  void compute();

  Real areaFactor() const { return areaFactor_; }

  // R_A for this form, dimension and h/dx (see the class comment).
  static Real calibratedAreaFactor(ExposedAreaForm form, int dimension, Real supportRadius,
                                   Real spacing);
  // cbar of a flat lattice face's deepest layer whose gradient (area) is not zero.
  static Real deepestAreaLayerFullness(int dimension, Real supportRadius, Real spacing);

 private:
  template <int Dim>
  void computeIn();
  void findCoarsePairs();

  ExposedAreaForm form_;
  int dimension_;
  Real supportRadius_;
  Real areaFactor_;
  std::vector<ParticleCloud*> exposed_;
  std::vector<const ParticleCloud*> covering_;
  std::vector<const ParticleCloud*> lattices_;
  Real spacing_;
  // per exposed cloud: the pairs within itself of its coarser particles, when it is graded
  std::vector<std::unique_ptr<GradedPairs>> coarsePairs_;
  std::vector<std::uint64_t> coarseLayouts_;       // the clouds' layoutVersion at coarsePairs_'s
  std::vector<std::vector<Real>> coveringVolume_;  // V of each covering cloud, every pass
  std::vector<std::vector<Real>> fullness_;        // c_i of each exposed cloud, every pass
  std::vector<std::vector<Real>> gradientArea_;    // the ungated A_i of each exposed cloud
  // Rows of a lattice (an exposed wall: its area is its own row's sums, no gate) that nothing
  // changed since the last pass keep what they hold: a mold at rest away from the metal, most
  // of crossDitchPress's mold rows, reads the same sums every heat step (markChanged).
  struct CoveringState {
    std::vector<Vector> positions;      // at the last pass
    std::vector<Real> volumes;          // at the last pass
    std::vector<std::uint8_t> changed;  // per particle: position or volume since then
    bool anyChanged = true;
  };
  struct LatticeRows {
    bool valid = false;                      // every row computed at least once
    std::size_t size = 0;                    // the cloud's particles then
    std::vector<std::uint64_t> listChanges;  // per covering cloud: the list's changes() then
    std::vector<std::uint32_t> neighbourIn;  // per row: bit c where it had pairs in cloud c
  };
  void markChanged();
  std::vector<CoveringState> coveringState_;
  std::vector<LatticeRows> latticeRows_;  // per exposed cloud (used for lattices only)
  Real gateFrom_ = 0, gateTo_ = 1;        // the interior gate's ramp in cbar
  Real fullLatticeMoment_ = 1;            // c_full
  const Neighbourhood& neighbourhood_;
};

// The interior gate: 1 for cbar <= from, 0 for cbar >= to, a smoothstep between.
inline Real interiorGate(Real meanFullness, Real from, Real to) {
  return Real(1) - smoothstep((meanFullness - from) / (to - from));
}

// g(p, q)/R_d of eq. (10).
inline Real exposureWeight(Real p, Real q) {
  if (!(p > Real(0))) return Real(0);
  if (p >= q) return Real(0.5) * q;
  const Real ratio = p / q;
  return p * ratio * ratio - Real(0.5) * p * ratio * ratio * ratio;
}

// sum_k g(1 - s_k, 1 - s_min)/R_d over the layers k = 0, 1, ... of a semi-infinite cubic
// lattice of spacing dx under a flat free surface, s_k summed with `kernel` (value(r)) over the
// half lattice and s_min = dx^d kernel.value(0): 1 / R_d for eq. (10)'s g to make the face's
// area (the calibration of eq. (11) here, of the surface energy in surface/).
template <int Dim, class Kernel>
Real flatSurfaceExposureSum(const Kernel& kernel, Real supportRadius, Real spacing) {
  const Real cell = std::pow(spacing, Dim);
  const int reach = static_cast<int>(std::ceil(supportRadius / spacing)) + 1;
  const int dyRange = Dim == 3 ? reach : 0;
  const Real q = Real(1) - cell * kernel.value(0);
  Real columnSum = 0;
  for (int layer = 0; layer <= reach; ++layer) {
    Real s = 0;
    for (int dz = -reach; dz <= reach; ++dz) {
      if (layer + dz < 0) continue;  // above the surface: no particle
      for (int dy = -dyRange; dy <= dyRange; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          s += cell * kernel.value(spacing * std::sqrt(Real(dx * dx + dy * dy + dz * dz)));
        }
      }
    }
    columnSum += exposureWeight(Real(1) - s, q);
  }
  return columnSum;
}

}  // namespace sphcast
