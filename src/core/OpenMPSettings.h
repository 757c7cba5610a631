#pragma once

#include <string>

namespace sphcast {

// How the applications run their OpenMP threads, chosen before any parallel loop so that two
// threads are never a penalty on a busy machine. Measured on the damBreak2D tutorial (800
// particles, ~20 parallel loops a step), 2-core VM, median of 3 (tests/benchmarks/README.md):
//
//                                   idle: wall  |  4 other busy processes: wall
//   1 thread                             2.35 s |  5.84 s
//   2 threads, libgomp's spinning        1.62 s | 22.5 s   (GOMP_SPINCOUNT 3e5, the default)
//   2 threads, spin 1e4 then sleep       1.67 s | 20.9 s
//   2 threads, passive (sleep at once)   2.33 s |  7.90 s
//
// A spinning thread holds the core the thread it waits for needs, and every loop then waits a
// time slice. So:
//
// adoptPassiveWaitPolicy: unless the user set OMP_WAIT_POLICY or GOMP_SPINCOUNT, the waiting
// threads sleep (OMP_WAIT_POLICY=passive). libgomp reads it once, when the program loads, so
// the application sets it and starts itself again (execv of /proc/self/exe, same arguments);
// if that fails it goes on with libgomp's default.
void adoptPassiveWaitPolicy(char* argv[]);

// chooseThreadCount: unless the user set OMP_NUM_THREADS, as many threads as there are cores
// not busy with other work at the start, at least 1: a busy machine gets one thread, which is
// what it can use (5.84 s against 7.90 s above), an idle one all its cores. The busy cores are
// measured over 0.2 s from /proc/stat (the load average lags by a minute: after a tutorial's
// particleizeMold it would still count that tool's threads).
void chooseThreadCount();

// For the banner: "2 (OpenMP, wait policy passive; 2 of 2 cores idle at the start ...)".
std::string openMPSummary();

}  // namespace sphcast
