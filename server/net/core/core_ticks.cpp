// SessionCore, per tick: feeds each profile's stream, serves every session a key or a delta
// (bundled with unacknowledged earlier frames on UDP), keeps the key roots few, and times out
// the silent.
#include "session_core.hpp"

#include "frame_records.hpp"
#include "message_builders.hpp"
#include "server_log.hpp"
#include "stream_wire.hpp"
#include "stream_wire.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <span>

namespace ocean::server {

protocol::SceneUpdate SessionCore::scene_update(const AnnouncedScene& scene, std::uint32_t request_id) const {
  return protocol::SceneUpdate{request_id, scene.from, scene.scene, scene.serial, scene.vessels};
}

// Both sides of every stream switch scene at its first tick with no keyframe: the encoders learn
// it now, the clients by the SceneUpdate (sent a lead ahead, so it arrives before that tick's
// frames; a client that missed it refuses those frames as unknown_scene and asks for a key).
void SessionCore::announce(const std::vector<AnnouncedScene>& scenes, std::optional<std::uint64_t> requester,
                          std::uint32_t request_id) {
  for (const AnnouncedScene& scene : scenes) {
    const model::SceneParams model = scene.scene;
    for (auto& stream : streams_) stream->set_scene(scene.from, scene.serial, model);
    if (scene.vessels) {
      vessels_ = *scene.vessels;
      for (auto& stream : streams_)
        if (stream->config().has_wake()) stream->set_vessels(vessels_, scene.from);
      if (host_.request_vessels) host_.request_vessels(vessels_, static_cast<std::int64_t>(scene.from));
    }
    // Encoded once for every session (with a fleet it is up to ~50 KB), once more for the requester.
    const protocol::Bytes broadcast = protocol::encode(scene_update(scene, 0));
    for (const auto& session : sessions_.snapshot())  // a full control queue closes its session
      send_control(*session, requester == session->id ? protocol::encode(scene_update(scene, request_id)) : broadcast);
    spdlog::info("scene {} announced: from tick {} (wind {} m/s towards {} deg, depth {} m)", scene.serial, scene.from,
                 scene.scene.wind_speed_mps, scene.scene.wind_dir_deg, scene.scene.depth_m);
  }
}

// A frame whose values its stream cannot carry is clamped, never fatal (a scene that slipped past
// servable_scene): that stream's viewers see those waves flattened, and the log and
// ocean_samples_saturated_total say so.
void SessionCore::add_truth(ProfileStream& stream, const sim::Frame& frame) {
  const std::uint64_t before = stream.saturated_samples();
  stream.add_truth(tick_, frame);
  const std::uint64_t clamped = stream.saturated_samples() - before;
  if (clamped == 0) return;
  host_.metrics.samples_saturated(stream.profile().name).inc(static_cast<double>(clamped));
  log_limited(spdlog::level::err, "stream_saturated", stream.profile().name,
              "tick {}: profile {} clamped {} samples beyond its 2^20 quantization steps; its viewers see those waves "
              "flattened", tick_, stream.profile().name, clamped);
}

void SessionCore::on_frames(const std::shared_ptr<const TickFrames>& frames, const Instant& now) {
  if (stopping_) return;
  tick_ = static_cast<Tick>(frames->tick);
  previous_frames_ = std::exchange(newest_frames_, frames);
  check_admin_changes(now);  // token checks and changes waiting for the admin budget
  announce(scenes_.announce(tick_));
  scenes_.forget_before(tick_ > protocol::kMaxFrameLag ? tick_ - protocol::kMaxFrameLag : 0);
  for (auto& stream : streams_)
    for (const ProfileFrame& frame : frames->frames)
      if (frame.profile == &stream->profile()) add_truth(*stream, frame.frame);

  bundles_.clear();  // the bytes of last tick's bundles stay alive while queued
  std::vector<std::pair<const void*, codec::StateId>> bases;
  if (holding_) {
    host_.metrics.timeline_held_ticks.inc();
    record_tick_stats(bases);
    sweep_timeouts(now.monotonic_s);
    return;
  }
  roots_full_.clear();
  if (second_tick()) forget_unwatched_streams();
  for (auto& stream : streams_)
    if (stream->is_frame_tick(tick_) && is_key_tick(*stream, tick_) && !limit_roots(*stream, tick_, now.monotonic_s))
      roots_full_.push_back(stream.get());
  // From a different session each tick: when a budget (keys, encodes) runs out, it is not always
  // the same sessions that wait. A copy, so a session closing meanwhile cannot upset the walk.
  rotate_from_ += 0x9E3779B97F4A7C15ull;
  std::vector<std::shared_ptr<Session>> order = sessions_.snapshot();
  if (!order.empty()) std::rotate(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(rotate_from_ % order.size()), order.end());
  for (const auto& session : order) {
    try {
      serve(*session, tick_, now.monotonic_s, bases);
    } catch (const std::exception& e) {  // an encoder precondition: a server bug, not the client's
      spdlog::error("session={} tick={}: {}", session->id, tick_, e.what());
      refuse(*session, protocol::Reason::internal_error, "internal_error: the server failed to encode a frame");
    }
  }
  publish_udp_tally();
  record_tick_stats(bases);
  sweep_timeouts(now.monotonic_s);
}

void SessionCore::record_tick_stats(std::vector<std::pair<const void*, codec::StateId>>& bases) {
  CoreTickStats stats;
  stats.tick = tick_;
  std::sort(bases.begin(), bases.end());
  stats.sessions_served = bases.size();
  stats.distinct_baselines = static_cast<std::size_t>(std::unique(bases.begin(), bases.end()) - bases.begin());
  ServerMetrics& metrics = host_.metrics;
  for (const auto& stream : streams_) {
    stats.encodes += stream->encodes_this_tick();
    if (stream->encodes_this_tick() > 0)
      metrics.encode_seconds(stream->profile().name).observe(stream->encode_seconds_this_tick());
  }
  metrics.encodes.inc(static_cast<double>(stats.encodes));
  metrics.encodes_last_tick.set(static_cast<double>(stats.encodes));
  if (second_tick()) metrics.send_queue_max_bytes.set(static_cast<double>(max_queued_bytes()));  // asks every link
  last_tick_ = stats;
  if (tick_observer_) tick_observer_(stats);
}

void SessionCore::serve(Session& session, Tick tick, double now_s,
                       std::vector<std::pair<const void*, codec::StateId>>& bases) {
  ProfileStream& stream = *session.stream;
  if (session.closed || !stream.is_frame_tick(tick)) return;
  const bool udp = session.on_udp();
  const bool due = key_due(session, now_s);
  std::optional<codec::StateId> base;
  if (session.rekey) {  // merged this key tick, its key already paid for
    session.rekey = false;
    if (!session.need_key && is_key_tick(stream, tick) && stream.can_key(tick)) {
      bases.emplace_back(&stream, codec::StateId{tick, 0});
      return send_key(session, stream, tick, now_s);
    }
  }
  if (!session.need_key && !(session.key_requested && due))
    base = session.baselines.choose(tick, udp, [&](codec::StateId id) { return stream.has_state(id); });
  if (!base) {
    // A key on the stream link, on a key tick (everyone keyed in one tick shares the key and every
    // delta after it): when required, else (acks missing) at most once per key interval.
    if ((!session.need_key && !due) || !is_key_tick(stream, tick) || !stream.can_key(tick)) return;
    if (std::find(roots_full_.begin(), roots_full_.end(), &stream) != roots_full_.end()) {
      host_.metrics.keys_deferred_roots.inc();
      return;
    }
    // Keys are paced server-wide: a burst of them (mass join, many acks late at once) waits for
    // the next key ticks instead of swamping the thread and the links in one.
    if (!keying_.take_key(static_cast<double>(stream.key(tick).bytes), now_s)) {
      host_.metrics.frames_skipped_load.inc();
      return;
    }
    bases.emplace_back(&stream, codec::StateId{tick, 0});
    return send_key(session, stream, tick, now_s);
  }
  // Late acks scatter baselines; past the per-tick encode budget, a session whose baseline has no
  // encode yet takes an encode of an older state it acked, and only without one skips this frame
  // (its next ack or a key brings it back) rather than delay everyone.
  if (!stream.has_encoded(tick, *base) && stream.encodes_this_tick() >= options_.max_encodes_per_tick) {
    base = session.baselines.choose_encoded(tick, [&](codec::StateId id) { return stream.has_encoded(tick, id); });
    if (!base) {
      host_.metrics.frames_skipped_load.inc();
      return;
    }
    host_.metrics.frames_rebased_load.inc();
  }
  bases.emplace_back(&stream, *base);
  deliver(session, tick, stream.delta(tick, *base), *base, now_s);
}

// A delta on its way: by UDP once its baseline is acked and the stream link has written its
// frames, else on the stream link within the session's pace and queue.
void SessionCore::deliver(Session& session, Tick tick, const SharedFrame& frame, codec::StateId base, double now_s) {
  ServerMetrics& metrics = host_.metrics;
  // UDP only once the frames queued on the stream link before it are written: a datagram
  // overtaking them would leave them complete but older than what the client already shows.
  // (Control messages queued there, such as a SceneUpdate, do not hold the stream back.)
  if (session.on_udp() && session.baselines.is_acked(base) && tcp_frames_written(session)) {
    if (!send_udp_frame(session, tick, frame, now_s)) {
      metrics.frames_skipped_bandwidth.inc();
      return;
    }
    session.baselines.record_sent(tick, frame.encoded->id, false);
  } else {
    // Within the budget the link paces; beyond a quarter second of backlog a frame is skipped.
    if (session.bytes_per_s > 0.0 && static_cast<double>(session.link->queued_bytes()) > 0.25 * session.bytes_per_s) {
      metrics.frames_skipped_bandwidth.inc();
      return;
    }
    if (!session.link->has_room(frame.bytes)) {
      metrics.send_queue_drops.inc();
      return;  // the baseline stays the last queued frame, or a key once it ages out
    }
    send_tcp_frame(session, frame);
    session.baselines.record_sent(tick, frame.encoded->id, true);
  }
  if (observer_) observer_(session.id, frame);
}

// Written through, a session stays so until its next frame on the stream link: asking the link
// every tick touched one more cold object per session and tick.
bool SessionCore::tcp_frames_written(Session& session) const {
  if (session.tcp_frames_pending && session.link->written_through(session.tcp_frames_mark))
    session.tcp_frames_pending = false;
  return !session.tcp_frames_pending;
}

void SessionCore::send_key(Session& session, ProfileStream& stream, Tick tick, double now_s) {
  const SharedFrame& frame = stream.key(tick);
  if (!session.link->has_room(frame.bytes)) {
    host_.metrics.send_queue_drops.inc();
    session.need_key = true;
    return;
  }
  send_tcp_frame(session, frame);
  session.need_key = session.key_requested = session.rekey = false;
  session.last_key_s = now_s;
  session.baselines.record_sent(tick, frame.encoded->id, true, true);
  session.recent_udp.clear();  // nothing from before a key predicts anything after it
  host_.metrics.keyframes_sent.inc();
  host_.metrics.key_bytes_sent.inc(static_cast<double>(frame.bytes));
  if (observer_) observer_(session.id, frame);
}

void SessionCore::send_tcp_frame(Session& session, const SharedFrame& frame) {
  for (const SharedBytes& message : frame.messages) session.link->send(message);
  session.tcp_frames_mark = session.link->enqueued_total();
  session.tcp_frames_pending = true;
  host_.metrics.frames_sent(session.link->transport()).inc();
  host_.metrics.bytes_sent(session.link->transport()).inc(static_cast<double>(frame.bytes));
}

// A single-chunk frame goes out with copies of the session's earlier UDP frames that it has not
// acked yet (newest udp_redundancy of them), oldest first, as one FrameBundle datagram; sessions
// with the same history share the bundle's bytes. Copies are dropped first when the bandwidth
// budget or the datagram size cannot hold them.
bool SessionCore::send_udp_frame(Session& session, Tick tick, const SharedFrame& frame, double now_s) {
  const std::size_t redundancy = static_cast<std::size_t>(host_.config.udp_redundancy);
  BundleKey key;
  if (frame.datagrams.size() == 1 && redundancy > 0) {
    const auto acked = session.baselines.newest_acked();
    for (const RecentFrame& r : session.recent_udp)
      if (!acked || r.tick > *acked) key.push(&r.frame->chunks.front());
    while (key.count > redundancy) key.drop_oldest();
    if (key.count > 0) key.push(&frame.encoded->chunks.front());
  }
  const SharedBytes* bundle = nullptr;
  while (key.count > 1) {
    bundle = &bundle_of(key);
    if ((*bundle)->size() <= protocol::kMaxDatagram && session.udp_bucket.try_take((*bundle)->size(), now_s)) break;
    bundle = nullptr;
    key.drop_oldest();  // the oldest copy goes first
  }
  if (bundle) {
    session.udp->send(*bundle);
    udp_tally_.bytes += (*bundle)->size();
    udp_tally_.copies += key.count - 1;
  } else {
    if (!session.udp_bucket.try_take(frame.datagram_bytes, now_s)) return false;
    for (const SharedBytes& datagram : frame.datagrams) session.udp->send(datagram);
    udp_tally_.bytes += frame.datagram_bytes;
  }
  ++udp_tally_.frames;
  if (frame.datagrams.size() == 1) {
    session.recent_udp.push_back(RecentFrame{tick, frame.encoded});
    while (session.recent_udp.size() > kMaxUdpRedundancy) session.recent_udp.pop_front();
  } else {
    session.recent_udp.clear();  // multi-chunk frames are not bundled
  }
  return true;
}

const SharedBytes& SessionCore::bundle_of(const BundleKey& key) {
  auto [it, fresh] = bundles_.try_emplace(key);
  if (fresh) {
    std::vector<protocol::FrameRecord> records;
    for (const codec::Chunk* chunk : key.view()) records.push_back(record_of(*chunk));
    it->second = std::make_shared<const protocol::Bytes>(protocol::frames_datagram(records));
  }
  return it->second;
}

// The UDP frames of a tick are counted once per tick: an atomic add of a double is a
// compare-and-swap loop, and three per frame were 1.4 % of the server's time at 1000 viewers.
void SessionCore::publish_udp_tally() {
  if (udp_tally_.frames == 0) return;
  ServerMetrics& metrics = host_.metrics;
  metrics.frames_sent("udp").inc(static_cast<double>(udp_tally_.frames));
  metrics.bytes_sent("udp").inc(static_cast<double>(udp_tally_.bytes));
  if (udp_tally_.copies > 0) metrics.bundled_copies.inc(static_cast<double>(udp_tally_.copies));
  udp_tally_ = {};
}

KeyedStream SessionCore::keyed(const ProfileStream& stream) {
  return {stream.profile().grid, stream.tick_step(), stream.profile().rate_hz};
}

void SessionCore::forget_unwatched_streams() {
  for (auto& stream : streams_) {
    const bool watched = std::any_of(sessions_.begin(), sessions_.end(),
                                     [&](const auto& session) { return session->stream == stream.get(); });
    if (!watched && stream->forget_states()) ++streams_released_;
  }
}

// Applies the keying policy's plan for a profile's roots on its key tick: the sessions of the
// roots it merges take this tick's key. False when the joiners must wait for a key tick with room.
bool SessionCore::limit_roots(ProfileStream& stream, Tick tick, double now_s) {
  if (!stream.can_key(tick)) return true;
  std::map<Tick, std::vector<Session*>> roots;
  std::size_t waiting = 0;  // sessions that need a key to show anything: they start a root now
  for (const auto& session : sessions_) {
    if (session->stream != &stream) continue;
    if (session->need_key || (session->key_requested && key_due(*session, now_s))) ++waiting;
    else if (const auto root = session->baselines.root_tick()) roots[*root].push_back(session.get());
  }
  std::map<Tick, std::size_t> sizes;
  for (const auto& [root, members] : roots) sizes[root] = members.size();
  const auto key_bytes = [&] { return static_cast<double>(stream.key(tick).bytes); };
  const RootPlan plan = keying_.plan_roots(keyed(stream), sizes, waiting, tick, key_bytes, now_s);
  for (const Tick root : plan.merge)
    for (Session* session : roots[root]) session->rekey = true;
  if (!plan.merge.empty()) {
    host_.metrics.root_merges.inc(static_cast<double>(plan.merge.size()));
    spdlog::debug("tick {} profile {}: {} key roots and {} joining; the {} smallest old enough are keyed again", tick,
                  stream.profile().name, roots.size(), waiting, plan.merge.size());
  }
  return plan.enter;
}

void SessionCore::sweep_timeouts(double now_s) {
  std::vector<std::shared_ptr<Session>> expired;
  for (const auto& session : handshaking_)
    if (session->link->open() && !session->ending && now_s - session->opened_s > host_.config.handshake_timeout_s)
      expired.push_back(session);
  for (const auto& session : expired) refuse(*session, protocol::Reason::timeout, "timeout: no Hello within the handshake time");
  expired.clear();
  for (const auto& session : sessions_)
    if (!session->closed && !session->ending && now_s - session->last_heard_s > host_.config.idle_timeout_s)
      expired.push_back(session);
  for (const auto& session : expired) {
    host_.metrics.rejects("idle_timeout").inc();
    end(*session, wire::ByeReason::idle_timeout, "no message for the idle limit (--idle-timeout)");
  }
}

}  // namespace ocean::server
