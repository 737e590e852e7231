#include "timeline_follower.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace ocean::server {

namespace {
constexpr std::size_t kReadBatch = 64;  // entries a read asks for; the rest at the next poll
constexpr double kKeepaliveRetryS = 0.2;

std::string origin_name(std::uint64_t origin) {
  char text[20];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(origin));
  return text;
}
}  // namespace

double timeline_clock_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::vector<ReadEntry> read_entries(const TimelineLog::Read& read) {
  std::vector<ReadEntry> out;
  for (const TimelineEntry& entry : read.entries) {
    ReadEntry e;
    e.index = entry.index;
    e.change = decode_change(entry.bytes, e.unreadable);
    out.push_back(std::move(e));
  }
  return out;
}

TimelineFollower::TimelineFollower(TimelineAddress address, Handlers handlers, Setup setup, std::uint64_t first_index,
                                   double poll_s, double timeout_s)
    : log_(std::move(address), timeout_s), handlers_(std::move(handlers)), setup_(std::move(setup)), poll_s_(poll_s) {
  next_index_.store(first_index);
  acked_ = first_index - 1;
  if (first_index > 1) last_read_s_.store(timeline_clock_s());
  thread_ = std::thread([this] { run(); });
}

TimelineFollower::~TimelineFollower() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
  // A server that stops leaves the fleet at once: changes need not wait out its lease.
  if (lease_ != 0) (void)log_.store().lease_revoke(lease_);
}

bool TimelineFollower::stopping() {
  std::lock_guard lock(mutex_);
  return stopping_;
}

void TimelineFollower::propose(TimelineChange change) {
  {
    std::lock_guard lock(mutex_);
    proposed_.push_back(std::move(change));
  }
  wake_.notify_all();
}

void TimelineFollower::run() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    lock.unlock();
    // The lease is renewed between the calls too: on a slow store one round of them can take
    // longer than a short lease's renewal period.
    keep_lease();
    append_proposed();
    keep_lease();
    read_new();
    read_decisions();
    decide_pending();
    keep_lease();
    acknowledge();
    deliver_decided();
    lock.lock();
    wake_.wait_for(lock, std::chrono::duration<double>(poll_s_), [this] { return stopping_ || !proposed_.empty(); });
  }
}

// The lease is this replica's membership: while the store keeps it, every commit waits for this
// replica's acknowledgement. Its certain life is counted from each keepalive's sending (the store
// renews it later than that, never earlier); once that has passed, the replica holds its frames.
void TimelineFollower::keep_lease() {
  const double now = timeline_clock_s();
  if (lease_ == 0) {
    const EtcdResult granted = log_.store().lease_grant(setup_.lease_s);
    if (granted.error.empty() && granted.lease != 0 && granted.ttl_s > 0) {
      lease_ = granted.lease;
      lease_valid_until_s_ = now + static_cast<double>(granted.ttl_s);
      next_keepalive_s_ = now + static_cast<double>(granted.ttl_s) / 3.0;
      read_under_lease_ = false;
      ack_due_ = true;  // the acknowledgement, bound to the new lease, makes this replica a member
    }
  } else if (now >= next_keepalive_s_) {
    const EtcdResult renewed = log_.store().lease_keepalive(lease_);
    if (!renewed.error.empty()) {
      next_keepalive_s_ = now + kKeepaliveRetryS;
    } else if (renewed.ttl_s <= 0) {  // lapsed at the store: the others commit without this replica
      lease_ = 0;
      lease_valid_until_s_ = -1.0;
      read_under_lease_ = false;
    } else {
      lease_valid_until_s_ = now + static_cast<double>(renewed.ttl_s);
      next_keepalive_s_ = now + static_cast<double>(renewed.ttl_s) / 3.0;
    }
  }
  lease_until_s_.store(read_under_lease_ ? lease_valid_until_s_ : -1.0);
}

void TimelineFollower::append_proposed() {
  for (;;) {
    TimelineChange change;
    {
      std::lock_guard lock(mutex_);
      if (proposed_.empty() || stopping_) return;
      change = std::move(proposed_.front());
      proposed_.pop_front();
    }
    const TimelineLog::Appended appended = log_.append(encode_change(change));
    if (!appended.error.empty() && handlers_.refused) handlers_.refused(change, appended.error);
  }
}

void TimelineFollower::read_new() {
  const bool member = lease_ != 0 && !ack_due_;  // reads from now on see what commits without this replica
  while (!stopping()) {
    const std::uint64_t from = next_index_.load();
    const TimelineLog::Read read = log_.read_from(from, kReadBatch);
    if (!read.error.empty()) return;  // the store is away: last_read_s() ages, and says so
    last_read_s_.store(timeline_clock_s());
    for (ReadEntry& entry : read_entries(read)) {
      next_index_.store(entry.index + 1);
      pending_.push_back({std::move(entry), std::nullopt});
    }
    publish_undecided();  // before this read is acknowledged, or counts as the member's
    if (read.entries.size() < kReadBatch) break;
  }
  if (member && !read_under_lease_) {
    read_under_lease_ = true;
    lease_until_s_.store(lease_valid_until_s_);
  }
  if (next_index_.load() - 1 > acked_) ack_due_ = true;
}

