// AdmissionBudget: whether the network thread can take more sessions, from how busy serving keeps
// it. Every second the hub reports the thread's busy time (ticks served, datagrams handled) and
// the sessions it served. While the smoothed busy share is above the target, the door closes at
// the sessions served now (a Hello beyond them is refused as server_full with a retry hint), so
// the sessions already admitted keep their service; it opens again below 80 % of the target.
// A closed door never ends a session. Pure: times are arguments.
#pragma once

#include <cstddef>
#include <limits>

namespace ocean::server {

class AdmissionBudget {
 public:
  static constexpr std::size_t kUnlimited = std::numeric_limits<std::size_t>::max();

  // target_busy: the share of the network thread that serving may use; the rest absorbs bursts
  // (joins, key ticks, acks arriving together) and keeps /healthz and I/O answered.
  explicit AdmissionBudget(double target_busy = 0.7) : target_busy_(target_busy) {}

  // The last period: seconds busy out of seconds of wall time, serving `sessions` on average.
  void observe(double busy_s, double wall_s, double sessions);

  std::size_t capacity() const { return capacity_; }  // kUnlimited while the door is open
  bool admits(std::size_t sessions) const { return sessions < capacity_; }
  double busy_share() const { return busy_share_; }
  bool over_target() const { return busy_share_ > target_busy_; }

 private:
  double target_busy_;
  double busy_share_ = 0.0;  // smoothed
  std::size_t capacity_ = kUnlimited;
};

}  // namespace ocean::server
