#pragma once

#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>

#include "core/CaseFolder.h"

namespace sphcast {

class Dictionary;

enum class StartFrom { startTime, firstTime, latestTime };
enum class StopAt { endTime, writeNow, noWriteNow, nextWrite };
enum class WriteControl { timeStep, runTime, adjustableRunTime };

// The run-control entries of system/controlDict, checked when read.
struct ControlSettings {
  std::string application;
  StartFrom startFrom = StartFrom::latestTime;
  double startTime = 0.0;
  StopAt stopAt = StopAt::endTime;
  double endTime = 0.0;
  double deltaT = 0.0;
  double maxDeltaT = std::numeric_limits<double>::max();
  bool adjustTimeStep = false;
  double maxCo = 0.25;
  // The heat conduction's step, maxDi dx^2 / alpha_max (OpenFOAM's chtMultiRegionFoam name):
  // forward Euler on the SPH Laplacian is stable to about 0.65 on a lattice (doc/physics.md §10.2).
  double maxDi = 0.1;
  WriteControl writeControl = WriteControl::timeStep;
  double writeInterval = 1.0;  // steps for timeStep, seconds otherwise
  int purgeWrite = 0;          // keep only this many written times (0: keep all)
  TimeFormat timeFormat = TimeFormat::general;
  int timePrecision = 6;
  bool runTimeModifiable = true;
  int logInterval = 1;  // sphCast's own: print the step block every N steps

  // Throws DictionaryError naming file, line and key for any unknown, missing or bad entry.
  // The `functions` sub-dictionary is accepted here and read by the solver (FunctionObject.h).
  static ControlSettings read(const Dictionary& controlDict);
};

// The exact time state written to <time>/uniform/time, so that a restart continues bit for bit.
struct TimeState {
  double value = 0.0;
  std::string name = "0";
  long index = 0;
  double deltaT = 0.0;  // the last step taken (0 before the first)
};

// The text of <time>/uniform/time for a state (values in full precision).
std::string uniformTimeDictionary(const TimeState& state);

// Case time and its control, as OpenFOAM's Time: picks the start time, advances, lands on write
// times and endTime, decides when to write and to stop, and re-reads system/controlDict when it
// changes during the run (so a user can stop a run cleanly by editing stopAt).
class TimeControl {
 public:
  // Reads system/controlDict and the start time's uniform/time (when present).
  explicit TimeControl(const CaseFolder& caseFolder);

  const ControlSettings& settings() const { return settings_; }
  const TimeState& state() const { return state_; }
  double value() const { return state_.value; }
  const std::string& timeName() const { return state_.name; }
  long timeIndex() const { return state_.index; }
  double deltaT() const { return deltaT_; }
  double startValue() const { return startValue_; }
  const std::string& startTimeName() const { return startName_; }

  // True while there is another step to take (OpenFOAM's run()). Re-reads a modified
  // controlDict first when runTimeModifiable is on.
  bool run();

  // With adjustTimeStep: the next step becomes the largest allowed by stableDeltaT (from the
  // models at maxCo), at most 1.2 times the last one and at most maxDeltaT, shortened so that
  // steps land on write times (adjustableRunTime) and on endTime.
  // limitName names what stableDeltaT comes from, for the log line of deltaTLimiter().
  void adjustDeltaT(double stableDeltaT, const std::string& limitName);
  // What set the current step: the model's limit, maxDeltaT, the growth limit, a landing.
  const std::string& deltaTLimiter() const { return deltaTLimiter_; }

  // Takes the step: time += deltaT, and decides whether this time is written.
  void advance();

  bool writeTime() const { return writeTime_; }
  // Whether the final state must be written when the loop ends (reached endTime, or stopped
  // with writeNow/nextWrite), and it was not written by the last step.
  bool finalWriteWanted() const;
  // Ends the run after the step just taken (a model's end condition: the casting is solid);
  // the final state is written as at endTime.
  void requestStop(const std::string& reason) { stopReason_ = reason; }
  // For the log: why run() returned false.
  std::string stopReason() const { return stopReason_; }
  // Any message from the last controlDict re-read (empty if nothing changed).
  std::string takeRereadMessage();
  // A parallel run's ranks re-read a modified controlDict at the same step and alike: `agree`
  // turns this rank's "it changed" into every rank's (whether any saw it change), and `share`
  // this rank's text of the file into one rank's, which every rank parses (a file caught
  // half-saved would otherwise give the ranks different settings, and they would part ways).
  void agreeOnChanges(std::function<bool(bool)> agree,
                      std::function<std::string(const std::string&)> share) {
    agree_ = std::move(agree);
    share_ = std::move(share);
  }

  // The completed fraction of [startTime, endTime], for the progress line.
  double progress() const;

 private:
  void chooseStartTime(const CaseFolder& caseFolder);
  void rereadIfModified();
  std::string nameFor(double time) const;
  long writeIndexAt(double time, double step) const;

  std::filesystem::path controlDictPath_;
  std::filesystem::file_time_type controlDictStamp_;
  ControlSettings settings_;
  TimeState state_;
  double deltaT_ = 0.0;     // the step to take next
  double startValue_ = 0.0;
  std::string startName_;
  std::optional<double> landingTime_;  // the write time or endTime the next step lands on
  long lastWriteIndex_ = 0;
  bool writeTime_ = false;
  bool stopRequested_ = false;
  bool endReached_ = false;
  std::string stopReason_;
  std::string rereadMessage_;
  std::string deltaTLimiter_ = "fixed deltaT";
  std::function<bool(bool)> agree_;
  std::function<std::string(const std::string&)> share_;
};

}  // namespace sphcast
