#include "core/OpenMPSettings.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sphcast {

namespace {

double idleAtStart = -1;  // idle cores chooseThreadCount measured
bool threadsChosen = false;

// The CPU time counters of /proc/stat's first line: all time, and the busy part of it.
bool readCpuTimes(double& total, double& busy) {
  std::ifstream stat("/proc/stat");
  std::string name;
  double user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  if (!(stat >> name >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal) ||
      name != "cpu") {
    return false;
  }
  busy = user + nice + system + irq + softirq + steal;
  total = busy + idle + iowait;
  return true;
}

}  // namespace

void adoptPassiveWaitPolicy(char* argv[]) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) {
    return;
  }
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("OMP_WAIT_POLICY");  // execv failed: this process keeps libgomp's default
}

void chooseThreadCount() {
#ifdef _OPENMP
  if (std::getenv("OMP_NUM_THREADS") != nullptr) return;
  double total0 = 0, busy0 = 0, total1 = 0, busy1 = 0;
  if (!readCpuTimes(total0, busy0)) return;
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  if (!readCpuTimes(total1, busy1) || !(total1 > total0)) return;
  const int cores = omp_get_num_procs();
  idleAtStart = cores * (1.0 - (busy1 - busy0) / (total1 - total0));
  omp_set_num_threads(std::clamp(static_cast<int>(std::lround(idleAtStart)), 1, cores));
  threadsChosen = true;
#endif
}

std::string openMPSummary() {
  std::ostringstream text;
  int threads = 1;
#ifdef _OPENMP
  threads = omp_get_max_threads();
#endif
  const char* policy = std::getenv("OMP_WAIT_POLICY");
  text << threads << " (OpenMP, wait policy "
       << (policy                          ? policy
           : std::getenv("GOMP_SPINCOUNT") ? "GOMP_SPINCOUNT"
                                           : "default");
  if (threadsChosen) {
    text.precision(2);
    text << "; " << idleAtStart << " of "
#ifdef _OPENMP
         << omp_get_num_procs()
#endif
         << " cores idle at the start; OMP_NUM_THREADS sets it";
  } else if (std::getenv("OMP_NUM_THREADS") != nullptr) {
    text << "; OMP_NUM_THREADS";
  }
  text << ")";
  return text.str();
}

}  // namespace sphcast
