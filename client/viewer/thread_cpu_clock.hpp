// CPU time of the calling thread, for per-frame cost figures that a busy shared machine does not
// inflate the way wall-clock time does (the thread is charged only while it runs).
#pragma once

#include <ctime>

namespace ocean::viewer {

inline double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

}  // namespace ocean::viewer
