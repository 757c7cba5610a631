#include "core/Log.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <iostream>
#include <sstream>

#include "core/OpenMPSettings.h"
#include "core/Real.h"


namespace sphcast {

namespace {
bool infoSilenced = false;
}  // namespace

std::ostream& info() {
  static std::ostream nowhere(nullptr);  // a stream without a buffer drops what it is given
  return infoSilenced ? nowhere : std::cout;
}

void silenceInfo(bool silenced) { infoSilenced = silenced; }

void warning(const std::string& message) {
  std::cout.flush();
  std::cerr << "\n--> sphCast Warning: " << message << '\n' << std::endl;
}

void printBanner(const std::string& application, const std::string& caseRoot) {
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%b %d %Y %H:%M:%S", std::localtime(&now));
  info() << "/*---------------------------------------------------------------------------*\\\n"
         << "  sphCast: SPH casting simulation                 https://github.com/sphCast\n"
         << "\\*---------------------------------------------------------------------------*/\n"
         << "Build    : " << SPHCAST_VERSION << " (" << SPHCAST_BUILD_TYPE << ", Real = "
         << (sizeof(Real) == sizeof(double) ? "double" : "float") << ")\n"
         << "Exec     : " << application << '\n'
         << "Date     : " << date << '\n'
         << "Host     : " << host << '\n'
         << "PID      : " << getpid() << '\n'
         << "Case     : " << caseRoot << '\n'
         << "nThreads : " << openMPSummary() << "\n\n";
}

namespace {
double processCpuSeconds() {
  timespec cpu{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu);
  return static_cast<double>(cpu.tv_sec) + 1e-9 * static_cast<double>(cpu.tv_nsec);
}
}  // namespace

RunClock::RunClock() : wallStart_(std::chrono::steady_clock::now()), cpuStart_(processCpuSeconds()) {}

double RunClock::executionTime() const { return processCpuSeconds() - cpuStart_; }

double RunClock::clockTime() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
}

std::string RunClock::timesLine() const {
  std::ostringstream line;
  line.precision(6);
  line << "ExecutionTime = " << executionTime() << " s  ClockTime = "
       << std::lround(clockTime()) << " s";
  return line.str();
}

std::string formatDuration(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, (total / 60) % 60, total % 60);
  return text;
}

std::string RunClock::progressLine(double fraction, long stepsTaken,
                                   std::optional<std::pair<double, std::string>> earlierEnd) const {
  const double wall = clockTime();
  const double stepsPerSecond = wall > 0.0 ? static_cast<double>(stepsTaken) / wall : 0.0;
  std::optional<double> eta;
  if (fraction > 0.0) eta = wall * (1.0 - fraction) / fraction;
  std::string why;
  if (earlierEnd && (!eta || earlierEnd->first < *eta)) {
    eta = earlierEnd->first;
    why = " (" + earlierEnd->second + ")";
  }
  char text[192];
  std::snprintf(text, sizeof text, "Progress %.1f%% of endTime  %.0f steps/s  ETA %s%s",
                100.0 * fraction, stepsPerSecond, eta ? formatDuration(*eta).c_str() : "-",
                why.c_str());
  return text;
}

void CompletionEstimate::add(double wallSeconds, double progress) {
  samples_.emplace_back(wallSeconds, progress);
  // keep the newest sample older than the window, so that the rate spans the whole window
  while (samples_.size() > 2 && samples_[1].first <= wallSeconds - window_) samples_.pop_front();
}

std::optional<double> CompletionEstimate::secondsLeft() const {
  if (samples_.size() < 2) return std::nullopt;
  const auto& [wallThen, then] = samples_.front();
  const auto& [wallNow, now] = samples_.back();
  if (!(now > then) || !(wallNow > wallThen)) return std::nullopt;
  const double rate = (now - then) / (wallNow - wallThen);
  return std::max(0.0, 1.0 - now) / rate;
}

}  // namespace sphcast
