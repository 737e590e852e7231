// TickClock: the arithmetic of fixed-rate ticks counted from a wall-clock epoch, and the decision
// of which tick to run when the loop wakes. Pure: the time is always an argument.
//
// Tick k starts at epoch + k / rate. Deadlines are computed from k, never accumulated, so there is
// no drift however long the server runs. Catch-up policy: when the loop wakes and ticks are
// overdue, it runs the next tick in order as long as no more than `max_catch_up` further ticks are
// also due (brief hiccups cost no ticks); beyond that it jumps to the current tick and counts the
// ones in between as skipped, because a burst of stale frames helps no client.
#pragma once

#include <cstdint>
#include <optional>

namespace ocean::server {

struct TickDecision {
  std::int64_t tick = 0;     // the tick to run now
  std::int64_t skipped = 0;  // ticks jumped over and never run
  bool late = false;         // the loop woke behind: more than the next tick was due
};

class TickClock {
 public:
  // rate_hz >= 1; max_catch_up >= 0.
  TickClock(int rate_hz, std::int64_t epoch_unix_ms, int max_catch_up = 2);

  int rate_hz() const { return rate_hz_; }
  int max_catch_up() const { return max_catch_up_; }

  // floor((now - epoch) * rate): the tick in progress at `unix_ns` (negative before the epoch).
  std::int64_t tick_at(std::int64_t unix_ns) const;
  // The first nanosecond at which tick_at() returns `tick`.
  std::int64_t deadline_ns(std::int64_t tick) const;
  // Simulation time of a tick in seconds: tick / rate.
  double sim_time_s(std::int64_t tick) const;

  // Which tick to run at `unix_ns`, given the last tick run (none yet: start at the current one).
  // Empty when the next tick is not yet due.
  std::optional<TickDecision> decide(std::int64_t unix_ns, std::optional<std::int64_t> last_tick) const;

 private:
  int rate_hz_;
  std::int64_t epoch_ns_;
  int max_catch_up_;
};

}  // namespace ocean::server
