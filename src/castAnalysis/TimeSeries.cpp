#include "castAnalysis/TimeSeries.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "castAnalysis/GnuplotPlot.h"
#include "core/AtomicFile.h"
#include "core/Log.h"
#include "particles/FieldNames.h"
#include "post/CloudSummary.h"

namespace sphcast {

namespace {

// The energy a pouring inlet brought into the cloud (J): part of the books' change.
double inflowEnergy(const ParticleCloud& cloud) {
  const auto inflow = cloud.attributes().find("inflowEnergy");
  return inflow == cloud.attributes().end() ? 0.0 : inflow->second;
}

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

const std::vector<std::string>& columns() {
  static const std::vector<std::string> names{"time",
                                              "particles",
                                              "Tmin",
                                              "Tmean",
                                              "Tmax",
                                              "solidFraction",
                                              "liquid",
                                              "frozen",
                                              "flowing",
                                              "solid",
                                              "densityDeviationMin",
                                              "densityDeviationMax",
                                              "kineticEnergy",
                                              "internalEnergy",
                                              "internalEnergyChange",
                                              "heatLost"};
  return names;
}

std::vector<std::string> cellsOf(const std::string& row) {
  std::vector<std::string> cells;
  std::istringstream stream(row.substr(0, row.find('\n')));
  for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
  return cells;
}

// A CSV cell for the report: 6 significant digits; a quantity the cloud does not have (nan in
// the CSV: a mold's solid fraction, a fixed cloud's kinetic energy) is a dash.
std::string shortNumber(const std::string& cell) {
  char* end = nullptr;
  const double value = std::strtod(cell.c_str(), &end);
  if (end == cell.c_str()) return cell;
  return std::isnan(value) ? "–" : formatNumber(value, 6);
}

int column(const std::string& name) {
  const auto& names = columns();
  return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin()) + 1;
}

}  // namespace

TimeSeries::TimeSeries(const std::string& name, const Dictionary& dict,
                       const AnalysisContext& context)
    : CastAnalysis(name, dict, context, {"clouds"}) {
  clouds_ = dict.getOrDefault<std::vector<std::string>>("clouds", context.clouds);
  for (const std::string& cloud : clouds_) {
    if (std::find(context.clouds.begin(), context.clouds.end(), cloud) == context.clouds.end()) {
      throw DictionaryError(dict.location("clouds"),
                            "no cloud '" + cloud + "' in the time folders, for " + dict.name());
    }
  }
}

std::string TimeSeries::csvHeader() {
  std::string header;
  for (const auto& name : columns()) header += (header.empty() ? "" : ",") + name;
  return header + '\n';
}

