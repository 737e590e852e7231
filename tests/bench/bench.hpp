// ocean-bench plumbing: each bench_*.cpp registers one subcommand; helpers for medians and JSON.
#pragma once

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace ocean::bench {

using BenchFn = int (*)(int argc, char** argv);  // argv[0] is the subcommand name

struct Registrar {
  Registrar(const char* name, const char* summary, BenchFn fn);
};

inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Wall-clock milliseconds since an arbitrary origin; benches measure, the sim never sees this.
inline double now_ms() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace ocean::bench
