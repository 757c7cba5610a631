#include "castAnalysis/SolidificationMaps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "castAnalysis/TemperatureGradient.h"
#include "core/Log.h"
#include "io/PvdIndex.h"
#include "io/VtpCloud.h"
#include "particles/FieldNames.h"
#include "solidification/Solidification.h"

namespace sphcast {

SolidificationMaps::SolidificationMaps(const std::string& name, const Dictionary& dict,
                                       const AnalysisContext& context)
    : CastAnalysis(name, dict, context,
                   {"cloud", "fillEnd", "criticalPressureDrop", "niyamaThreshold"}) {
  cloud_ = readCloud();
  materialOf(cloud_, "solidificationMaps").requireFreezingRange("solidificationMaps");
  fillEndGiven_ = dict.found("fillEnd");
  fillEnd_ = dict.getOrDefault<double>("fillEnd", 0);
  criticalPressureDrop_ = dict.getOrDefault<double>("criticalPressureDrop", 1.01e5);
  niyamaThreshold_ = dict.getOrDefault<double>("niyamaThreshold", 1.0);
  for (const char* key : {"criticalPressureDrop", "niyamaThreshold"}) {
    if (dict.found(key) && !(dict.get<double>(key) > 0)) {
      throw DictionaryError(dict.location(key),
                            "'" + std::string(key) + "' must be positive in " + dict.name());
    }
  }
  if (context.supportRadius <= 0) {
    throw DictionaryError(dict.location(), dict.name() +
                                               " needs h (supportRadius of "
                                               "system/sphSchemes) for grad T");
  }
}

bool SolidificationMaps::hasHistory(const ParticleCloud& cloud) {
  static const std::vector<std::string> fields{field::liquidusTime, field::criticalTime,
                                               field::coolingRate, field::solidusTime};
  return cloud.hasIdField(field::id) &&
         std::all_of(fields.begin(), fields.end(),
                     [&](const std::string& field) { return cloud.hasScalarField(field); });
}

void SolidificationMaps::add(const WrittenTime& time) {
  const ParticleCloud* cloud = time.find(cloud_);
  if (!cloud || !cloud->hasScalarField(field::T) || !cloud->hasIdField(field::id)) return;
  // a time written before the solver ran (setCastFields' 0) has T but no history yet
  const bool history = hasHistory(*cloud);
  const double t = time.folder.value;
  const auto& ids = cloud->idField(field::id);
  const std::vector<Vector> gradient =
      temperatureGradient(*cloud, context_.supportRadius, context_.dimension);
  std::unordered_map<std::int64_t, double> now;
  now.reserve(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const double G = static_cast<double>(gradient[i].norm());
    now[ids[i]] = G;
    if (!history) continue;
    const double tc = cloud->scalarField(field::criticalTime)[i];
    if (tc < 0) {
      criticalGradient_.erase(ids[i]);  // not yet, or melted again since
      continue;
    }
    if (criticalGradient_.contains(ids[i])) continue;
    const auto before = previousGradient_.find(ids[i]);
    if (before != previousGradient_.end() && previousTime_ < t) {
      const double f = std::clamp((tc - previousTime_) / (t - previousTime_), 0.0, 1.0);
      criticalGradient_[ids[i]] = (1 - f) * before->second + f * G;
    } else {
      criticalGradient_[ids[i]] = G;  // crossed before the first selected time
    }
  }
  previousGradient_ = std::move(now);
  previousTime_ = t;
  if (!fillEndTaken_ && (!fillEndGiven_ || t >= fillEnd_)) {
    const auto& T = cloud->scalarField(field::T);
    const Material& material = materialOf(cloud_, "solidificationMaps");
    for (std::size_t i = 0; i < ids.size(); ++i) {
      fillEndTemperature_[ids[i]] = T[i];
      fillEndSolidFraction_[ids[i]] = solidFraction(material, T[i]);
    }
    fillEndTaken_ = true;
  }
  last_ = *cloud;
  lastTimeName_ = time.folder.name;
  lastTime_ = t;
}

ReportSection SolidificationMaps::finish() {
  ReportSection section;
  if (lastTimeName_.empty()) {
    section.markdown = "No selected time holds cloud " + cloud_ + ".\n";
    return section;
  }
  if (!hasHistory(last_)) {
    throw DictionaryError(dict_.location("cloud"),
                          "cloud '" + cloud_ + "' at time " + lastTimeName_ +
                              " has no solidification history (liquidusTime, criticalTime, "
                              "coolingRate, solidusTime): " +
                              dict_.name() +
                              " maps what the solver records; run with solidification { model "
                              "frozenSolid; } in constant/physicsModels");
  }
  const Material& material = materialOf(cloud_, "solidificationMaps");
  const FreezingRange& range = *material.freezingRange;
  const std::size_t n = last_.size();
  ParticleCloud maps(cloud_);
  maps.resize(n);
  maps.positions() = last_.positions();
  maps.addIdField(field::id) = last_.idField(field::id);
  if (last_.attributes().contains("spacing")) {
    maps.attributes()["spacing"] = last_.attributes().at("spacing");
  }
  auto& solidification = maps.addScalarField(field::solidificationTime);
  auto& freezing = maps.addScalarField(field::localFreezingTime);
  auto& rate = maps.addScalarField(field::coolingRate);
  auto& gradient = maps.addScalarField(field::temperatureGradient);
  auto& niyama = maps.addScalarField(field::niyama);
  // the solver's first wall contact of each particle (sph/FillTime.h), when the run has a flow
  if (last_.hasScalarField(field::fillTime))
    maps.addScalarField(field::fillTime) = last_.scalarField(field::fillTime);
  auto& fillT = maps.addScalarField(field::temperatureAtFillEnd);
  auto& fillFs = maps.addScalarField(field::solidFractionAtFillEnd);
  const auto& ids = last_.idField(field::id);
  const auto& liquidusTime = last_.scalarField(field::liquidusTime);
  const auto& solidusTime = last_.scalarField(field::solidusTime);
  const auto& coolingRate = last_.scalarField(field::coolingRate);
  const auto& criticalTime = last_.scalarField(field::criticalTime);
  auto& resolved = maps.addScalarField(field::mushyZoneSpacings);
  const double freezingRange = range.liquidus - range.solidus;
  const double dx = last_.attributes().contains("spacing") ? last_.attributes().at("spacing") : 0.0;
  std::size_t underResolved = 0;
  const ParticleCloud::ScalarField* solverGradient =
      last_.hasScalarField(field::criticalGradient) ? &last_.scalarField(field::criticalGradient)
                                                    : nullptr;
  std::size_t fromSolver = 0;
  for (std::size_t i = 0; i < n; ++i) {
    solidification[i] = solidusTime[i];
    freezing[i] =
        solidusTime[i] >= 0 && liquidusTime[i] >= 0 ? solidusTime[i] - liquidusTime[i] : Real(-1);
    rate[i] = criticalTime[i] >= 0 ? coolingRate[i] : Real(-1);
    // the solver's G at the crossing where it wrote one, else the writes' interpolated
    const auto G = criticalGradient_.find(ids[i]);
    if (solverGradient && (*solverGradient)[i] >= 0) {
      gradient[i] = (*solverGradient)[i];
      ++fromSolver;
    } else {
      gradient[i] = G != criticalGradient_.end() ? Real(G->second) : Real(-1);
    }
    niyama[i] = gradient[i] >= 0 && rate[i] > 0
                    ? Real(gradient[i] / 1000 / std::sqrt(double(rate[i])))
                    : Real(-1);
    // how many spacings the freezing range spans at T_c: below one the cooling rate there is
    // smoothed by the neighbours (tutorials/validation/chvorinovPlates), Niyama too high
    resolved[i] =
        gradient[i] > 0 && dx > 0 ? Real(freezingRange / (double(gradient[i]) * dx)) : Real(-1);
    if (resolved[i] >= 0 && resolved[i] < 1) ++underResolved;
    const auto T = fillEndTemperature_.find(ids[i]);
    fillT[i] = T != fillEndTemperature_.end() ? Real(T->second) : Real(-1);
    const auto fs = fillEndSolidFraction_.find(ids[i]);
    fillFs[i] = fs != fillEndSolidFraction_.end() ? Real(fs->second) : Real(-1);
  }
  std::ostringstream text;
  if (material.dendriteArmSpacing) {
    const auto [A, exponent] = *material.dendriteArmSpacing;
    const double muLiquid = material.requireViscosity("dimensionlessNiyama")(range.liquidus);
    const TemperatureTable& density = material.requireDensity("dimensionlessNiyama");
    const double beta = density(range.solidus) / density(range.liquidus) - 1;
    const double deltaTf = range.liquidus - range.solidus;
    auto& spacing = maps.addScalarField(field::secondaryArmSpacing);
    auto& dimensionless = maps.addScalarField(field::dimensionlessNiyama);
    for (std::size_t i = 0; i < n; ++i) {
      spacing[i] = freezing[i] > 0 ? Real(A * std::pow(double(freezing[i]), exponent)) : Real(-1);
      dimensionless[i] = spacing[i] > 0 && niyama[i] >= 0 && beta > 0
                             ? Real(double(spacing[i]) * double(gradient[i]) *
                                    std::sqrt(criticalPressureDrop_ /
                                              (muLiquid * beta * deltaTf * double(rate[i]))))
                             : Real(-1);
    }
    text << "Secondary dendrite arm spacing lambda_2 = " << A << " t_f^" << exponent
         << " m; dimensionless Niyama with mu_l = " << formatNumber(muLiquid, 4)
         << " Pa s, beta = " << formatNumber(beta, 4) << ", dT_f = " << formatNumber(deltaTf, 4)
         << " K, dP_cr = " << formatNumber(criticalPressureDrop_, 4) << " Pa.\n\n";
  } else {
    text << "No secondary arm spacing or dimensionless Niyama: material " << material.name
         << " gives no dendriteArmSpacing (A n).\n\n";
  }
  const auto folderOfTime = folder() / lastTimeName_;
  std::filesystem::create_directories(folderOfTime);
  writeCloudVtp(maps, folderOfTime / (cloud_ + ".vtp"));
  writePvd(folder() / (name_ + ".pvd"),
           {PvdEntry{lastTime_, lastTimeName_, cloud_, lastTimeName_ + "/" + cloud_ + ".vtp"}});
  info() << "    " << name_ << ": wrote " << (folderOfTime / (cloud_ + ".vtp")).string() << '\n';

  // the report: extremes and where
  std::size_t solidCount = 0, lastSolid = n, worstNiyama = n, belowThreshold = 0, mapped = 0;
  double freezingMin = std::numeric_limits<double>::max(), freezingMax = -1;
  for (std::size_t i = 0; i < n; ++i) {
    if (solidification[i] >= 0) {
      ++solidCount;
      if (lastSolid == n || solidification[i] > solidification[lastSolid]) lastSolid = i;
      freezingMin = std::min(freezingMin, double(freezing[i]));
      freezingMax = std::max(freezingMax, double(freezing[i]));
    }
    if (niyama[i] >= 0) {
      ++mapped;
      if (worstNiyama == n || niyama[i] < niyama[worstNiyama]) worstNiyama = i;
      if (niyama[i] < niyamaThreshold_) ++belowThreshold;
    }
  }
  text << "At time " << lastTimeName_ << ": " << solidCount << " of " << n
       << " particles have reached the solidus.\n\n";
  if (lastSolid < n) {
    text << "- Last to solidify: " << formatPoint(last_.positions()[lastSolid]) << " at "
         << formatNumber(solidification[lastSolid], 5) << " s"
         << (solidCount < n ? " (of those solid so far)" : "") << ".\n"
         << "- Local freezing time: " << formatNumber(freezingMin, 4) << " to "
         << formatNumber(freezingMax, 4) << " s.\n";
  }
  if (worstNiyama < n) {
    text << "- Niyama minimum: " << formatNumber(niyama[worstNiyama], 4) << " (K s)^0.5/mm at "
         << formatPoint(last_.positions()[worstNiyama]) << " (G "
         << formatNumber(gradient[worstNiyama], 4) << " K/m, cooling "
         << formatNumber(rate[worstNiyama], 4) << " K/s); " << belowThreshold << " of " << mapped
         << " particles below " << niyamaThreshold_ << " (K s)^0.5/mm.\n";
    text << "- " << underResolved << " of " << mapped
         << " particles passed T_c where the freezing range was thinner than a spacing "
            "(mushyZoneSpacings < 1): their cooling rates read low and their Niyama values "
            "high; refine there.\n";
  }
  text << "- T_c = " << formatNumber(criticalTemperature(range), 6)
       << " K; crossing times, cooling rates and G (" << fromSolver << " of " << n
       << " particles) from the heat step that crossed it"
       << (fromSolver < n ? "; the other G from the written times, interpolated in time" : "")
       << ".\n";
  section.markdown = text.str();
  return section;
}

}  // namespace sphcast
