// SessionCore's HeightQuery: the true sea at a batch of points, what a game server needs for
// buoyancy without rendering anything. The answer samples the newest tick's frame of a profile
// with the client's own sampler (codec::SurfaceQuery), so a viewer's height_at and the server's
// answer differ only by what the stream's bound allows. A token is checked once per connection
// through the admin queue (guessing stays as slow as for changes); after that, queries are
// answered at once, at the per-connection rate and within the points budget of all connections.
#include "session_core.hpp"

#include "message_builders.hpp"
#include "message_readers.hpp"
#include "admin_token.hpp"
#include "surface_query.hpp"

#include <spdlog/fmt/fmt.h>

namespace ocean::server {
namespace {

const ProfileFrame* frame_of(const TickFrames* frames, const Profile& profile) {
  if (!frames) return nullptr;
  for (const ProfileFrame& f : frames->frames)
    if (f.profile == &profile) return &f;
  return nullptr;
}

}  // namespace

void SessionCore::on_height_query(const std::shared_ptr<Session>& session, const wire::HeightQuery& wire_query,
                                  const Instant& now) {
  if (session->change_waiting)
    return refuse(*session, protocol::Reason::rate_limited,
                  "rate_limited: a HeightQuery before the previous request was answered; closing");
  protocol::HeightQuery query = protocol::read(wire_query);
  if (query_rate_refused(*session, query.points.size(), now)) return;
  // A proven connection's right token needs no turn in the admin queue: the guessing it bounds
  // is over for this connection. A wrong one takes the queue's path (and counts as a guess).
  if (session->admin_proven && same_token(query.admin_token, host_.config.admin_token))
    return answer_height_query(*session, query);
  session->change_waiting = true;
  admin_queue_.push_back({session, std::move(query)});
  check_admin_changes(now);
}

// True when refused (answered; a connection that keeps asking at twice the rate is closed).
bool SessionCore::query_rate_refused(Session& session, std::size_t points, const Instant& now) {
  if (session.height_queries.rate() <= 0.0) {
    session.height_queries = TokenBucket(options_.height_queries_per_s, options_.height_query_burst, now.monotonic_s);
    session.query_refusals = TokenBucket(options_.height_queries_per_s, options_.height_query_burst, now.monotonic_s);
  }
  const bool mine = session.height_queries.try_take(1, now.monotonic_s);
  if (mine && query_points_.try_take(points, now.monotonic_s)) return false;
  if (!session.query_refusals.try_take(1, now.monotonic_s)) {
    refuse(session, protocol::Reason::rate_limited,
           "rate_limited: HeightQueries beyond the rate without waiting for the answers; closing", "query_flood");
    return true;
  }
  const double wait_s = mine ? query_points_.wait_s(points, now.monotonic_s) : session.height_queries.wait_s(1, now.monotonic_s);
  answer_error(session, protocol::Reason::rate_limited,
               mine ? fmt::format("rate_limited: at most {:g} query points a second over every connection; retry in {:.2f} s",
                                  options_.query_points_per_s, wait_s + 0.01)
                    : fmt::format("rate_limited: at most {:g} HeightQueries a second per connection (a burst of {:g}); "
                                  "retry in {:.2f} s",
                                  options_.height_queries_per_s, options_.height_query_burst, wait_s + 0.01));
  return true;
}

void SessionCore::answer_height_query(Session& session, const protocol::HeightQuery& query) {
  const ProfileStream* stream = query.profile_id == 0 ? streams_.front().get() : nullptr;
  for (const auto& s : streams_)
    if (s->profile().id == query.profile_id) stream = s.get();
  if (!stream) {
    if (find_profile(query.profile_id))
      return answer_error(session, protocol::Reason::profile_unavailable,
                          fmt::format("profile_unavailable in HeightQuery.profile_id: {} is not offered by this server",
                                      query.profile_id));
    return answer_error(session, protocol::Reason::unknown_profile,
                        fmt::format("unknown_profile in HeightQuery.profile_id: {} is no profile (PROTOCOL.md 8)",
                                    query.profile_id));
  }
  if (holding_)  // the newest frames may not be the log's sea (SessionCore::set_holding)
    return answer_error(session, protocol::Reason::internal_error,
                        "internal_error in HeightQuery: the server holds its frames until it has caught up with the "
                        "fleet's timeline; retry in a second");
  const ProfileFrame* now = frame_of(newest_frames_.get(), stream->profile());
  if (!now)
    return answer_error(session, protocol::Reason::profile_unavailable,
                        "profile_unavailable in HeightQuery: the server has no frame yet; retry after a tick");
  // The rate of change at the point, over the last tick (0 at the first frame, or across a jump).
  const ProfileFrame* before = frame_of(previous_frames_.get(), stream->profile());
  const double dt = before ? newest_frames_->time_s - previous_frames_->time_s : 0.0;
  const codec::SurfaceQuery sea(stream->config());
  protocol::HeightAnswer answer{query.request_id, static_cast<Tick>(newest_frames_->tick), stream->profile().id, {}};
  answer.samples.reserve(query.points.size());
  for (const wire::QueryPoint& p : query.points) {
    const codec::SurfaceQuery::Point s = sea.at(now->frame, p.x_m(), p.z_m());
    const double rate = dt > 0.0 ? (s.height_m - sea.height_at(before->frame, p.x_m(), p.z_m())) / dt : 0.0;
    answer.samples.emplace_back(static_cast<float>(s.height_m), static_cast<float>(s.normal[0]),
                                static_cast<float>(s.normal[1]), static_cast<float>(s.normal[2]), static_cast<float>(rate));
  }
  host_.metrics.height_queries.inc();
  send_control(session, protocol::encode(answer));
}

}  // namespace ocean::server
