// ClientTally: what one simulated client's frames added up to - received, verified, late, bad,
// stalls - and the frames its stream schedule owed it, so lost = expected - received. Pure.
#pragma once

#include "tick.hpp"

#include <cstdint>
#include <optional>
#include <set>

#include "arrival_clock.hpp"

namespace ocean::loadtest {

struct FrameOutcome {
  bool within_bound = true;
  bool on_time = true;
};

class ClientTally {
 public:
  // frame_interval_ticks: ticks between the stream's frames (tick rate / stream rate).
  ClientTally(double tick_period_s, Tick frame_interval_ticks)
      : clock_(tick_period_s, 64), period_(tick_period_s), interval_(frame_interval_ticks ? frame_interval_ticks : 1) {}

  client::ArrivalClock& clock() { return clock_; }
  double tick_period_s() const { return period_; }
  Tick interval() const { return interval_; }

  // Records a frame's verdict; false (not counted) for a tick already recorded, before the
  // first one, or more than kWindowTicks older than the newest. Frames may come out of order (a
  // late copy of an older frame): it counts, and is on time if it came before its deadline.
  bool record(Tick tick, FrameOutcome outcome, double error_m) {
    if (first_tick_ && tick < *first_tick_) return false;
    if (last_tick_ && tick + kWindowTicks < *last_tick_) return false;
    if (!seen_.insert(tick).second) return false;
    if (!first_tick_) first_tick_ = tick;
    const bool newest = !last_tick_ || tick > *last_tick_;
    if (newest) last_tick_ = tick;
    while (seen_.size() > 1 && *seen_.begin() + kWindowTicks < *last_tick_) seen_.erase(seen_.begin());
    ++received_;
    if (error_m > max_error_m_) max_error_m_ = error_m;
    if (!outcome.within_bound) ++bad_;
    if (!outcome.on_time) ++late_;
    if (outcome.within_bound && outcome.on_time) {
      ++ok_;
      // A gap in the on-time sequence: the renderer ran out of frames in between.
      if (newest && last_on_time_ && tick > *last_on_time_ + interval_) ++stalls_;
      if (!last_on_time_ || tick > *last_on_time_) last_on_time_ = tick;
    }
    return true;
  }

  static constexpr std::uint32_t kWindowTicks = 64;

  // The stream's frame ticks in [first frame (or start_tick when none came), end_tick].
  std::uint64_t expected(Tick start_tick, Tick end_tick) const {
    const Tick from = first_tick_.value_or(start_tick);
    if (end_tick < from) return 0;
    const std::uint64_t first = (static_cast<std::uint64_t>(from) + interval_ - 1) / interval_;
    const std::uint64_t last = end_tick / interval_;
    return last >= first ? last - first + 1 : 0;
  }

  std::uint64_t received() const { return received_; }
  std::uint64_t ok() const { return ok_; }
  std::uint64_t late() const { return late_; }
  std::uint64_t bad() const { return bad_; }
  std::uint64_t stalls() const { return stalls_; }
  double max_error_m() const { return max_error_m_; }
  std::optional<Tick> first_tick() const { return first_tick_; }

 private:
  client::ArrivalClock clock_;
  double period_;
  Tick interval_;
  std::optional<Tick> first_tick_, last_tick_, last_on_time_;
  std::set<Tick> seen_;  // recorded ticks within kWindowTicks of the newest
  std::uint64_t received_ = 0, ok_ = 0, late_ = 0, bad_ = 0, stalls_ = 0;
  double max_error_m_ = 0.0;
};

}  // namespace ocean::loadtest
