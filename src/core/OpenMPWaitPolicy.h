#pragma once

namespace sphcast {

// OpenMP threads that wait at the end of a parallel loop spin by default (GNU libgomp: some 3e5
// iterations, ~0.3 ms, before they sleep). On an idle machine that saves the wake-up; on a busy
// one a spinning thread holds the core the thread it waits for needs, and every one of the
// step's ~20 loops waits a time slice: the 2D dam break took 98.5 s of CPU and 284 s of wall time
// with 2 threads at load 8, against 15.5 s with 1 thread (and 13 s with 2 passive threads).
// libgomp reads OMP_WAIT_POLICY once, when the program loads, so an application that finds it
// unset sets it to `passive` and starts itself again (execv of /proc/self/exe, same arguments).
// A user's own OMP_WAIT_POLICY or GOMP_SPINCOUNT is left alone. Returns normally when nothing
// is to be done or the restart is impossible (the default policy then stays).
void adoptPassiveWaitPolicy(char* argv[]);

// The wait policy in effect, for the banner: "passive", "active" or "default".
const char* openMPWaitPolicy();

}  // namespace sphcast
