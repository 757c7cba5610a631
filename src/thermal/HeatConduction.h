#pragma once

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "thermal/GradedConduction.h"
#include "thermal/HeatTransferModel.h"

namespace sphcast {

// Heat conduction within and between the heat clouds, eq. (13) of the paper in the form of
// Cleary & Monaghan (1999, J. Comput. Phys. 148:227):
//
//   du_i/dt = 1/rho_i sum_j V_j 4 kappa_i kappa_j / (kappa_i + kappa_j) (T_i - T_j) F_ij,
//   F_ij = (x_ij . grad_i W_ij) / (|x_ij|^2 + eta^2),   eta^2 = 0.01 dx^2,
//
// V_j = m_j / rho_j. Within one material it is taken through the Kirchhoff transform
// phi(T) = int kappa dT (TemperatureTable::integral):
//
//   du_i/dt = 1/rho_i sum_j V_j 2 (phi_i - phi_j) F_ij,
//
// the conductivity averaged over the pair's temperature interval, (phi_i - phi_j) / (T_i - T_j),
// the same as 2 kappa (T_i - T_j) for a constant kappa and exact for steady conduction along the
// pair. The harmonic mean of the two particles' kappa puts a jump of kappa (a freezing front:
// AC4CH's 175 to 85 W/m/K across its 58 K mushy range, narrower than a spacing beside a chill)
// midway between them, for pairs up to h apart: an error first order in h (Chvorinov's plates at
// dx = 1 mm: the 10 mm plate 9.6 % late, n = 1.951; 3.2 % and 1.985 with the transform).
// Between two materials the harmonic mean stays.
// The printed (13) lacks the factor x_ij / (|x_ij|^2 + eta^2) that turns the kernel gradient
// into a second derivative; without it the sum is not a Laplacian (doc/physics.md §10.2.1).
// The harmonic mean of the conductivities keeps the flux continuous across a jump of kappa
// (metal against mold). The pair term is antisymmetric: heat moves between particles,
// sum_i m_i du_i/dt = 0 to round-off.
//
// A held particle of a mold with a surface (particleizeMold's `normal` and `wallDistance`, its
// depth d_k behind the surface) stands for the surface held at its T, not for a particle at T:
// the free particle f in front of it, at d_f, sees the temperature extended linearly through the
// surface, T_k' = T_k - (T_f - T_k) d_k / d_f, and conducts with its own kappa on both sides:
//   (T_f - T_k') = (1 + d_k / d_f) (T_f - T_k),
//   4 kappa_f kappa_k / (kappa_f + kappa_k) -> 2 kappa_f
// (as the flow's no-slip wall extends the velocity, Morris, Fox & Zhu 1997), so the held surface
// lies where the mold's surface is. Without it a held surface lay on the first held layer's
// centres, half a spacing behind particleizeMold's wall, and further back for the layers behind
// (doc/physics.md §10.2.1). A held cloud without those fields (a box of setCastFields) gets them
// at the start: its surface midway between its particles and the free particles it holds
// against (placeHeldSurface). The pair stays antisymmetric: what the surface takes in is what
// the free particle gives up.
// A mold with a surface that conducts (not held) meets another cloud's particle f across its
// wall: the pair takes the two conductivities in series over its two sides of the wall, d_f in
// front and d_k behind, kappa = kappa_f kappa_k (d_f + d_k) / (d_f kappa_k + d_k kappa_f), where
// the harmonic mean would put the jump of kappa midway between the particles (the same where
// d_f = d_k). Measured, aluminium on iron: the contact temperature 0.26 % off against 0.99 %.
//
// Within a mold particleized at graded spacing (the field localSpacing), the pairs and their
// kernels are GradedConduction's: each pair's own support, corrected so that a linear profile
// is exact across a change of spacing (made again where a decomposed run moved its particles).
//
// Between two clouds whose materials have a contact coefficient (moldContact), this model
// leaves the exchange to MoldContactTransfer: the coefficient is the interface's conductance.
//
// Step limit: the diffusion number, dt <= maxDi dx^2 / alpha_max (controlDict, default 0.1),
// alpha = kappa / (rho c) with c = du/dT, the largest over each material's tables. Forward Euler
// on this Laplacian is stable below 0.65 dx^2 / alpha on a lattice with h = 3 dx (its largest
// eigenvalue, 3.06 alpha / dx^2, is that of the mode alternating along the diagonal).
class HeatConduction : public HeatTransferModel {
 public:
  // contactPairs: material pairs (both orders) whose exchange is MoldContactTransfer's.
  HeatConduction(const HeatTransferContext& context,
                 std::set<std::pair<std::string, std::string>> contactPairs);

  const char* name() const override { return "conduction"; }
  std::string description() const override;
  // Gives each held cloud without a surface (normal, wallDistance) one from the start state:
  // placeHeldSurface.
  std::string start() override;
  void addEnergyRates() override;
  double stableDeltaT() const override { return stableDeltaT_; }

  // The largest kappa / (rho du/dT) of a material over its tables (m^2/s).
  static double largestDiffusivity(const Material& material);

 private:
  template <int Dim>
  void addRatesIn();
  template <int Dim>
  std::size_t placeHeldSurface(std::size_t cloud);
  bool conducts(std::size_t a, std::size_t b) const;
  bool graded(std::size_t a) const;
  std::string buildGradedPairs();

  const HeatTransferContext& context_;
  std::set<std::pair<std::string, std::string>> contactPairs_;
  std::vector<std::vector<Real>> volumes_;    // m / rho of each cloud, refreshed every pass
  std::vector<std::vector<Real>> kirchhoff_;  // phi(T) of each cloud, refreshed every pass
  std::vector<std::unique_ptr<GradedConduction>> graded_;  // per cloud: null unless graded
  std::vector<std::uint64_t> gradedLayouts_;  // the clouds' layoutVersion at graded_'s build
  double stableDeltaT_;
};

}  // namespace sphcast
