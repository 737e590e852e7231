// SessionHub's side of the fleet's timeline (--timeline, issue 37): the follower's thread reads
// and appends; what it brings is handed to the network thread, where the core applies each entry
// in log order. /readyz and /metrics say how fresh the timeline is.
#include "session_hub.hpp"

#include "server_log.hpp"
#include "tick_clock.hpp"
#include "tick_loop.hpp"

#include <asio/post.hpp>
#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <spdlog/spdlog.h>

namespace ocean::server {

void SessionHub::follow_timeline() {
  std::string error;
  std::optional<TimelineAddress> address = parse_timeline_url(server_.config().timeline, error);
  if (!address) throw std::invalid_argument("--timeline: " + error);  // validate_server_config checked it
  TimelineFollower::Handlers handlers;
  handlers.entry = [this](std::uint64_t index, TimelineChange change) {
    asio::post(server_.context(), [this, index, change = std::move(change)] {
      core_.apply_logged(index, change);
      if (core_.last_late_entry() == index) late_until_s_.store(timeline_clock_s() + kTimelineLateUnreadyS);
      // Frames the simulation made before it took the entry still show the sea without it: those
      // of its tick on are held (entries are taken a second ahead; one read late is not).
      timeline_requests_needed_ = server_.requests_made();
      timeline_untaken_tick_ = std::min<std::uint64_t>(timeline_untaken_tick_, change.update.effective_tick);
      timeline_->applied(index);
    });
  };
  handlers.refused = [this](const TimelineChange& change, const std::string& reason) {
    asio::post(server_.context(), [this, change, reason] { core_.refuse_logged(change, reason); });
  };
  handlers.unreadable = [this](std::uint64_t index, const std::string& reason) {
    asio::post(server_.context(), [this, index, reason] { skip_unreadable(index, reason); });
  };
  const std::uint64_t next = read_timeline_history(*address);
  spdlog::info("following the fleet's timeline at etcd {}:{} prefix {} from entry {} (lease {} s)", address->store.host,
               address->store.port, address->prefix, next, server_.config().timeline_lease_s);
  TimelineFollower::Setup setup;
  setup.origin = timeline_origin_;
  setup.lease_s = server_.config().timeline_lease_s;
  setup.tick_rate_hz = server_.config().tick_rate_hz;
  setup.tick_now = [clock = TickClock(server_.config().tick_rate_hz, server_.config().epoch_unix_ms)] {
    return clock.tick_at(system_unix_ns());
  };
  timeline_ = std::make_unique<TimelineFollower>(std::move(*address), std::move(handlers), std::move(setup), next);
  server_.set_readiness_check([this] { return timeline_readiness(); });
}

// The log as it stands, before the first tick is served: its committed entries set the sea from
// their ticks, past ones included, so a replica started late streams the log's sea from its first
// frame; the follower takes over at the first entry not yet decided (and holds the frames until it
// has read the log as a member). A store that does not answer stops the start (exit 1): the
// config's sea is not the fleet's.
std::uint64_t SessionHub::read_timeline_history(const TimelineAddress& address) {
  TimelineLog log(address, 1.0);
  std::uint64_t next = 1;
  std::string last_error;
  const double deadline = timeline_clock_s() + kTimelineStartS;
  while (timeline_clock_s() < deadline) {
    const TimelineLog::Read read = log.read_from(next, 256);
    const TimelineLog::Decisions decided = log.decisions_from(next, 256);
    if (!read.error.empty() || !decided.error.empty()) {
      last_error = read.error.empty() ? decided.error : read.error;
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      continue;
    }
    for (ReadEntry& entry : read_entries(read)) {  // on this thread, before any tick: straight to the core
      const auto decision = std::ranges::find(decided.decided, entry.index, &TimelineLog::Decision::index);
      if (!entry.change) {
        skip_unreadable(entry.index, entry.unreadable);
      } else if (decision == decided.decided.end()) {
        return entry.index;  // not decided yet: the follower's
      } else if (decision->commit) {
        core_.apply_logged(entry.index, *entry.change, true);
      }
      next = entry.index + 1;
    }
    if (read.entries.size() < 256) return next;
  }
  throw std::runtime_error("--timeline: the store at " + address.store.host + ":" + std::to_string(address.store.port) +
                           " did not answer within " + std::to_string(static_cast<int>(kTimelineStartS)) +
                           " s (" + last_error + "); a server that cannot read the fleet's timeline does not start");
}

void SessionHub::skip_unreadable(std::uint64_t index, const std::string& reason) {
  server_.metrics().timeline_skipped.inc();
  spdlog::error("timeline entry {} skipped (every replica skips it): {}", index, reason);
}

// Frames this replica must not stream: from the tick of an entry it has read and the fleet has not
// decided, and all of them while its lease may have lapsed (others may be committing entries it
// cannot read). Its viewers then get nothing rather than a sea the log may not say.
bool SessionHub::timeline_holds(const TickFrames& frames) {
  if (!timeline_) return false;
  const bool untaken = frames.requests_taken < timeline_requests_needed_;
  if (!untaken) timeline_untaken_tick_ = std::numeric_limits<std::uint64_t>::max();
  const auto tick = static_cast<std::uint64_t>(frames.tick);
  return timeline_clock_s() >= timeline_->lease_until_s() || tick >= timeline_->hold_tick() ||
         (untaken && tick >= timeline_untaken_tick_);
}

std::string SessionHub::timeline_readiness() const {
  const double lease = timeline_->lease_until_s();
  if (timeline_clock_s() >= lease)
    return lease < 0.0 ? "timeline: not yet a member of the fleet's timeline (no lease on the store, or the log not read under it)"
                       : "timeline: this server's lease on the store may have lapsed; it streams no frame until it is back";
  if (timeline_clock_s() < late_until_s_.load())
    return "timeline: an entry came after its tick; the viewers are being keyed again onto the log's sea";
  const double last = timeline_->last_read_s();
  if (last < 0.0) return "timeline: the store has not answered yet";
  const double age = timeline_clock_s() - last;
  if (age > kTimelineStaleS)
    return "timeline: stale, the store last answered " + std::to_string(age).substr(0, 5) + " s ago";
  return {};
}

void SessionHub::publish_timeline_metrics() {
  ServerMetrics& metrics = server_.metrics();
  metrics.timeline_index.set(static_cast<double>(timeline_->entries_read()));
  const double last = timeline_->last_read_s();
  metrics.timeline_age_seconds.set(last < 0.0 ? -1.0 : timeline_clock_s() - last);
}

}  // namespace ocean::server
