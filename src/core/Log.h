#pragma once

#include <chrono>
#include <ostream>
#include <string>

namespace sphcast {

// The log is OpenFOAM's: plain lines on standard output that foamLog-style tools can parse.
// Warnings and errors go to standard error.
std::ostream& info();
void warning(const std::string& message);

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
  std::string progressLine(double fraction, long stepsTaken) const;

 private:
  std::chrono::steady_clock::time_point wallStart_;
  double cpuStart_;
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
