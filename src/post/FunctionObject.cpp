#include "post/FunctionObject.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>

#include "core/Error.h"
#include "post/BodyHistory.h"
#include "post/EnergyBalance.h"
#include "post/FieldMinMax.h"
#include "post/MassAverage.h"
#include "post/SamplingFunctionObjects.h"

namespace fs = std::filesystem;

namespace sphcast {

namespace {

const std::vector<std::string> commonKeys = {"type", "cloud", "writeControl", "writeInterval"};

}  // namespace

FunctionObject::FunctionObject(const std::string& name, const Dictionary& dict,
                               const FunctionObjectContext& context,
                               const std::vector<std::string>& extraKeys, Clouds clouds)
    : outputFolder_(context.caseRoot / "postProcessing" / name / context.startTimeName),
      name_(name),
      comm_(context.comm),
      startTime_(context.startTime) {
  std::vector<std::string> valid = commonKeys;
  if (clouds == Clouds::many) valid.erase(std::find(valid.begin(), valid.end(), "cloud"));
  valid.insert(valid.end(), extraKeys.begin(), extraKeys.end());
  dict.checkKeys(valid);
  readWriteControl(dict);
  if (clouds == Clouds::many) return;

  const auto cloudName = dict.get<std::string>("cloud");
  for (const ParticleCloud* cloud : context.clouds) {
    if (cloud->name() == cloudName) cloud_ = cloud;
  }
  if (!cloud_) {
    std::string present;
    for (const ParticleCloud* cloud : context.clouds) present += " " + cloud->name();
    throw DictionaryError(dict.location("cloud"), "unknown cloud '" + cloudName + "' in " +
                                                      dict.name() + "; the run has: (" + present +
                                                      " )");
  }
}

void FunctionObject::readWriteControl(const Dictionary& dict) {
  const std::string control =
      dict.getChoiceOrDefault("writeControl", {"timeStep", "writeTime", "runTime"}, "timeStep");
  control_ = control == "timeStep"    ? Control::timeStep
             : control == "writeTime" ? Control::writeTime
                                      : Control::runTime;
  interval_ = dict.getOrDefault<double>("writeInterval", 1.0);
  if (!(interval_ > 0) || (control_ == Control::timeStep && interval_ != std::floor(interval_))) {
    throw DictionaryError(dict.location("writeInterval"),
                          "'writeInterval' must be positive (a whole number of steps with "
                          "writeControl timeStep) in " +
                              dict.name());
  }
}

bool FunctionObject::wanted(const TimeState& time, bool caseWriteTime) {
  // As TimeControl's write index: whole intervals from time 0, rounded at half a step.
  const auto runTimeIndex =
      static_cast<long>(std::floor((time.value + 0.5 * time.deltaT) / interval_));
  if (!started_) {
    // The start: sampled where the uninterrupted run samples too, so that joined restarts
    // reproduce it (runTime assumes the step before the start was as long as the last one).
    started_ = true;
    lastRunTimeIndex_ = runTimeIndex;
    if (time.index == 0) return true;
    switch (control_) {
      case Control::timeStep:
        return time.index % static_cast<long>(interval_) == 0;
      case Control::writeTime:
        return true;  // a run starts from a written time
      case Control::runTime:
        return runTimeIndex >
               static_cast<long>(std::floor((time.value - 0.5 * time.deltaT) / interval_));
    }
  }
  switch (control_) {
    case Control::timeStep:
      return time.index % static_cast<long>(interval_) == 0;
    case Control::writeTime:
      return caseWriteTime;
    case Control::runTime: {
      const bool due = runTimeIndex > lastRunTimeIndex_;
      lastRunTimeIndex_ = runTimeIndex;
      return due;
    }
  }
  return false;
}

void FunctionObject::execute(const TimeState& time, bool caseWriteTime) {
  if (wanted(time, caseWriteTime)) sample(time.value);
}

std::ofstream& FunctionObject::openOutput(const std::string& fileName, const std::string& header) {
  auto& file = files_[fileName];
  if (!file && !comm_.master()) {  // rank 0 writes: the others' rows go nowhere
    file = std::make_unique<std::ofstream>();
    file->setstate(std::ios::badbit);
  }
  if (!file) {
    fs::create_directories(outputFolder_);
    const fs::path path = outputFolder_ / fileName;
    file = std::make_unique<std::ofstream>(path, std::ios::trunc);
    if (!*file) throw Error("cannot write " + path.string());
    char startLine[64];
    std::snprintf(startLine, sizeof startLine, "# startTime %.17g\n", startTime_);
    *file << startLine << header << std::flush;
  }
  return *file;
}

void FunctionObject::writeRow(std::ofstream& file, double time, const std::string& values) {
  char timeText[32];
  std::snprintf(timeText, sizeof timeText, "%-16.12g", time);
  // a time of 16 characters or more (0.00124963677918) fills the column: keep a separator
  file << timeText << (timeText[std::strlen(timeText) - 1] == ' ' ? "" : " ") << values << '\n'
       << std::flush;
}

std::string formatSample(double value) {
  if (std::isnan(value)) return "nan";
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

std::string formatSample(const Vector& value) {
  return '(' + formatSample(double(value.x())) + ' ' + formatSample(double(value.y())) + ' ' +
         formatSample(double(value.z())) + ')';
}

FunctionObjectTypes& functionObjectTypes() {
  static FunctionObjectTypes types = [] {
    FunctionObjectTypes registry("function object");
    registry.add<Probes>("probes");
    registry.add<SurfaceHeights>("surfaceHeights");
    registry.add<FluidFront>("front");
    registry.add<FieldMinMax>("fieldMinMax");
    registry.add<MassAverage>("massAverage");
    registry.add<EnergyBalance>("energyBalance");
    registry.add<BodyHistory>("bodyHistory");
    return registry;
  }();
  return types;
}

FunctionObjectList::FunctionObjectList(const Dictionary& controlDict,
                                       const FunctionObjectContext& context) {
  if (!controlDict.found("functions")) return;
  const Dictionary& functions = controlDict.subDict("functions");
  for (const std::string& name : functions.keys()) {
    const Dictionary& dict = functions.subDict(name);
    objects_.push_back(functionObjectTypes().build(functionObjectTypes().choose(dict, "type"), name,
                                                   dict, context));
  }
}

void FunctionObjectList::execute(const TimeState& time, bool caseWriteTime) {
  for (auto& object : objects_) object->execute(time, caseWriteTime);
}

std::vector<std::vector<double>> readFunctionObjectSeries(const fs::path& caseRoot,
                                                          const std::string& name,
                                                          const std::string& fileName) {
  const fs::path folder = caseRoot / "postProcessing" / name;
  std::vector<std::pair<double, fs::path>> starts;
  if (fs::is_directory(folder)) {
    for (const auto& entry : fs::directory_iterator(folder)) {
      const std::string start = entry.path().filename().string();
      char* end = nullptr;
      const double value = std::strtod(start.c_str(), &end);
      if (end != start.c_str() && *end == '\0' && fs::exists(entry.path() / fileName)) {
        starts.emplace_back(value, entry.path() / fileName);
      }
    }
  }
  std::sort(starts.begin(), starts.end());

  // Every file's exact start time (its header's first line) and rows.
  std::vector<double> startTimes;
  std::vector<std::vector<std::vector<double>>> files;
  for (const auto& [start, path] : starts) {
    startTimes.push_back(start);
    auto& fileRows = files.emplace_back();
    std::ifstream file(path);
    std::string line;
    while (std::getline(file, line)) {
      if (file.eof()) break;  // no newline: a row cut off by a killed run
      if (line.rfind("# startTime ", 0) == 0) {
        startTimes.back() = std::strtod(line.c_str() + 12, nullptr);
        continue;
      }
      if (line.empty() || line[0] == '#') continue;
      std::replace(line.begin(), line.end(), '(', ' ');
      std::replace(line.begin(), line.end(), ')', ' ');
      std::istringstream numbers(line);
      std::vector<double> row;
      std::string word;
      while (numbers >> word) row.push_back(std::strtod(word.c_str(), nullptr));
      if (!row.empty()) fileRows.push_back(std::move(row));
    }
  }
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < files.size(); ++k) {
    // Rows print 12 digits: a row within 1e-10 (relative) of the next start is that start.
    const double nextStart = k + 1 < files.size()
                                 ? startTimes[k + 1] - 1e-10 * std::abs(startTimes[k + 1])
                                 : std::numeric_limits<double>::infinity();
    for (auto& row : files[k]) {
      if (row.front() < nextStart) rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace sphcast
