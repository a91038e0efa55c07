#pragma once
// The clock every cost in the bench is read from: the processor time of the thread
// that runs the engine. On a shared machine the wall clock also counts the time the run
// waits for a core while other programs have it, which no engine spent and which came
// and went with the load; the thread's own processor time leaves that out. Box2D runs
// on the same thread and is timed by the same clock.

#include <ctime>

namespace bench {

// Seconds of processor time the calling thread has used so far: only differences mean
// anything.
inline double thread_cpu_seconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace bench
