// SessionCore's side of the fleet's timeline (--timeline, issue 37): the entries of the log, in
// its order, each announced and applied at the tick the replica that took it stamped, as an admin
// change is on a server of its own. Every replica runs this on the same entries, so all announce
// the same scenes with the same serials from the same ticks and stream the same bytes.
#include "session_core.hpp"

#include "server_log.hpp"

#include <spdlog/spdlog.h>

namespace ocean::server {

void SessionCore::apply_logged(std::uint64_t index, const TimelineChange& change, bool history) {
  const protocol::SceneUpdate& update = change.update;
  Session* requester = change.origin == host_.timeline_origin ? sessions_.find(change.session) : nullptr;
  // Read after its tick (the store was away from this replica longer than the lead, or the append
  // took that long): its viewers have seen another sea since. It is applied all the same - the sea
  // from now on is the log's - and every viewer is keyed again, its decoder holding the other.
  const bool late = update.effective_tick <= tick_ && !history;
  // The replica that appended it checked it; one written into the store by other hands is checked
  // here, alike on every replica (one config, one set of profiles), and skipped by all - the origin
  // included: its mark in the entry is no proof of who wrote it.
  if (const std::string error = unservable(update.scene); !error.empty()) {
    host_.metrics.timeline_skipped.inc();
    spdlog::error("timeline entry {} skipped (every replica skips it): {}", index, error);
    if (requester) answer_error(*requester, protocol::Reason::out_of_range, error, "param_change");
    return;
  }
  std::optional<std::vector<model::VesselTrack>> fleet = update.vessels;
  if (host_.request_scene) host_.request_scene(update.scene, static_cast<std::int64_t>(update.effective_tick));
  const AnnouncedScene& announced = scenes_.add_logged(update.effective_tick, update.scene, std::move(fleet));
  announce({announced}, requester ? std::optional(requester->id) : std::nullopt, update.request_id);
  host_.metrics.timeline_entries.inc();
  if (requester) host_.metrics.param_changes.inc();
  if (late) {
    host_.metrics.timeline_late_entries.inc();
    last_late_entry_ = index;
    for (const auto& session : sessions_) session->need_key = true;
    spdlog::error("timeline entry {} takes effect at tick {}, which this server had passed (tick {}): its viewers saw "
                  "another sea for {} ticks; applied now, every viewer keyed again",
                  index, update.effective_tick, tick_, tick_ - update.effective_tick + 1);
  }
  spdlog::info("timeline entry {} applied: scene {} from tick {}{}", index, announced.serial, update.effective_tick,
               requester ? " (taken here)" : history ? " (the log's history at start)" : "");
}

void SessionCore::refuse_logged(const TimelineChange& change, const std::string& reason) {
  host_.metrics.timeline_refused.inc();
  spdlog::warn("timeline append refused for request {} of session {}: {}", change.update.request_id, change.session, reason);
  if (Session* session = change.origin == host_.timeline_origin ? sessions_.find(change.session) : nullptr)
    answer_error(*session, protocol::Reason::internal_error,
                 "the fleet's timeline did not confirm the change: " + reason,
                 "param_change");
}

}  // namespace ocean::server
