// AdmissionBudget: how many sessions the network thread can serve, projected from how loaded
// serving the present ones keeps it. Every second the hub reports the thread's time running, its
// time ready to run but waiting for a CPU, and the sessions it served.
//
// The load is the running time plus three times the waiting time. A thread that waits for its
// core (another process busy there) is late for every tick by that wait, and such contention
// turns into collapse long before the thread itself is busy: with a busy loop beside the server,
// 2200 viewers held at 33 % running and 28 % waiting in two runs of three and collapsed in the
// third, while alone it runs 75 % and keeps every tick. Counted twice, the waiting still let the
// door open that far; thrice, it closes at 1700-1900 there, and alone, where the wait is 1-2 %,
// it changes almost nothing.
//
// Only the share of that load spent serving sessions counts (LoadPeriod::served_s): the work of
// accepting and refusing strangers is bounded per address (ConnectRate) and is not what one
// more session would cost. Once the smoothed session load passes half the target, the capacity is
// the sessions that would load the thread to its target at what each costs now (a fixed cost
// makes that an underestimate far from the target and exact at it). A Hello beyond it is refused
// as server_full with a retry hint; the sessions already admitted keep their service, and a
// closed door never ends a session. Under `floor` sessions the door stays open: so few say little
// about their cost, and --max-clients is the hard cap. Pure: times are arguments.
#pragma once

#include <cstddef>
#include <limits>

namespace ocean::server {

struct LoadPeriod {
  double ran_s = 0.0;     // the network thread on a CPU
  double waited_s = 0.0;  // ready to run, waiting for a CPU
  double wall_s = 0.0;
  double sessions = 0.0;  // served, on average over the period
  // Of ran_s, the time the hub timed serving sessions (their frames and datagrams); < 0: all of
  // it. The rest - accepting and closing connections that never said Hello, refusing strangers -
  // is not what a newcomer would cost, and never closes the door to one (issue 33: connections
  // churned at 13 400 a second let 1 of 11 viewers in).
  double served_s = -1.0;
};

class AdmissionBudget {
 public:
  static constexpr std::size_t kUnlimited = std::numeric_limits<std::size_t>::max();
  static constexpr double kDefaultTarget = 0.85;

  // target_load: the load serving may reach; the rest absorbs bursts (joins, key ticks, acks
  // arriving together) and keeps I/O answered.
  explicit AdmissionBudget(double target_load = kDefaultTarget, std::size_t floor = 32)
      : target_load_(target_load), floor_(floor) {}

  void observe(const LoadPeriod& period);

  std::size_t capacity() const { return capacity_; }  // kUnlimited while the door is open
  bool admits(std::size_t sessions) const { return sessions < capacity_; }
  double busy_share() const { return busy_share_; }  // running or waiting, smoothed
  double wait_share() const { return wait_share_; }  // waiting, smoothed
  double load() const { return busy_share_ + 2.0 * wait_share_; }  // running + 3 x waiting
  // The part of load() serving sessions (the waits shared out like the running time).
  double session_load() const { return served_share_ * load(); }
  bool over_target() const { return load() > target_load_; }

 private:
  double target_load_;
  std::size_t floor_;
  double busy_share_ = 0.0;
  double wait_share_ = 0.0;
  double sessions_ = 0.0;  // smoothed alike, so that it matches the load it is divided by
  double served_share_ = 1.0;  // of the running time, serving sessions (smoothed alike)
  std::size_t capacity_ = kUnlimited;
};

}  // namespace ocean::server
