// WorkerPool: a few threads that run the jobs of one call side by side with the caller, for work
// that splits into a handful of independent pieces per frame (a decoder's transforms). The threads
// sleep between frames; a call costs a wake-up, not a thread start.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace ocean {

class WorkerPool {
 public:
  // `helpers` threads beside the caller's (0: run() does everything on the caller's thread).
  explicit WorkerPool(int helpers);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // job(0) .. job(count - 1), each once, on the caller's thread and the helpers; returns when all
  // have returned. One call at a time; jobs must not throw (a throwing job ends the process).
  void run(int count, const std::function<void(int)>& job);

  int helpers() const { return static_cast<int>(threads_.size()); }

  // Helpers for a client that leaves one core to its renderer: hardware threads - 2, in [0, limit].
  static int spare_cores(int limit);

 private:
  void serve();
  void take_jobs();

  std::mutex mutex_;
  std::condition_variable wake_, finished_;
  const std::function<void(int)>* job_ = nullptr;
  int count_ = 0;
  int next_ = 0;      // the next job index to hand out
  int running_ = 0;   // helpers still inside the current call
  std::atomic<std::uint64_t> call_{0};  // written under mutex_; read without it while a helper spins
  std::atomic<bool> stopping_{false};
  std::vector<std::thread> threads_;
};

}  // namespace ocean
