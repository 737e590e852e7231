// TimelineFollower: a replica's thread for the fleet's timeline log. It appends the changes this
// replica took (TimelineLog::append: after whatever any replica wrote) and reads the log every
// poll, handing each entry on in log order, once, whoever wrote it - the replica that took a
// change applies it when it comes back through the log, like every other, so all apply the same
// entries in the same order. Only this thread talks to the store: a slow or absent store never
// holds the tick loop or the network thread. An append the store refused, or whose outcome it
// never told, is handed back with the reason (the admin is told; nothing is retried blindly).
#pragma once

#include "timeline_change.hpp"
#include "timeline_log.hpp"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace ocean::server {

class TimelineFollower {
 public:
  struct Handlers {
    // Both run on the follower's thread: hand the work to the thread that owns it.
    std::function<void(std::uint64_t index, TimelineChange change)> entry;
    std::function<void(const TimelineChange& change, const std::string& reason)> refused;
    // An entry no replica can read (logged and skipped by every replica alike).
    std::function<void(std::uint64_t index, const std::string& reason)> unreadable;
  };

  // Reads from entry `first_index` on (the ones before it were read by whoever started it);
  // poll_s: how often the log is read; timeout_s: each call's deadline.
  TimelineFollower(TimelineAddress address, Handlers handlers, std::uint64_t first_index = 1, double poll_s = 0.05,
                   double timeout_s = 0.5);
  ~TimelineFollower();  // stops and joins
  TimelineFollower(const TimelineFollower&) = delete;
  TimelineFollower& operator=(const TimelineFollower&) = delete;

  // Thread-safe: appended on the follower's thread, ahead of its next read.
  void propose(TimelineChange change);

  // Seconds (steady clock) of the last read the store answered; negative before the first.
  double last_read_s() const { return last_read_s_.load(); }
  std::uint64_t entries_read() const { return next_index_.load() - 1; }
  const TimelineAddress& address() const { return log_.address(); }

 private:
  void run();
  void append_proposed();
  void read_new();

  TimelineLog log_;
  Handlers handlers_;
  double poll_s_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<TimelineChange> proposed_;
  bool stopping_ = false;
  std::atomic<double> last_read_s_{-1.0};
  std::atomic<std::uint64_t> next_index_{1};
  std::thread thread_;
};

// Seconds on the steady clock, as last_read_s() gives them.
double timeline_clock_s();

// Hands each entry read to handlers.entry, or to handlers.unreadable, in log order; returns the
// index after the last one (`next` when there was none). The follower's reads and a replica's
// read of the log at its start both pass here.
std::uint64_t deliver_entries(const TimelineLog::Read& read, std::uint64_t next, const TimelineFollower::Handlers& handlers);

}  // namespace ocean::server
