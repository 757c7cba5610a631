#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"
#include "surface/SurfaceTensionModel.h"

namespace sphcast {

// The colour of a free surface seen through the kernel: a fluid that fills the half space
// z > 0 (z: depth below its surface) has the colour
//   C(z) = sum_j V_j W(x - x_j) -> 1/2 + int_0^z P(t) dt,   P(t) = int W(sqrt(t^2 + rho^2)) d rho
// (P: the kernel integrated over the plane). Tabulated once (Simpson's rule) for the kernel of
// support h, and inverted: the depth of a particle under the surface from its colour.
class SurfaceDepthProfile {
 public:
  SurfaceDepthProfile(int dimension, Real supportRadius);
  // The depth z in [0, h] at which a half space's colour is c (0 for c <= 1/2, h for c >= 1).
  Real depth(Real colour) const;
  // C(z), z in [0, h] (1/2 at the surface, 1 from h on).
  Real colour(Real depth) const;

 private:
  Real h_;
  std::vector<Real> colour_;  // C at z_k = k h / (size - 1), increasing from 1/2 to 1
};

// Surface tension set by sigma, with the contact angle theta at the walls: the continuum
// surface force (Brackbill, Kothe & Zemach 1992, J. Comput. Phys. 100:335) for a free surface
// with one phase, with corrected operators (the normal and the contact angle as Breinlinger,
// Polfer, Hashibon & Kraft 2013, J. Comput. Phys. 243:14; doc/physics.md §10.1.2):
//
//   a_i = -(2 sigma(T_i) kappa_i / rho_i) g_i,   g_i = -sum_j V_j grad_i W_ij          (CSF)
//
// over the fluid and the walls. g_i is the colour's gradient (out of the liquid), the surface's
// delta times its normal; in the bulk it vanishes. Why 2 and this g: the flow's pressure force,
// -sum_j V_j (p_i + p_j) grad_i W_ij / rho_i, is for a uniform pressure P exactly
// +2 P g_i / rho_i, nonzero where the kernel is cut by the free surface: that is how SPH holds
// p = 0 there. With the force above, a drop at the uniform pressure sigma kappa is in exact
// discrete equilibrium whatever its particles' arrangement, when kappa is right (the flow's
// walls carry the fluid's pressure, so they count in g: a face on a mold has g = 0 and no force).
// - normal: g smoothed over the fluid (Shepard, sum_j V_j g_j W_ij / sum_j V_j W_ij) and made
//   unit, n_i; on the particles whose |g| is above a tenth of a flat face's largest (a weight
//   rising smoothly to 1 at a fifth, so that no particle is kicked by a threshold), within h of
//   the surface: the surface particles;
// - contact angle: within h of a wall (its distance l_i and normal n_w from the wall particles,
//   particles/WallSurfaceDistance.h, each step, so curved and moving molds are followed) the
//   normal is turned towards n_w cos(theta) + t sin(theta), t the unit part of n_i along the
//   wall, with the weight 1 - s(l_i / h) (s: smoothstep): at the wall the surface meets it at
//   theta (Young), and the curvature that follows bends it there; theta is at most 150 degrees
//   (above it a free drop on a wall threw particles out; 150 reads 109 to 114 on a sessile
//   drop with no-slip walls, which pin the contact line, and 140 with `wallSlip slip`,
//   doc/validation.md §2.2);
// - curvature: the divergence of n over the surface particles, normalised so that it is exact
//   for a field that turns only along the surface, whatever part of the kernel is filled:
//     kappa_i = (d - 1) sum_j w_j V_j (n_j - n_i) . grad_i W_ij
//                 / sum_j w_j V_j F_ij (r_ij^2 - (n_i . x_ij)^2)
//   (grad_i W_ij = F_ij x_ji, F = -W'/r, w_j the surface weight): (d - 1) / r on a sphere of
//   radius r. A surface particle lies at the depth z_i = C^-1(c_i) under the surface
//   (SurfaceDepthProfile, c_i = sum_j V_j W_ij over fluid and walls, over a lattice's bulk sum),
//   whose curvature is kappa_i (d - 1) / ((d - 1) + kappa_i z_i). Then smoothed over the surface
//   particles (Shepard), and carried to every particle within h of them, fading as fewer are
//   near: the force acts wherever g is not 0 near the surface, as the pressure's does;
// - a gap between facing walls narrower than 2 h (`gapMeniscus on`; off by default): its
//   meniscus is tighter than the kernel resolves (the curvature above is bounded by (d - 1) /
//   h), so near the surface in the gap the curvature is Young-Laplace's for a slot of width w,
//   -2 cos(theta) / w (w: the distances to the nearest wall surface and to the facing one, at
//   least dx), in full up to w = h, blended into the kernel's over h < w < 2 h and past the
//   facing wall's end. A round hole has two such curvatures: it is read as a slot, with half
//   its entry pressure. Not the default: in crossDitchPress it holds the pressed plate's rim,
//   but the pressed melt comes to rest later and the run takes twice as long (doc/physics.md
//   §10.1.2).
// Read on a drop of rings at Laplace's pressure (ContinuumSurfaceForceTest): curvature within
// 0.3 % of (d - 1) / R, 1 to 1.5 % from particle to particle; what is left of the force after
// the pressure's, 1 % RMS. A lattice's staircase reads more curvature, on the mean over its surface
// particles 4 to 6 % (3D, R = 15 and 30 dx) and 14 to 40 % (2D, R = 15 to 60 dx), until the
// surface rounds its steps off.
//
// sigma(T) is the fluid material's surfaceTension: a constant or a table; a particle where it
// is 0 (the solid rows of AC4CH) carries no force. Reads the fluid's positions, mass, rho, T
// (when sigma is a table); the walls' positions, normal, wallDistance and volumes. Adds to
// `acceleration`; writes `curvature` (1/m: the surface's, near the surface; 0 elsewhere, and on
// frozen metal more than three neighbour hops from the melt, whose colour gradient is not summed).
class ContinuumSurfaceForce : public SurfaceTensionModel {
 public:
  // settings: dimension, supportRadius, spacing, gasTension (sigma) and cosContactAngle
  // (150 degrees by default, and at most: see settingsWarning) are read; the rest belongs to
  // surfaceEnergy.
  ContinuumSurfaceForce(SurfaceTensionSettings settings, ParticleCloud& fluid,
                        std::vector<const ParticleCloud*> walls, Neighbourhood& neighbourhood);

