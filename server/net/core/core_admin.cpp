// SessionCore's admin side: ParamChanges wait in one queue for their token check, which runs at
// token_checks_per_s over every connection together, first come first served (one waiting change
// per connection); a right token's change is applied when the scene is servable and the change
// rate allows. So guessing is bounded however many addresses guess, and an operator who shares an
// address (a NAT, a bastion) with a guesser waits a few checks, never a lockout.
#include "session_core.hpp"

#include "admin_token.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "servable_scene.hpp"
#include "server_log.hpp"
#include "vessel_commands.hpp"

#include <spdlog/spdlog.h>

#include <spdlog/fmt/fmt.h>

namespace ocean::server {

void SessionCore::on_param_change(const std::shared_ptr<Session>& session, const wire::ParamChange& wire_change,
                                  const Instant& now) {
  // An admin tool waits for each answer; a connection that streams changes without reading them
  // is a guesser, and answering each would only fill its queue: it is closed.
  if (session->change_waiting)
    return refuse(*session, protocol::Reason::rate_limited,
                  "rate_limited: a ParamChange before the previous one was answered; closing");
  session->change_waiting = true;
  admin_queue_.push_back({session, protocol::read(wire_change)});
  check_admin_changes(now);
}

// Runs on every change queued and every tick: as many checks as the budget has tokens.
void SessionCore::check_admin_changes(const Instant& now) {
  while (!admin_queue_.empty()) {
    const std::shared_ptr<Session> session = admin_queue_.front().session.lock();
    if (!session || session->closed || session->ending) {
      admin_queue_.pop_front();
      continue;
    }
    if (!token_checks_.try_take(1, now.monotonic_s)) return;
    const auto request = std::move(admin_queue_.front().request);
    admin_queue_.pop_front();
    session->change_waiting = false;
    if (const auto* change = std::get_if<protocol::ParamChange>(&request)) {
      if (!token_refused(*session, change->admin_token, "ParamChange")) apply_param_change(*session, *change, now);
    } else if (const auto* query = std::get_if<protocol::HeightQuery>(&request)) {
      if (!token_refused(*session, query->admin_token, "HeightQuery")) answer_height_query(*session, *query);
    }
  }
}

// True when the token is refused (answered, and the connection closed after a few guesses).
bool SessionCore::token_refused(Session& session, const std::string& token, std::string_view message) {
  if (same_token(token, host_.config.admin_token)) {
    session.admin_proven = true;
    return false;
  }
  if (++session.token_failures >= options_.token_failures_per_connection) {
    refuse(session, protocol::Reason::unauthorized,
           fmt::format("unauthorized in {}.admin_token: too many wrong tokens; closing", message), "token_guessing");
    return true;
  }
  answer_error(session, protocol::Reason::unauthorized,
               fmt::format("unauthorized in {}.admin_token: expected the server's admin token", message), message);
  return true;
}

// The fleet after an admin's vessel command, or nothing when it is refused (answered here).
std::optional<std::vector<model::VesselTrack>> SessionCore::fleet_after(Session& session, const protocol::VesselCommand& command,
                                                                        Tick from) {
  const auto refused = [&](const std::string& text) {
    answer_error(session, protocol::Reason::out_of_range, text, "vessel command");
    return std::nullopt;
  };
  if (streams_.empty() || !streams_.front()->config().has_wake())
    return refused("out_of_range in ParamChange.vessel: this server streams no wake (its config has no [[vessel]] or "
                   "[[drop]]; start it with --wake on to add vessels to an empty sea)");
  const WakeLattice& wake = streams_.front()->config().wake;
  const FleetRules rules{host_.config.wake_origin_x_m, host_.config.wake_origin_z_m, host_.config.wake_size_m,
                         host_.config.tick_rate_hz, static_cast<std::int64_t>(wake.epoch_ticks)};
  FleetChange changed = apply_vessel_command(vessels_, command, from, tick_, rules);
  if (!changed.error.empty()) return refused("out_of_range in ParamChange.vessel: " + changed.error);
  return std::move(changed.fleet);
}

std::string SessionCore::unservable(const model::SceneParams& scene) const {
  std::vector<const Profile*> offered;
  for (const auto& stream : streams_) offered.push_back(&stream->profile());
  return servable_scene(scene, offered);
}

void SessionCore::apply_param_change(Session& session, const protocol::ParamChange& change, const Instant& now) {
  const Tick from = tick_ + scenes_.lead_ticks();
  model::SceneParams scene = scenes_.in_force(from).scene;
  // A vessel command: the fleet from `from` on, announced with the scene in force (changed too
  // when the same message changes it).
  std::optional<std::vector<model::VesselTrack>> fleet;
  if (change.vessel) {
    fleet = fleet_after(session, *change.vessel, from);
    if (!fleet) return;  // refused, and answered
  }
  if (change.wind_speed_mps) scene.wind_speed_mps = *change.wind_speed_mps;
  if (change.wind_dir_deg) scene.wind_dir_deg = *change.wind_dir_deg;
  if (change.amplitude) scene.amplitude = *change.amplitude;
  if (change.choppiness) scene.choppiness = *change.choppiness;
  if (change.spectrum) scene.spectrum = static_cast<model::SpectrumKind>(*change.spectrum);
  if (const std::string error = unservable(scene); !error.empty()) {
    return answer_error(session, protocol::Reason::out_of_range, error, "param_change");
  }
  if (!scene_changes_.try_take(1, now.monotonic_s)) {
    const double wait_s = scene_changes_.wait_s(1, now.monotonic_s);
    return answer_error(session, protocol::Reason::rate_limited,
                        fmt::format("rate_limited: at most {:g} scene changes a second (a burst of {:g}); retry in {:.1f} s",
                                    options_.scene_changes_per_s, options_.scene_change_burst, wait_s + 0.05));
  }
  if (host_.propose) {  // the fleet's timeline: applied when its log hands it back (core_timeline.cpp)
    spdlog::info("param_change sent to the timeline session={} peer={} request={} for tick {}", session.id, session.peer(),
                 change.request_id, from);
    return host_.propose(
        TimelineChange{host_.timeline_origin, session.id, protocol::SceneUpdate{change.request_id, from, scene, 0, std::move(fleet)}});
  }
  if (host_.request_scene) host_.request_scene(scene, static_cast<std::int64_t>(from));
  const std::size_t vessels = fleet ? fleet->size() : 0;
  announce({scenes_.add_admin(tick_, scene, std::move(fleet))}, session.id, change.request_id);
  host_.metrics.param_changes.inc();
  if (change.vessel)
    spdlog::info("vessel command accepted session={} peer={} request={} from tick {}: action {} vessel {}; {} tracks",
                 session.id, session.peer(), change.request_id, from, static_cast<int>(change.vessel->action),
                 change.vessel->id, vessels);
  spdlog::info("param_change accepted session={} peer={} request={} from tick {}: wind={} m/s dir={} deg amplitude={} "
               "choppiness={}",
               session.id, session.peer(), change.request_id, from, scene.wind_speed_mps, scene.wind_dir_deg,
               scene.amplitude, scene.choppiness);
}

}  // namespace ocean::server
