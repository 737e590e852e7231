// BuildQueue: one thread that builds what a scene known ahead will need (the sim's oceans, the
// encoders' models) during its lead. One thread, not one per build: on a two-core server ten
// builds at once (an admin change on a server of five profiles, two changes in a second) took the
// network thread's core for 60-100 ms, and its viewers' frames came late. At the process's own
// priority: FFTW's planner is one lock for the whole process, and a builder at a lower priority
// holding it while the tick's threads wait for it (a build they must finish, a plan they destroy)
// held a loaded server's frames for seconds.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>

namespace ocean::server {

class BuildQueue {
 public:
  BuildQueue();
  ~BuildQueue();  // waits for the build under way; those not started are dropped (broken promise)
  BuildQueue(const BuildQueue&) = delete;
  BuildQueue& operator=(const BuildQueue&) = delete;

  // Runs `build` after those submitted before it; the future holds its result or exception.
  template <typename F>
  auto submit(F build) -> std::future<decltype(build())> {
    auto task = std::make_shared<std::packaged_task<decltype(build())()>>(std::move(build));
    auto result = task->get_future();
    push([task] { (*task)(); });
    return result;
  }

 private:
  void push(std::function<void()> job);
  void run();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace ocean::server
