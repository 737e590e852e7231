#include "worker_pool.hpp"

#include <algorithm>
#include <chrono>

namespace ocean {

namespace {
constexpr std::chrono::microseconds kStayAwake{200};
}  // namespace

WorkerPool::WorkerPool(int helpers) {
  for (int i = 0; i < helpers; ++i) threads_.emplace_back([this] { serve(); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_.store(true);
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

int WorkerPool::spare_cores(int limit) {
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(cores - 2, 0, limit);
}

// Hands out indices under the lock: a handful of jobs per call, each far longer than the lock.
void WorkerPool::take_jobs() {
  std::unique_lock lock(mutex_);
  const std::function<void(int)>* job = job_;
  while (next_ < count_) {
    const int i = next_++;
    lock.unlock();
    (*job)(i);
    lock.lock();
  }
}

void WorkerPool::run(int count, const std::function<void(int)>& job) {
  if (threads_.empty() || count <= 1) {
    for (int i = 0; i < count; ++i) job(i);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    job_ = &job;
    count_ = count;
    next_ = 0;
    running_ = static_cast<int>(threads_.size());
    call_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  take_jobs();
  std::unique_lock lock(mutex_);
  finished_.wait(lock, [this] { return running_ == 0; });
  job_ = nullptr;
}

void WorkerPool::serve() {
  std::uint64_t seen = 0;
  for (;;) {
    // A frame's calls come back to back (advance, transforms, output): a helper that has just
    // finished one waits a moment awake, because waking a sleeping thread can cost more than a
    // job (hundreds of microseconds on a virtual machine's idle core).
    const auto until = std::chrono::steady_clock::now() + kStayAwake;
    while (call_.load(std::memory_order_acquire) == seen && !stopping_.load(std::memory_order_acquire) &&
           std::chrono::steady_clock::now() < until)
      std::this_thread::yield();
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_.load() || call_.load() != seen; });
      if (stopping_.load()) return;
      seen = call_.load();
    }
    take_jobs();
    std::lock_guard lock(mutex_);
    if (--running_ == 0) finished_.notify_one();
  }
}

}  // namespace ocean
