#pragma once

#include <chrono>
#include <deque>
#include <optional>
#include <ostream>
#include <string>
#include <utility>

namespace sphcast {

// The log is OpenFOAM's: plain lines on standard output that foamLog-style tools can parse.
// Warnings and errors go to standard error.
std::ostream& info();
void warning(const std::string& message);
// A parallel run prints its log from rank 0 only: the others' info() goes nowhere (their
// warnings and errors still reach standard error).
void silenceInfo(bool silenced);

// The header every application prints: name, case, build, host, threads.
void printBanner(const std::string& application, const std::string& caseRoot);

// ExecutionTime (CPU seconds of the process, all threads) and ClockTime (wall seconds), as
// OpenFOAM prints them, plus the progress line: percent of endTime, steps/s and ETA.
class RunClock {
 public:
  RunClock();
  double executionTime() const;
  double clockTime() const;
  // "ExecutionTime = 1.23 s  ClockTime = 2 s"
  std::string timesLine() const;
  // "Progress 12.5% of endTime  1523 steps/s  ETA 0:01:23"; steps counted since construction.
  // `earlierEnd`: the wall seconds to another end of the run (the casting solid, with
  // endWhenSolid), and what it is; the ETA is the sooner of the two, named when it is that one.
  std::string progressLine(double fraction, long stepsTaken,
                           std::optional<std::pair<double, std::string>> earlierEnd = {}) const;

 private:
  std::chrono::steady_clock::time_point wallStart_;
  double cpuStart_;
};

// The wall time a measure of progress (rising from 0 to 1: the solid fraction of a casting
// that ends when solid) still needs, from its rise over the last `window` seconds of wall time
// (the oldest sample within it and the newest; the two newest when they are further apart): a
// casting freezes at a rate that changes as it goes, so the recent rate, not the run's mean.
class CompletionEstimate {
 public:
  explicit CompletionEstimate(double window = 60.0) : window_(window) {}
  void add(double wallSeconds, double progress);
  // Nothing until the measure has risen between two samples.
  std::optional<double> secondsLeft() const;

 private:
  std::deque<std::pair<double, double>> samples_;  // (wall seconds, progress), oldest first
  double window_;
};

// Runs `work`, adds its wall time to `total` (seconds) and returns what `work` returns: the
// solver's and the flow's time per part of the step.
template <class Work>
auto addWallTime(double& total, Work&& work) {
  struct AddOnExit {
    double& total;
    std::chrono::steady_clock::time_point start;
    ~AddOnExit() {
      total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  } add{total, std::chrono::steady_clock::now()};
  return work();
}

// Seconds as h:mm:ss.
std::string formatDuration(double seconds);

}  // namespace sphcast
