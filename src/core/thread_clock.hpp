#pragma once
// CPU time of the calling thread. Benchmarks time single-threaded work with it: on a shared
// machine the time spent descheduled is not the code's.
#include <ctime>

namespace swarmagg {

inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace swarmagg
