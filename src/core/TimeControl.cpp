#include "core/TimeControl.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/Error.h"
#include "core/Log.h"
#include "core/dictionary/Dictionary.h"

namespace fs = std::filesystem;

namespace sphcast {

namespace {

const std::vector<std::string> controlDictKeys = {
    "application",     "startFrom",         "startTime",     "stopAt",
    "endTime",         "deltaT",            "maxDeltaT",     "adjustTimeStep",
    "maxCo",           "maxDi",             "writeControl",  "writeInterval",
    "purgeWrite",      "timeFormat",        "timePrecision", "runTimeModifiable",
    "logInterval",     "writeFormat",       "writePrecision", "writeCompression",
    "functions",       "healthChecks"};

// Relative tolerance for "this step lands on that time": far below any step, far above rounding.
constexpr double landingTolerance = 1e-9;

void require(bool condition, const Dictionary& dict, const std::string& key,
             const std::string& rule) {
  if (!condition) {
    throw DictionaryError(dict.location(key), "'" + key + "' " + rule + " in " + dict.name());
  }
}

template <class Enum>
Enum choose(const Dictionary& dict, const std::string& key, const std::vector<std::string>& names,
            Enum fallback, const std::string& fallbackName) {
  const std::string chosen = dict.getChoiceOrDefault(key, names, fallbackName);
  const auto at = std::find(names.begin(), names.end(), chosen);
  return at == names.end() ? fallback : static_cast<Enum>(at - names.begin());
}

}  // namespace

ControlSettings ControlSettings::read(const Dictionary& dict) {
  dict.checkKeys(controlDictKeys);
  ControlSettings s;
  s.application = dict.getOrDefault<std::string>("application", "");
  s.startFrom = choose(dict, "startFrom", {"startTime", "firstTime", "latestTime"},
                       StartFrom::latestTime, "latestTime");
  s.startTime = dict.getOrDefault<double>("startTime", 0.0);
  s.stopAt = choose(dict, "stopAt", {"endTime", "writeNow", "noWriteNow", "nextWrite"},
                    StopAt::endTime, "endTime");
  s.endTime = dict.get<double>("endTime");
  s.deltaT = dict.get<double>("deltaT");
  require(s.deltaT > 0.0, dict, "deltaT", "must be positive");
  s.adjustTimeStep = dict.getOrDefault<bool>("adjustTimeStep", false);
  s.maxDeltaT = dict.getOrDefault<double>("maxDeltaT", s.maxDeltaT);
  require(s.maxDeltaT > 0.0, dict, "maxDeltaT", "must be positive");
  s.maxCo = dict.getOrDefault<double>("maxCo", s.maxCo);
  require(s.maxCo > 0.0 && s.maxCo <= 1.0, dict, "maxCo", "must be in (0, 1]");
  s.maxDi = dict.getOrDefault<double>("maxDi", s.maxDi);
  require(s.maxDi > 0.0 && s.maxDi <= 0.5, dict, "maxDi", "must be in (0, 0.5]");
  s.writeControl = choose(dict, "writeControl", {"timeStep", "runTime", "adjustableRunTime"},
                          WriteControl::timeStep, "timeStep");
  s.writeInterval = dict.get<double>("writeInterval");
  require(s.writeInterval > 0.0, dict, "writeInterval", "must be positive");
  if (s.writeControl == WriteControl::timeStep) {
    require(s.writeInterval == std::floor(s.writeInterval), dict, "writeInterval",
            "must be a whole number of steps with writeControl timeStep");
  }
  s.purgeWrite = dict.getOrDefault<int>("purgeWrite", 0);
  require(s.purgeWrite >= 0, dict, "purgeWrite", "must be 0 (keep all) or a positive count");
  s.timeFormat = choose(dict, "timeFormat", {"general", "fixed", "scientific"},
                        TimeFormat::general, "general");
  s.timePrecision = dict.getOrDefault<int>("timePrecision", 6);
  require(s.timePrecision >= 1 && s.timePrecision <= 17, dict, "timePrecision",
          "must be between 1 and 17");
  s.runTimeModifiable = dict.getOrDefault<bool>("runTimeModifiable", true);
  s.logInterval = dict.getOrDefault<int>("logInterval", 1);
  require(s.logInterval >= 1, dict, "logInterval", "must be at least 1");
  return s;
}

TimeControl::TimeControl(const CaseFolder& caseFolder)
    : controlDictPath_(caseFolder.systemFile("controlDict")) {
  const Dictionary controlDict = Dictionary::read(controlDictPath_);
  settings_ = ControlSettings::read(controlDict);
  controlDictStamp_ = fs::last_write_time(controlDictPath_);
  chooseStartTime(caseFolder);
  if (!(settings_.endTime > startValue_) && settings_.stopAt == StopAt::endTime) {
    // Not an error: a finished case restarted with latestTime has nothing left to do.
    stopReason_ = "endTime " + nameFor(settings_.endTime) + " is not after the start time " +
                  startName_;
  }
}

void TimeControl::chooseStartTime(const CaseFolder& caseFolder) {
  const auto times = caseFolder.times();
  std::string chosen;
  switch (settings_.startFrom) {
    case StartFrom::startTime: {
      chosen = nameFor(settings_.startTime);
      const bool exists = std::any_of(times.begin(), times.end(),
                                      [&](const TimeFolder& t) { return t.name == chosen; });
      if (!exists) {
        throw Error(controlDictPath_.string() + ": startFrom startTime: no time folder '" +
                    chosen + "' in " + caseFolder.root().string());
      }
      break;
    }
    case StartFrom::firstTime:
    case StartFrom::latestTime:
      if (times.empty()) {
        throw Error("no time folder in " + caseFolder.root().string() +
                    " to start from (run setCastFields first to write 0/)");
      }
      chosen = settings_.startFrom == StartFrom::firstTime ? times.front().name
                                                           : times.back().name;
      break;
  }

  state_ = TimeState{};
  state_.name = chosen;
  state_.value = std::strtod(chosen.c_str(), nullptr);
  const fs::path uniformTime = caseFolder.root() / chosen / "uniform" / "time";
  if (fs::exists(uniformTime)) {
    // The folder name is rounded; the exact time and step are here (bit-exact restarts).
    const Dictionary saved = Dictionary::read(uniformTime);
    saved.checkKeys({"value", "name", "index", "deltaT"});
    state_.value = saved.get<double>("value");
    state_.index = saved.get<long>("index");
    state_.deltaT = saved.get<double>("deltaT");
  } else if (state_.value != 0.0) {
    // OpenFOAM takes the folder's name then too; say what that changes.
    warning(uniformTime.string() + " is missing: starting at time " + chosen +
            " (the folder's name) with time index 0 and deltaT of controlDict. The run "
            "continues, but does not reproduce the run that wrote " +
            chosen + " bit for bit, and writeControl timeStep counts its steps from here.");
  }
  startValue_ = state_.value;
  startName_ = chosen;
  deltaT_ = state_.deltaT > 0.0 && settings_.adjustTimeStep ? state_.deltaT : settings_.deltaT;
  lastWriteIndex_ = writeIndexAt(state_.value, state_.deltaT);
}

std::string TimeControl::nameFor(double time) const {
  return sphcast::timeName(time, settings_.timeFormat, settings_.timePrecision);
}

long TimeControl::writeIndexAt(double time, double step) const {
  // As OpenFOAM: the write index counts whole writeIntervals, rounded at half a step. It is
  // measured from time 0, not from the start time, so restarts write at the same times.
  return static_cast<long>(std::floor((time + 0.5 * step) / settings_.writeInterval));
}

void TimeControl::rereadIfModified() {
  if (!settings_.runTimeModifiable) return;
  std::error_code ignored;
  const auto stamp = fs::last_write_time(controlDictPath_, ignored);
  bool modified = !ignored && stamp != controlDictStamp_;
  if (agree_) modified = agree_(modified);
  if (!modified) return;
  controlDictStamp_ = stamp;
  std::string text;
  {
    std::ifstream file(controlDictPath_, std::ios::binary);
    std::ostringstream whole;
    whole << file.rdbuf();
    if (file) text = whole.str();
  }
  if (share_) text = share_(text);
  try {
    if (text.empty()) throw Error("cannot read " + controlDictPath_.string());
    ControlSettings changed =
        ControlSettings::read(Dictionary::parse(text, controlDictPath_.string()));
    // Where the run started is history now; everything else applies from the next step.
    changed.startFrom = settings_.startFrom;
    changed.startTime = settings_.startTime;
    if (!changed.adjustTimeStep) deltaT_ = changed.deltaT;
    settings_ = changed;
    rereadMessage_ = "Re-read " + controlDictPath_.string();
  } catch (const Error& error) {
    // A half-edited file must not kill a long run: keep the settings we have.
    rereadMessage_ = "Warning: ignoring modified " + controlDictPath_.string() +
                     " (keeping the previous settings): " + error.what();
  }
}

std::string TimeControl::takeRereadMessage() { return std::exchange(rereadMessage_, {}); }

bool TimeControl::run() {
  if (!stopReason_.empty()) return false;
  rereadIfModified();
  const bool tookAStep = state_.index > 0 && state_.value > startValue_;
  switch (settings_.stopAt) {
    case StopAt::noWriteNow:
      stopReason_ = "stopAt noWriteNow";
      return false;
    case StopAt::writeNow:
      stopReason_ = "stopAt writeNow";
      return false;
    case StopAt::nextWrite:
      if (tookAStep && writeTime_) {
        stopReason_ = "stopAt nextWrite";
        return false;
      }
      break;
    case StopAt::endTime:
      break;
  }
  if (endReached_ || state_.value >= settings_.endTime - 0.5 * deltaT_) {
    stopReason_ = "reached endTime";
    return false;
  }
  return true;
}

void TimeControl::adjustDeltaT(double stableDeltaT, const std::string& limitName) {
  landingTime_.reset();
  // A fixed step is never shortened (OpenFOAM's semantics): a run stopped at any step and
  // restarted then takes exactly the steps of the uninterrupted run.
  if (!settings_.adjustTimeStep) return;

  double next = stableDeltaT;
  deltaTLimiter_ = limitName;
  if (settings_.maxDeltaT < next) {
    next = settings_.maxDeltaT;
    deltaTLimiter_ = "maxDeltaT";
  }
  if (state_.deltaT > 0.0 && 1.2 * state_.deltaT < next) {
    next = 1.2 * state_.deltaT;
    deltaTLimiter_ = "growth limit (1.2 x last step)";
  }
  if (!(next > 0.0) || !std::isfinite(next)) {
    throw Error("the time step at t = " + state_.name + " would be " + std::to_string(next) +
                ": the run cannot continue");
  }

  // Land exactly on endTime and, with adjustableRunTime, on the next write time: the steps up
  // to it are made equal, so the step shrinks smoothly instead of ending with a tiny one.
  double target = settings_.endTime;
  const char* targetName = "endTime";
  if (settings_.writeControl == WriteControl::adjustableRunTime) {
    const double intervalsDone =
        std::floor(state_.value / settings_.writeInterval + landingTolerance);
    const double nextWrite = (intervalsDone + 1.0) * settings_.writeInterval;
    if (nextWrite < target) {
      target = nextWrite;
      targetName = "next write time";
    }
  }
  const double remaining = target - state_.value;
  const double stepsLeft = std::ceil(remaining / next * (1.0 - landingTolerance));
  if (remaining > 0.0 && stepsLeft <= 1.0) {
    deltaT_ = remaining;
    landingTime_ = target;
    deltaTLimiter_ += std::string(", landing on ") + targetName;
  } else if (remaining > 0.0) {
    deltaT_ = remaining / stepsLeft;
    if (deltaT_ < next) deltaTLimiter_ += std::string(", equal steps to ") + targetName;
  } else {
    deltaT_ = next;
  }
}

void TimeControl::advance() {
  state_.value = landingTime_ ? *landingTime_ : state_.value + deltaT_;
  endReached_ = landingTime_ && *landingTime_ == settings_.endTime;
  landingTime_.reset();
  state_.deltaT = deltaT_;
  ++state_.index;

  const std::string previousName = state_.name;
  state_.name = nameFor(state_.value);
  if (state_.name == previousName) {
    // Two times that print alike would overwrite each other's folder: print more digits.
    while (settings_.timePrecision < 17 && state_.name == previousName) {
      ++settings_.timePrecision;
      state_.name = nameFor(state_.value);
    }
    rereadMessage_ = "Increased timePrecision to " + std::to_string(settings_.timePrecision) +
                     " to distinguish time folders";
  }

  switch (settings_.writeControl) {
    case WriteControl::timeStep:
      writeTime_ = state_.index % static_cast<long>(settings_.writeInterval) == 0;
      break;
    case WriteControl::runTime:
    case WriteControl::adjustableRunTime: {
      const long writeIndex = writeIndexAt(state_.value, deltaT_);
      writeTime_ = writeIndex > lastWriteIndex_;
      lastWriteIndex_ = writeIndex;
      break;
    }
  }
}

bool TimeControl::finalWriteWanted() const {
  const bool tookAStep = state_.value != startValue_;
  return tookAStep && !writeTime_ && settings_.stopAt != StopAt::noWriteNow;
}

std::string uniformTimeDictionary(const TimeState& state) {
  char values[256];
  std::snprintf(values, sizeof values,
                "value       %.17g;\nname        \"%s\";\nindex       %ld;\ndeltaT      %.17g;\n",
                state.value, state.name.c_str(), state.index, state.deltaT);
  return foamFileHeader(state.name + "/uniform", "time") + "\n" + values;
}

double TimeControl::progress() const {
  const double span = settings_.endTime - startValue_;
  return span > 0.0 ? std::clamp((state_.value - startValue_) / span, 0.0, 1.0) : 1.0;
}

}  // namespace sphcast