std::string TimeSeries::csvRow(double time, const ParticleCloud& cloud) {
  const std::size_t n = cloud.size();
  const auto scalar = [&](const char* name) {
    return cloud.hasScalarField(name) ? &cloud.scalarField(name) : nullptr;
  };
  const auto* mass = scalar(field::mass);
  const auto* T = scalar(field::T);
  const auto* fs = scalar(field::solidFraction);
  const auto* frozen = scalar(field::frozen);
  const auto* rho = scalar(field::rho);
  const auto* rhoS = scalar(field::restDensity);
  const auto* u = scalar(field::u);
  const auto* U = cloud.hasVectorField(field::U) ? &cloud.vectorField(field::U) : nullptr;
  const auto weight = [&](std::size_t i) { return mass ? double((*mass)[i]) : 1.0; };
  double totalMass = 0;
  for (std::size_t i = 0; i < n; ++i) totalMass += weight(i);

  double tMin = nan, tMean = nan, tMax = nan, solid = nan, devMin = nan, devMax = nan;
  double kinetic = nan, internal = nan, change = nan, lost = nan;
  double liquid = nan, frozenCount = nan, flowing = double(n), solidCount = nan;
  if (T && n > 0) {
    tMin = *std::min_element(T->begin(), T->end());
    tMax = *std::max_element(T->begin(), T->end());
    tMean = 0;
    for (std::size_t i = 0; i < n; ++i) tMean += weight(i) * double((*T)[i]) / totalMass;
  }
  if (fs && n > 0) {
    solid = liquid = solidCount = 0;
    for (std::size_t i = 0; i < n; ++i) {
      solid += weight(i) * double((*fs)[i]) / totalMass;
      liquid += (*fs)[i] == 0;
      solidCount += (*fs)[i] == 1;
    }
  }
  if (frozen) {
    frozenCount =
        double(std::count_if(frozen->begin(), frozen->end(), [](Real f) { return f != 0; }));
    flowing = double(n) - frozenCount;
  }
  if (!U) flowing = 0;
  if (rho && rhoS && n > 0) {
    devMin = std::numeric_limits<double>::max();
    devMax = -devMin;
    for (std::size_t i = 0; i < n; ++i) {
      const double d = double((*rho)[i]) / double((*rhoS)[i]) - 1;
      devMin = std::min(devMin, d);
      devMax = std::max(devMax, d);
    }
  }
  if (U && mass) {
    kinetic = 0;
    for (std::size_t i = 0; i < n; ++i) kinetic += 0.5 * weight(i) * double((*U)[i].squaredNorm());
  }
  if (u && mass) {
    internal = 0;
    for (std::size_t i = 0; i < n; ++i) internal += weight(i) * double((*u)[i]);
    lost = 0;
    for (const auto& [key, value] : cloud.attributes()) {
      if (key.rfind("heatLost.", 0) == 0) lost += value;
    }
    if (const auto start = cloud.attributes().find("internalEnergyAtStart");
        start != cloud.attributes().end()) {
      change = internal - start->second - inflowEnergy(cloud);
    }
  }
  char row[768];
  std::snprintf(row, sizeof row,
                "%.17g,%zu,%.10g,%.10g,%.10g,%.10g,%.0f,%.0f,%.0f,%.0f,%.10g,%.10g,%.10g,%.17g,"
                "%.17g,%.17g\n",
                time, n, tMin, tMean, tMax, solid, liquid, frozenCount, flowing, solidCount, devMin,
                devMax, kinetic, internal, change, lost);
  return row;
}

std::string TimeSeries::energyBalanceRow(const WrittenTime& time) {
  double change = 0, lost = 0, scale = 0;
  int clouds = 0;
  for (const ParticleCloud& cloud : time.clouds) {
    const auto start = cloud.attributes().find("internalEnergyAtStart");
    if (start == cloud.attributes().end() || !cloud.hasScalarField(field::u) ||
        !cloud.hasScalarField(field::mass)) {
      continue;
    }
    double internal = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      internal +=
          double(cloud.scalarField(field::mass)[i]) * double(cloud.scalarField(field::u)[i]);
    }
    change += internal - start->second - inflowEnergy(cloud);
    scale += std::abs(start->second) + inflowEnergy(cloud);
    for (const auto& [key, value] : cloud.attributes()) {
      if (key.rfind("heatLost.", 0) == 0) lost += value;
    }
    ++clouds;
  }
  if (clouds == 0) return "";
  char row[256];
  std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,%.10g,%.10g\n", time.folder.value, change, lost,
                change + lost, (change + lost) / scale);
  return row;
}

void TimeSeries::add(const WrittenTime& time) {
  if (const std::string row = energyBalanceRow(time); !row.empty()) {
    if (energy_.empty())
      energy_ = "time,internalEnergyChange,heatLost,imbalance,relativeImbalance\n";
    energy_ += row;
    lastEnergyRow_ = row;
  }
  for (const std::string& name : clouds_) {
    const ParticleCloud* cloud = time.find(name);
    if (!cloud) continue;
    std::string& csv = csv_[name];
    if (csv.empty()) csv = csvHeader();
    lastRow_[name] = csvRow(time.folder.value, *cloud);
    csv += lastRow_[name];
    spill_[name] = spillLine(time.folder.value, *cloud);
    if (spill_[name].empty()) spill_.erase(name);
  }
}

// The metal a flow spilled out of its domain by `time` (solver/MetalSpill.h), as a sentence;
// empty for a cloud no flow moved (it carries no domain).
std::string TimeSeries::spillLine(double time, const ParticleCloud& cloud) {
  const auto& attributes = cloud.attributes();
  if (!attributes.contains("domain.lower.x")) return "";
  std::ostringstream line;
  line.precision(4);
  const auto spilled = attributes.find("spilledMass");
  if (spilled == attributes.end() || !(spilled->second > 0)) {
    line << "No metal of " << cloud.name() << " left the domain by " << time << " s.\n";
    return line.str();
  }
  double held = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    held += static_cast<double>(cloud.scalarField(field::mass)[i]);
  }
  const auto heat = attributes.find("heatLost.spilled");
  line << "**Metal spilled**: by " << time << " s " << attributes.at("spilledParticles")
       << " particles of " << cloud.name() << " left the domain, " << spilled->second << " kg ("
       << 100 * spilled->second / (held + spilled->second) << " % of the metal)";
  if (heat != attributes.end()) line << ", carrying " << heat->second << " J of heat";
  line << "; the log names where (\"spilled\").\n";
  return line.str();
}

