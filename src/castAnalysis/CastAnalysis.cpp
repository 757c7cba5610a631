#include "castAnalysis/CastAnalysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "castAnalysis/BodyMotion.h"
#include "castAnalysis/CastingView.h"
#include "castAnalysis/CloudSummaryAnalysis.h"
#include "castAnalysis/HotSpots.h"
#include "castAnalysis/ShrinkageCavities.h"
#include "castAnalysis/Slice.h"
#include "castAnalysis/SolidificationMaps.h"
#include "castAnalysis/Thermocouples.h"
#include "castAnalysis/TimeSeries.h"
#include "core/AtomicFile.h"
#include "core/Log.h"
#include "core/dictionary/SourceLocation.h"
#include "io/VtpCloud.h"
#include "particles/FieldNames.h"
#include "post/CloudSummary.h"

namespace sphcast {

const ParticleCloud* WrittenTime::find(const std::string& cloudName) const {
  for (const ParticleCloud& cloud : clouds) {
    if (cloud.name() == cloudName) return &cloud;
  }
  return nullptr;
}

CastAnalysis::CastAnalysis(const std::string& name, const Dictionary& dict,
                           const AnalysisContext& context, const std::vector<std::string>& keys)
    : name_(name), type_(dict.get<std::string>("type")), dict_(dict), context_(context) {
  std::vector<std::string> valid = keys;
  valid.push_back("type");
  dict.checkKeys(valid);
}

std::filesystem::path CastAnalysis::folder() const {
  const auto path = context_.caseRoot / "postProcessing" / name_;
  std::filesystem::create_directories(path);
  return path;
}

void CastAnalysis::writeRowsByTime(const std::string& fileName, const std::string& csv) const {
  const auto file = folder() / fileName;
  std::string content = csv;
  if (!context_.allTimes && std::filesystem::exists(file)) {
    std::ostringstream existing;
    existing << std::ifstream(file).rdbuf();
    content = mergeCloudSummaryCsv(existing.str(), csv);
  }
  writeFileAtomically(file, content);
  info() << "    " << name_ << ": wrote " << file.string() << '\n';
}

std::string CastAnalysis::readCloud(const std::string& key) const {
  const auto cloud = dict_.get<std::string>(key);
  const auto& clouds = context_.clouds;
  if (std::find(clouds.begin(), clouds.end(), cloud) == clouds.end()) {
    std::string list;
    for (const auto& known : clouds) list += (list.empty() ? "" : " ") + known;
    throw DictionaryError(dict_.location(key), "no cloud '" + cloud + "' in the time folders of " +
                                                   context_.caseRoot.string() + " for " +
                                                   dict_.name() + "; they hold (" + list + ")");
  }
  return cloud;
}

const Material& CastAnalysis::materialOf(const std::string& cloud,
                                         const std::string& neededBy) const {
  const auto found = context_.materials.find(cloud);
  if (found == context_.materials.end()) {
    throw DictionaryError(dict_.location("cloud"),
                          "cloud '" + cloud + "' has no material, which " + neededBy + " of " +
                              dict_.name() +
                              " needs: it must be a heatTransfer cloud of constant/physicsModels");
  }
  return found->second;
}

const ParticleCloud* CastAnalysis::cloudAt(const WrittenTime& time, const std::string& cloudName) {
  if (const ParticleCloud* cloud = time.find(cloudName)) return cloud;
  if (const auto found = constantClouds_.find(cloudName); found != constantClouds_.end()) {
    return &found->second;
  }
  const auto file = context_.caseRoot / "constant" / "particles" / (cloudName + ".vtp");
  if (!std::filesystem::exists(file)) return nullptr;
  return &constantClouds_.emplace(cloudName, readCloudVtp(file, cloudName)).first->second;
}

std::vector<std::string> CastAnalysis::constantCloudNames() const {
  std::vector<std::string> names;
  const auto folder = context_.caseRoot / "constant" / "particles";
  if (std::filesystem::exists(folder)) {
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      if (entry.path().extension() == ".vtp") names.push_back(entry.path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> CastAnalysis::cloudsAt(const WrittenTime& time) const {
  std::vector<std::string> names;
  for (const ParticleCloud& cloud : time.clouds) names.push_back(cloud.name());
  for (const std::string& name : constantCloudNames()) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string formatNumber(double value, int digits) {
  if (!std::isfinite(value)) return "nan";
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

bool CastAnalysis::readRange(double& low, double& high) const {
  if (!dict_.found("range")) return false;
  const auto range = dict_.get<std::vector<double>>("range");
  if (range.size() != 2 || !(range[0] < range[1])) {
    throw DictionaryError(dict_.location("range"),
                          "'range' of " + dict_.name() + " must be (low high), low < high");
  }
  low = range[0];
  high = range[1];
  return true;
}

bool CastAnalysis::readPictureTimes(std::vector<double>& show) const {
  const bool all = dict_.getChoiceOrDefault("times", {"latest", "all"}, "latest") == "all";
  show = dict_.getOrDefault<std::vector<double>>("show", {});
  if (!show.empty() && !all) {
    throw DictionaryError(dict_.location("show"),
                          "'show' needs 'times all' (a picture of every time) in " + dict_.name());
  }
  return all;
}

std::vector<std::size_t> CastAnalysis::shownPictures(const std::vector<double>& drawnTimes,
                                                     const std::vector<double>& show) {
  std::vector<std::size_t> shown;
  for (const double wanted : show) {
    std::size_t nearest = 0;
    for (std::size_t k = 1; k < drawnTimes.size(); ++k) {
      if (std::abs(drawnTimes[k] - wanted) < std::abs(drawnTimes[nearest] - wanted)) nearest = k;
    }
    if (std::find(shown.begin(), shown.end(), nearest) == shown.end()) shown.push_back(nearest);
  }
  std::erase(shown, drawnTimes.size() - 1);
  shown.push_back(drawnTimes.size() - 1);
  return shown;
}

std::string fieldUnit(const std::string& field) {
  if (field == field::T) return " (K)";
  if (field.ends_with("Time")) return " (s)";
  if (field == field::p) return " (Pa)";
  if (field == field::rho || field == field::restDensity) return " (kg/m^3)";
  return "";
}

std::string formatPoint(const Vector& x) {
  return "(" + formatNumber(x.x(), 4) + " " + formatNumber(x.y(), 4) + " " +
         formatNumber(x.z(), 4) + ") m";
}

CastAnalysisTypes& castAnalysisTypes() {
  static CastAnalysisTypes types = [] {
    CastAnalysisTypes registry("castPostProcess analysis");
    registry.add<CloudSummaryAnalysis>("cloudSummary");
    registry.add<TimeSeries>("timeSeries");
    registry.add<Thermocouples>("thermocouples");
    registry.add<SolidificationMaps>("solidificationMaps");
    registry.add<ShrinkageCavities>("shrinkageCavities");
    registry.add<Slice>("slice");
    registry.add<CastingView>("view");
    registry.add<HotSpots>("hotSpots");
    registry.add<BodyMotion>("bodyMotion");
    return registry;
  }();
  return types;
}

std::vector<std::unique_ptr<CastAnalysis>> readCastAnalyses(const Dictionary& dict,
                                                            const AnalysisContext& context) {
  std::vector<std::unique_ptr<CastAnalysis>> analyses;
  for (const std::string& name : dict.keys()) {
    if (!dict.isDict(name)) {
      throw DictionaryError(dict.location(name),
                            "'" + name + "' in " + dict.name() +
                                " is not an analysis: each entry is name { type ...; }");
    }
    const Dictionary& entry = dict.subDict(name);
    analyses.push_back(
        castAnalysisTypes().build(castAnalysisTypes().choose(entry, "type"), name, entry, context));
  }
  return analyses;
}

}  // namespace sphcast