// An entry read too near its tick (by this replica's clock) is decided - aborted, unless a commit
// already stands - before this replica acknowledges it: an acknowledgement is a promise to hold
// the entry's tick until it is decided, and a replica whose clock is behind must not commit it
// on the strength of this one's.
void TimelineFollower::acknowledge() {
  if (lease_ == 0 || !ack_due_) return;
  if (std::ranges::any_of(pending_, [this](const Pending& p) { return !p.decision && p.entry.change && too_late(p); }))
    return;  // its abort did not reach the store: acknowledged at a later round
  const std::uint64_t read = next_index_.load() - 1;
  if (log_.acknowledge(setup_.origin, read, lease_).error.empty()) {
    acked_ = read;
    ack_due_ = false;
  }
}

void TimelineFollower::read_decisions() {
  const auto first = std::ranges::find_if(pending_, [](const Pending& p) { return !p.decision && p.entry.change; });
  if (first == pending_.end()) return;
  const TimelineLog::Decisions read = log_.decisions_from(first->entry.index, kReadBatch);
  if (!read.error.empty()) return;
  for (const TimelineLog::Decision& d : read.decided)
    for (Pending& p : pending_)
      if (p.entry.index == d.index) p.decision = d;
}

// Any member decides an undecided entry: commit once every member (every live lease's
// acknowledgement) has read it, abort once its tick is nearer than the commit margin. The first
// decision written stands, so replicas deciding at once agree.
bool TimelineFollower::too_late(const Pending& p) const {
  const std::int64_t margin = static_cast<std::int64_t>(std::ceil(setup_.commit_margin_s * setup_.tick_rate_hz));
  return setup_.tick_now() + margin >= static_cast<std::int64_t>(p.entry.change->update.effective_tick);
}

void TimelineFollower::decide_pending() {
  std::optional<TimelineLog::Acks> acks;
  for (Pending& p : pending_) {
    if (stopping()) return;
    if (p.decision || !p.entry.change) continue;
    const auto tick = static_cast<std::int64_t>(p.entry.change->update.effective_tick);
    const bool late = too_late(p);
    if (!acks) acks = log_.acks();
    if (!acks->error.empty()) return;
    std::string behind;
    bool me = false;
    for (const auto& [origin, read] : acks->read) {
      me = me || origin == setup_.origin;
      if (read < p.entry.index) behind += (behind.empty() ? "" : ", ") + origin_name(origin);
    }
    const bool all_read = behind.empty() && me && lease_ != 0;
    if (!late && !all_read) continue;  // not yet
    // A commit this near the tick could reach a replica after it: that one would hold its frames
    // and key its viewers again. Aborted instead; the admin is told why.
    TimelineLog::Decision decision{p.entry.index, !late, {}};
    if (late)
      decision.reason = "not every replica following the timeline had read it " +
                        std::to_string(setup_.commit_margin_s).substr(0, 3) + " s before its tick " +
                        std::to_string(tick) + (behind.empty() ? "" : " (behind: " + behind + ")");
    TimelineLog::Decision decided;
    if (log_.decide(decision, decided).empty()) p.decision = decided;
  }
}

void TimelineFollower::deliver_decided() {
  while (!pending_.empty()) {
    Pending& p = pending_.front();
    if (!p.entry.change) {
      if (handlers_.unreadable) handlers_.unreadable(p.entry.index, p.entry.unreadable);
    } else if (!p.decision) {
      break;
    } else if (p.decision->commit) {
      {
        std::lock_guard lock(hold_mutex_);
        in_flight_tick_ = std::min<std::uint64_t>(in_flight_tick_, p.entry.change->update.effective_tick);
        last_handed_on_ = p.entry.index;
      }
      if (handlers_.entry) handlers_.entry(p.entry.index, std::move(*p.entry.change));
    } else if (handlers_.refused) {
      handlers_.refused(*p.entry.change, "the fleet aborted timeline entry " + std::to_string(p.entry.index) + ": " +
                                             p.decision->reason);
    }
    pending_.pop_front();
  }
  publish_undecided();
}

void TimelineFollower::publish_undecided() {
  std::uint64_t first = std::numeric_limits<std::uint64_t>::max();
  for (const Pending& p : pending_)
    if (p.entry.change) first = std::min<std::uint64_t>(first, p.entry.change->update.effective_tick);
  undecided_tick_.store(first);
}

std::uint64_t TimelineFollower::hold_tick() const {
  std::lock_guard lock(hold_mutex_);
  return std::min(undecided_tick_.load(), in_flight_tick_);
}

void TimelineFollower::applied(std::uint64_t index) {
  std::lock_guard lock(hold_mutex_);
  if (index >= last_handed_on_) in_flight_tick_ = std::numeric_limits<std::uint64_t>::max();
}

}  // namespace ocean::server
