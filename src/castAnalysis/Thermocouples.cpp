#include "castAnalysis/Thermocouples.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "castAnalysis/CoolingCurve.h"
#include "castAnalysis/GnuplotPlot.h"
#include "core/AtomicFile.h"
#include "core/Log.h"
#include "particles/FieldNames.h"
#include "post/FluidSampling.h"
#include "post/FunctionObject.h"

namespace sphcast {

Thermocouples::Thermocouples(const std::string& name, const Dictionary& dict,
                             const AnalysisContext& context)
    : CastAnalysis(name, dict, context, {"cloud", "locations", "probes", "supportRadius"}) {
  cloud_ = readCloud();
  const FreezingRange& range =
      materialOf(cloud_, "thermocouples").requireFreezingRange("thermocouples (" + name + ")");
  liquidus_ = range.liquidus;
  solidus_ = range.solidus;
  if (dict.found("locations") == dict.found("probes")) {
    throw DictionaryError(dict.location(),
                          dict.name() +
                              " needs either 'locations' { name "
                              "(x y z); ... } or 'probes' <function object>, not " +
                              std::string(dict.found("probes") ? "both" : "neither"));
  }
  if (dict.found("probes")) {
    probes_ = dict.get<std::string>("probes");
    const auto rows = readFunctionObjectSeries(context.caseRoot, probes_, "T");
    if (rows.empty()) {
      throw DictionaryError(dict.location("probes"),
                            "no rows of T from function object '" + probes_ + "' under " +
                                (context.caseRoot / "postProcessing" / probes_).string() +
                                ": it must be a probes function object with fields (T) that "
                                "has run");
    }
    for (std::size_t k = 1; k < rows.front().size(); ++k) {
      names_.push_back("probe" + std::to_string(k - 1));
    }
    temperatures_.resize(names_.size());
    for (const auto& row : rows) {
      times_.push_back(row[0]);
      for (std::size_t k = 0; k < names_.size(); ++k) {
        temperatures_[k].push_back(k + 1 < row.size() ? row[k + 1] : noFluid);
      }
    }
    return;
  }
  const Dictionary& locations = dict.subDict("locations");
  for (const std::string& key : locations.keys()) {
    names_.push_back(key);
    locations_.push_back(locations.get<Vector>(key));
  }
  if (names_.empty()) {
    throw DictionaryError(dict.location("locations"),
                          "'locations' names no thermocouple in " + dict.name());
  }
  supportRadius_ = dict.getOrDefault<Real>("supportRadius", context.supportRadius);
  if (!(supportRadius_ > 0)) {
    throw DictionaryError(dict.location(), dict.name() +
                                               " needs 'supportRadius' (m): the case "
                                               "has no system/sphSchemes to take h from");
  }
  temperatures_.resize(names_.size());
}

void Thermocouples::add(const WrittenTime& time) {
  if (!probes_.empty()) return;  // the function object's rows are read already
  const ParticleCloud* cloud = time.find(cloud_);
  if (!cloud || !cloud->hasScalarField(field::T)) return;
  const ShepardInterpolation interpolation(*cloud, supportRadius_);
  times_.push_back(time.folder.value);
  for (std::size_t k = 0; k < names_.size(); ++k) {
    const double T = interpolation.scalar(cloud->scalarField(field::T), locations_[k]);
    if (!checked_ && !std::isfinite(T)) {
      const Dictionary& locations = dict_.subDict("locations");
      std::ostringstream message;
      message << "thermocouple '" << names_[k] << "' of " << dict_.name()
              << " lies outside the casting: no particle of cloud '" << cloud_
              << "' within h = " << supportRadius_ << " m of it at time " << time.folder.name;
      throw DictionaryError(locations.location(names_[k]), message.str());
    }
    temperatures_[k].push_back(T);
  }
  checked_ = true;
}

ReportSection Thermocouples::finish() {
  const auto out = folder();
  std::string csv = "time";
  for (const auto& name : names_) csv += "," + name;
  csv += '\n';
  for (std::size_t r = 0; r < times_.size(); ++r) {
    csv += formatNumber(times_[r], 12);
    for (const auto& curve : temperatures_) csv += "," + formatNumber(curve[r], 10);
    csv += '\n';
  }
  writeFileAtomically(out / "temperature.csv", csv);

  std::ostringstream breaks, report;
  breaks << "thermocouple,liquidusTime,solidusTime,localFreezingTime,arrestTime,"
            "arrestTemperature,endTime,endTemperature\n";
  report << "| thermocouple | reaches liquidus / solidus (s) | local freezing time (s) | "
            "slope breaks (K) |\n|---|---|---|---|\n";
  for (std::size_t k = 0; k < names_.size(); ++k) {
    const double liquidusTime = firstTimeAtOrBelow(times_, temperatures_[k], liquidus_);
    const double solidusTime = firstTimeAtOrBelow(times_, temperatures_[k], solidus_);
    const CoolingCurveBreaks found = findCoolingCurveBreaks(times_, temperatures_[k]);
    const double nan = std::nan("");
    const auto at = [&](const CoolingCurveBreak& b, bool temperature) {
      return !b.found ? nan : temperature ? b.temperature : b.time;
    };
    breaks << names_[k] << ',' << formatNumber(liquidusTime, 10) << ','
           << formatNumber(solidusTime, 10) << ',' << formatNumber(solidusTime - liquidusTime, 10)
           << ',' << formatNumber(at(found.arrest, false), 10) << ','
           << formatNumber(at(found.arrest, true), 10) << ','
           << formatNumber(at(found.end, false), 10) << ',' << formatNumber(at(found.end, true), 10)
           << '\n';
    report << "| " << names_[k] << " | " << formatNumber(liquidusTime, 4) << " / "
           << formatNumber(solidusTime, 4) << " | " << formatNumber(solidusTime - liquidusTime, 4)
           << " | " << formatNumber(at(found.arrest, true), 5) << " / "
           << formatNumber(at(found.end, true), 5) << " |\n";
  }
  writeFileAtomically(out / "breaks.csv", breaks.str());
  report << "\nLiquidus " << liquidus_ << " K, solidus " << solidus_ << " K; "
         << (probes_.empty() ? "sampled at the written times"
                             : "sampled every step by function object " + probes_)
         << ".\n";
  info() << "    " << name_ << ": wrote " << (out / "temperature.csv").string() << " and "
         << (out / "breaks.csv").string() << '\n';

  Plot plot;
  plot.title = "Cooling curves (" + cloud_ + ")";
  plot.yLabel = "T (K)";
  plot.csv = out / "temperature.csv";
  for (std::size_t k = 0; k < names_.size(); ++k) {
    plot.series.push_back({static_cast<int>(k) + 2, names_[k]});
  }
  plot.levels = {{liquidus_, "liquidus"}, {solidus_, "solidus"}};
  ReportSection section;
  section.markdown = report.str();
  if (drawPlot(plot, out / "coolingCurves.png")) {
    section.images.push_back(name_ + "/coolingCurves.png");
  }
  return section;
}

}  // namespace sphcast
