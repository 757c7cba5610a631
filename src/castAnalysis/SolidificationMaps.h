#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "castAnalysis/CastAnalysis.h"

namespace sphcast {

// type solidificationMaps: what each particle of the casting went through, as maps on the metal
// particles at the last selected time (postProcessing/<name>/<time>/<cloud>.vtp, listed in
// postProcessing/<name>/<name>.pvd so ParaView opens them beside <case>.pvd):
//
//   solidificationTime    s, when it reached the solidus (-1: not yet)
//   localFreezingTime     s, liquidus to solidus (-1: not yet)
//   coolingRate           K/s, -dT/dt at T_c = T_sol + 0.1 (T_liq - T_sol)
//   temperatureGradient   K/m, G = |grad T| at T_c: the solver's (criticalGradient), else
//                         from the written times (below)
//   niyama                (K s)^0.5 / mm, G / sqrt(coolingRate) (Niyama et al. 1982)
//   mushyZoneSpacings     (T_liq - T_sol) / (G dx): the spacings the freezing range spans at
//                         T_c; below 1 the cooling rate there is smoothed (Niyama too high)
//   secondaryArmSpacing   m, lambda_2 = A t_f^n (the material's dendriteArmSpacing, if given)
//   dimensionlessNiyama   lambda_2 G sqrt(dP_cr / (mu_l beta dT_f Tdot)) (Carlson & Beckermann
//                         2009, Metall. Mater. Trans. A 40:163): mu_l = mu(T_liq), beta =
//                         rho_s(T_sol) / rho_s(T_liq) - 1, dT_f = T_liq - T_sol, dP_cr the
//                         entry criticalPressureDrop (1.01e5 Pa by default); with lambda_2 only
//   fillTime              s, when the particle first touched the mold (-1: never; recorded by
//                         the solver at every step, sph/FillTime.h; only with a flow)
//   temperatureAtFillEnd, solidFractionAtFillEnd   at the first written time >= fillEnd (f_s from
//                         the material's u(T), as the solver computes it)
//                         (key, s; the first time by default: a case started filled)
//
// The crossing times, the cooling rate and G are the solver's (solidification/Solidification.h
// records them at the heat step that crossed). For a run without criticalGradient (written
// before it existed) G comes from the written times: at each, grad T of the cloud, interpolated
// linearly in time to each particle's crossing of T_c between the two writes around it
// (particles are followed by id): as good as the write interval lets a linear interpolation be
// (towards the start's uniform T, zero, for what crosses in the first interval).
// Keys: cloud; fillEnd, criticalPressureDrop, niyamaThreshold (optional; (K s)^0.5 / mm, 1 by
// default: the report counts the volume below it).
class SolidificationMaps : public CastAnalysis {
 public:
  SolidificationMaps(const std::string& name, const Dictionary& dict,
                     const AnalysisContext& context);

  void add(const WrittenTime& time) override;
  ReportSection finish() override;

 private:
  static bool hasHistory(const ParticleCloud& cloud);

  std::string cloud_;
  double fillEnd_ = 0;
  bool fillEndGiven_ = false;
  double criticalPressureDrop_ = 1.01e5;
  double niyamaThreshold_ = 1.0;
  // per particle id
  std::unordered_map<std::int64_t, double> previousGradient_, criticalGradient_;
  std::unordered_map<std::int64_t, double> fillEndTemperature_, fillEndSolidFraction_;
  double previousTime_ = -1;
  bool fillEndTaken_ = false;
  ParticleCloud last_{"last"};
  std::string lastTimeName_;
  double lastTime_ = 0;
};

}  // namespace sphcast
