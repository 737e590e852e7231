#include "timeline_follower.hpp"

#include <chrono>

namespace ocean::server {

namespace {
constexpr std::size_t kReadBatch = 64;  // entries a read asks for; the rest at the next poll
}

double timeline_clock_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

TimelineFollower::TimelineFollower(TimelineAddress address, Handlers handlers, std::uint64_t first_index, double poll_s,
                                   double timeout_s)
    : log_(std::move(address), timeout_s), handlers_(std::move(handlers)), poll_s_(poll_s) {
  next_index_.store(first_index);
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
    append_proposed();
    read_new();
    lock.lock();
    wake_.wait_for(lock, std::chrono::duration<double>(poll_s_), [this] { return stopping_ || !proposed_.empty(); });
  }
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
  for (;;) {
    const std::uint64_t from = next_index_.load();
    const TimelineLog::Read read = log_.read_from(from, kReadBatch);
    if (!read.error.empty()) return;  // the store is away: last_read_s() ages, and says so
    last_read_s_.store(timeline_clock_s());
    next_index_.store(deliver_entries(read, from, handlers_));
    if (read.entries.size() < kReadBatch) return;
  }
}

std::uint64_t deliver_entries(const TimelineLog::Read& read, std::uint64_t next, const TimelineFollower::Handlers& handlers) {
  for (const TimelineEntry& entry : read.entries) {
    std::string error;
    if (std::optional<TimelineChange> change = decode_change(entry.bytes, error)) {
      if (handlers.entry) handlers.entry(entry.index, std::move(*change));
    } else if (handlers.unreadable) {
      handlers.unreadable(entry.index, error);
    }
    next = entry.index + 1;
  }
  return next;
}

}  // namespace ocean::server