  std::string limitName() const override { return "capillary"; }
  std::string summary(double soundSpeed) const override;
  // contactAngle above 150 degrees (imposed as 150)
  std::string settingsWarning(double soundSpeed) const override;
  void addAcceleration() override;
  // The flow sums g_i in its own pair loop into this (the model's colour pass then reads it).
  std::vector<Vector>* colourGradientBuffer() override { return &flowGradient_; }
  // 0.25 sqrt(rho_min dx^3 / (2 pi sigma_max)) (Brackbill, Kothe & Zemach 1992).
  double stableDeltaT() const override;
  double seconds() const override { return seconds_; }

  // The per-particle quantities of the last pass (tests, the log); colour and depth only where
  // |g| is above a tenth of a face's (where i can be on the surface), NaN elsewhere.
  const std::vector<Real>& colour() const { return colour_; }
  const std::vector<Real>& depth() const { return depth_; }
  const std::vector<Vector>& unitNormal() const { return unitNormal_; }
  // g_i over the flat face's bulk colour (1/m)
  const std::vector<Vector>& colourGradient() const { return gradient_; }
  // How many passes took g from the flow's pair loop (colourGradientBuffer), not their own.
  std::size_t passesWithFlowsGradient() const { return passesWithFlowsGradient_; }
  // 1 for the surface particles (a byte each: the passes write them from several threads)
  const std::vector<std::uint8_t>& onSurface() const { return onSurface_; }
  // Computes the colour, normals, curvature and delta of the current positions, no force.
  void computeSurface();

 private:
  template <int Dim>
  void computeColourAndNormal();
  template <int Dim>
  void computeCurvature();

  void turnNormalsAtWalls();

  SurfaceTensionSettings settings_;
  Real cosTheta_, sinTheta_;
  SurfaceDepthProfile profile_;
  Real bulkColour_;       // the kernel's sum over a lattice of spacing dx
  Real surfaceGradient_;  // P(0): the largest colour gradient of a half space (its surface's)
  ParticleCloud& fluid_;
  std::vector<const ParticleCloud*> walls_;
  WallVolumes wallVolumes_;
  Neighbourhood& neighbourhood_;
  // per particle, from the last pass
  std::vector<Real> volume_, tension_, colour_, depth_, kappa_;
  std::vector<Vector> gradient_, unitNormal_;
  std::vector<Vector> flowGradient_;  // -sum_j V_j grad_i W_ij, from the flow's pass (unscaled)
  std::size_t passesWithFlowsGradient_ = 0;
  std::vector<std::uint8_t> onSurface_;
  std::vector<Real> surfaceWeight_;  // 0 off the surface to 1 on it
  double seconds_ = 0;
};

}  // namespace sphcast
