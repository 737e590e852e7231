// ClientTally: what one simulated client's frames added up to - received, verified, late, bad,
// stalls - and the frames its stream schedule owed it, so lost = expected - received. Pure.
#pragma once

#include "tick.hpp"

#include <cstdint>
#include <optional>
#include <array>

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
    const bool newest = !last_tick_ || tick > *last_tick_;
    if (newest) advance_to(tick);
    else if (seen(tick)) return false;
    mark(tick);
    if (!first_tick_) first_tick_ = tick;
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
  // Recorded ticks within kWindowTicks of the newest, one bit each at tick % kRingTicks: a frame
  // arrives 30 times a second per client, and a node-based set cost an allocation per frame.
  static constexpr Tick kRingTicks = 128;
  static_assert(kRingTicks > kWindowTicks);
  std::array<std::uint64_t, kRingTicks / 64> ring_{};
  bool seen(Tick tick) const { return (ring_[(tick % kRingTicks) / 64] >> (tick % 64)) & 1u; }
  void mark(Tick tick) { ring_[(tick % kRingTicks) / 64] |= std::uint64_t{1} << (tick % 64); }
  // The newest tick moves to `tick`: the bits of the ticks in between (and of the ring's older
  // wrap) no longer stand for recorded ticks.
  void advance_to(Tick tick) {
    if (!last_tick_ || tick - *last_tick_ >= kRingTicks) {
      ring_.fill(0);
    } else {
      for (Tick t = *last_tick_ + 1; t <= tick; ++t) ring_[(t % kRingTicks) / 64] &= ~(std::uint64_t{1} << (t % 64));
    }
    last_tick_ = tick;
  }
  std::uint64_t received_ = 0, ok_ = 0, late_ = 0, bad_ = 0, stalls_ = 0;
  double max_error_m_ = 0.0;
};

}  // namespace ocean::loadtest
