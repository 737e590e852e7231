// ParallelFor: how a decoder may spread independent work over threads its client owns. The codec
// starts no thread itself (it stays pure); a client that has cores to spare hands it one of these.
// The bits never depend on it: each job writes only its own outputs.
#pragma once

#include <functional>

namespace ocean::codec {

// Runs job(0) .. job(count - 1), each exactly once, in any order and on any threads, and returns
// when all have returned. The jobs do not throw. Empty: in order on the calling thread.
using ParallelFor = std::function<void(int count, const std::function<void(int)>& job)>;

// How many parts work that splits evenly (modes, samples) is cut into when threads are lent: as
// many as a client lends at most (its caller and three helpers).
inline constexpr int kParallelParts = 4;

inline void run_jobs(const ParallelFor& parallel, int count, const std::function<void(int)>& job) {
  if (parallel && count > 1) {
    parallel(count, job);
    return;
  }
  for (int i = 0; i < count; ++i) job(i);
}

}  // namespace ocean::codec
