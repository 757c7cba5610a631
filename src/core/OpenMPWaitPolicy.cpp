#include "core/OpenMPWaitPolicy.h"

#include <unistd.h>

#include <cstdlib>

namespace sphcast {

void adoptPassiveWaitPolicy(char* argv[]) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) {
    return;
  }
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("OMP_WAIT_POLICY");  // execv failed: this process keeps libgomp's default
}

const char* openMPWaitPolicy() {
  const char* policy = std::getenv("OMP_WAIT_POLICY");
  if (policy == nullptr) return std::getenv("GOMP_SPINCOUNT") ? "GOMP_SPINCOUNT" : "default";
  return policy;
}

}  // namespace sphcast
