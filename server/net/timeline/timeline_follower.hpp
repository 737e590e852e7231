// TimelineFollower: a replica's thread for the fleet's timeline log. It holds the replica's lease
// on the store (its membership), appends the changes this replica took (TimelineLog::append: after
// whatever any replica wrote), reads the log every poll, acknowledges what it read, decides the
// entries it can (commit once every member has acknowledged one, abort once its tick is too near),
// and hands each decided entry on in log order, once, whoever wrote it - the replica that took a
// change applies it when it comes back through the log, like every other, so all apply the same
// entries in the same order. Only this thread talks to the store: a slow or absent store never
// holds the tick loop or the network thread. An append the store refused, or whose outcome it
// never told, is handed back with the reason (the admin is told; nothing is retried blindly).
//
// What a replica must not stream, it learns here: frames from the tick of an entry read but not
// yet decided or applied (hold_tick()), and every frame once its lease may have lapsed at the store
// (lease_until_s()), for then the others may commit entries it has not read.
#pragma once

#include "timeline_change.hpp"
#include "timeline_log.hpp"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace ocean::server {

// An entry as read: its change, or why no replica can read it.
struct ReadEntry {
  std::uint64_t index = 0;
  std::optional<TimelineChange> change;
  std::string unreadable;
};
std::vector<ReadEntry> read_entries(const TimelineLog::Read& read);

class TimelineFollower {
 public:
  struct Handlers {
    // All run on the follower's thread: hand the work to the thread that owns it.
    std::function<void(std::uint64_t index, TimelineChange change)> entry;  // committed
    std::function<void(const TimelineChange& change, const std::string& reason)> refused;  // aborted, or never appended
    // An entry no replica can read (logged and skipped by every replica alike).
    std::function<void(std::uint64_t index, const std::string& reason)> unreadable;
  };
  struct Setup {
    std::uint64_t origin = 0;         // this replica's mark (its acknowledgement's key)
    std::int64_t lease_s = 10;        // the lease's time to live
    int tick_rate_hz = 30;
    std::function<std::int64_t()> tick_now;  // the replica's tick by its clock
    double commit_margin_s = 0.3;     // an entry not committed this long before its tick is aborted
  };

  // Reads from entry `first_index` on (the ones before it were read by whoever started it);
  // poll_s: how often the log is read; timeout_s: each call's deadline.
  TimelineFollower(TimelineAddress address, Handlers handlers, Setup setup, std::uint64_t first_index = 1,
                   double poll_s = 0.025, double timeout_s = 0.5);
  ~TimelineFollower();  // stops and joins; gives its lease back (the fleet stops waiting for this replica)
  TimelineFollower(const TimelineFollower&) = delete;
  TimelineFollower& operator=(const TimelineFollower&) = delete;

  // Thread-safe: appended on the follower's thread, ahead of its next read.
  void propose(TimelineChange change);

  // Seconds (steady clock) of the last read the store answered; negative before the first.
  double last_read_s() const { return last_read_s_.load(); }
  std::uint64_t entries_read() const { return next_index_.load() - 1; }
  // Until when (steady clock) the store keeps this replica's lease for certain, counted from the
  // last keepalive's sending; negative before the lease is held and the log read under it.
  double lease_until_s() const { return lease_until_s_.load(); }
  // The first tick whose frames may not be the log's: the effective tick of the first entry read
  // and not yet decided, or committed and not yet applied (the largest tick if none).
  std::uint64_t hold_tick() const;
  // The network thread has applied the committed entry `index` (handed on by handlers.entry).
  void applied(std::uint64_t index);
  const TimelineAddress& address() const { return log_.address(); }

 private:
  void run();
  void keep_lease();
  void append_proposed();
  void read_new();
  void acknowledge();
  void decide_pending();
  void read_decisions();
  void deliver_decided();
  bool stopping();

  struct Pending {
    ReadEntry entry;
    std::optional<TimelineLog::Decision> decision;
  };

  bool too_late(const Pending& p) const;  // its tick nearer than the commit margin

  TimelineLog log_;
  Handlers handlers_;
  Setup setup_;
  double poll_s_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<TimelineChange> proposed_;
  bool stopping_ = false;
  // The follower thread's own.
  std::deque<Pending> pending_;  // read, in index order, not yet handed on
  std::int64_t lease_ = 0;
  double lease_sent_s_ = 0.0, lease_valid_until_s_ = -1.0, next_keepalive_s_ = 0.0;
  bool read_under_lease_ = false;  // a read began after the lease and acknowledgement were in place
  std::uint64_t acked_ = 0;
  bool ack_due_ = false;
  std::atomic<double> last_read_s_{-1.0};
  std::atomic<double> lease_until_s_{-1.0};
  void publish_undecided();
  std::atomic<std::uint64_t> undecided_tick_{std::numeric_limits<std::uint64_t>::max()};
  mutable std::mutex hold_mutex_;  // the two below change together
  std::uint64_t in_flight_tick_ = std::numeric_limits<std::uint64_t>::max();  // committed, handed on, not applied
  std::uint64_t last_handed_on_ = 0;
  std::atomic<std::uint64_t> next_index_{1};
  std::thread thread_;
};

// Seconds on the steady clock, as last_read_s() gives them.
double timeline_clock_s();

}  // namespace ocean::server