ReportSection TimeSeries::finish() {
  const auto out = folder();
  for (const auto& [cloud, csv] : csv_) writeRowsByTime(cloud + ".csv", csv);
  if (!energy_.empty()) writeRowsByTime("energyBalance.csv", energy_);
  // one plot per quantity, every cloud in it
  struct Figure {
    const char* file;
    const char* title;
    const char* yLabel;
    std::vector<const char*> columns;
  };
  const std::vector<Figure> figures{
      {"temperature", "Temperature", "T (K)", {"Tmin", "Tmean", "Tmax"}},
      {"solidFraction", "Solid fraction (by mass)", "f_s", {"solidFraction"}},
      {"particles", "Particles", "count", {"liquid", "frozen", "flowing", "solid"}},
      {"density",
       "Density deviation",
       "rho / rho_s - 1",
       {"densityDeviationMin", "densityDeviationMax"}},
      {"kineticEnergy", "Kinetic energy", "J", {"kineticEnergy"}},
      {"internalEnergy", "Change of internal energy", "J", {"internalEnergyChange"}}};
  ReportSection section;
  for (const Figure& figure : figures) {
    // a cloud whose rows are all nan in these columns is left out of the plot
    for (const auto& [cloud, rows] : csv_) {
      const auto cells = cellsOf(lastRow_[cloud]);
      const bool any = std::any_of(figure.columns.begin(), figure.columns.end(),
                                   [&](const char* c) { return cells[column(c) - 1] != "nan"; });
      if (!any) continue;
      Plot plot;
      plot.title = std::string(figure.title) + " of " + cloud;
      plot.yLabel = figure.yLabel;
      plot.csv = out / (cloud + ".csv");
      for (const char* c : figure.columns) plot.series.push_back({column(c), c});
      const std::string png = std::string(figure.file) + "_" + cloud + ".png";
      if (drawPlot(plot, out / png)) section.images.push_back(name_ + "/" + png);
    }
  }
  // the report: the last row of each cloud
  std::ostringstream text;
  text << "| cloud | time (s) | T min / mean / max (K) | solid fraction | frozen / flowing | "
          "kinetic energy (J) | internal energy change (J) |\n|---|---|---|---|---|---|---|\n";
  for (const auto& [cloud, row] : lastRow_) {
    const auto cells = cellsOf(row);
    const auto cell = [&](const char* c) { return shortNumber(cells[column(c) - 1]); };
    text << "| " << cloud << " | " << cell("time") << " | " << cell("Tmin") << " / "
         << cell("Tmean") << " / " << cell("Tmax") << " | " << cell("solidFraction") << " | "
         << cell("frozen") << " / " << cell("flowing") << " | " << cell("kineticEnergy") << " | "
         << cell("internalEnergyChange") << " |\n";
  }
  text << "\n(–: the cloud has no such quantity, e.g. a mold's solid fraction.)\n";
  for (const auto& [cloud, line] : spill_) text << '\n' << line;
  if (!lastEnergyRow_.empty()) {
    const auto cells = cellsOf(lastEnergyRow_);
    text << "\nHeat books of every heat cloud at " << shortNumber(cells[0])
         << " s: internal energy changed by " << shortNumber(cells[1]) << " J, "
         << shortNumber(cells[2])
         << " J left through the held surfaces, the air, radiation and spilled metal; imbalance "
         << shortNumber(cells[3]) << " J (" << shortNumber(cells[4])
         << " of the start's heat content; energyBalance.csv).\n";
    Plot plot;
    plot.title = "Energy imbalance of the heat clouds (change + lost)";
    plot.yLabel = "J";
    plot.csv = out / "energyBalance.csv";
    plot.series = {{4, "imbalance"}};
    if (drawPlot(plot, out / "energyBalance.png")) {
      section.images.push_back(name_ + "/energyBalance.png");
    }
  }
  section.markdown = text.str();
  return section;
}

}  // namespace sphcast
