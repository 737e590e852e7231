// BuildQueue: one thread that builds what a scene known ahead will need (the sim's oceans, the
// encoders' models) during its lead. One thread, not one per build: on a two-core server ten
// builds at once (an admin change on a server of five profiles, two changes in a second) took the
// network thread's core for 60-100 ms, and its viewers' frames came late. A queue whose builds
// take no lock the tick's threads need (the encoders' models) runs below their priority, so that
// they keep their cores; the simulation's may not: FFTW's planner is one lock for the whole
// process, and a low-priority builder holding it while the sim thread waited for it (a build it
// must finish, a plan it destroys) held a loaded server's frames for seconds.
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
  // nice: added to the thread's scheduling niceness (0: the process's priority).
  explicit BuildQueue(int nice = 0);
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
  int nice_;
  std::thread thread_;
};

// Below the tick's threads: the kernel gives a busy network thread about nine tenths of a
// contended core against it.
inline constexpr int kBackgroundNice = 10;

}  // namespace ocean::server
