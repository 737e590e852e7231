// TickLoop: runs TickClock's schedule on its own thread (the simulation thread), so frame
// computation never blocks the network io_context. A steady_timer is re-armed for each tick's
// wall-clock deadline, recomputed from the tick index, so clock adjustments never accumulate.
#pragma once

#include "tick_clock.hpp"

#include <asio/io_context.hpp>
#include <asio/steady_timer.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <system_error>
#include <thread>

namespace ocean::server {

// Unix time in nanoseconds from the system clock.
std::int64_t system_unix_ns();

class TickLoop {
 public:
  using TickHandler = std::function<void(const TickDecision&)>;  // runs on the simulation thread
  using WallClock = std::function<std::int64_t()>;                // Unix nanoseconds

  TickLoop(TickClock clock, TickHandler on_tick, WallClock now = system_unix_ns);
  ~TickLoop();
  TickLoop(const TickLoop&) = delete;
  TickLoop& operator=(const TickLoop&) = delete;

  const TickClock& clock() const { return clock_; }

  void start();  // starts the simulation thread; the first tick runs at once
  void stop();   // thread-safe and idempotent; returns after the thread has finished

 private:
  void do_wait();
  void on_timer(std::error_code error);

  TickClock clock_;
  TickHandler on_tick_;
  WallClock now_;
  asio::io_context context_;
  asio::steady_timer timer_;
  std::optional<std::int64_t> last_tick_;
  std::thread thread_;
};

}  // namespace ocean::server
