// What the benchmarks share beyond tests/support (gpredict's catalogue is there:
// tb::testing::gpredict_catalogue_sets): the thread's CPU clock, for timing the parts of one
// iteration separately (Google Benchmark's CPU time is the same clock).
#pragma once
#include <time.h>

namespace tb::bench {

// This thread's CPU time, ns.
inline double thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e9 + static_cast<double>(ts.tv_nsec);
}

}  // namespace tb::bench
