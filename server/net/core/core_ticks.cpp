// SessionCore, per tick: feeds each profile's stream, serves every session a key or a delta
// (bundled with unacknowledged earlier frames on UDP), keeps the key roots few, and times out
// the silent.
#include "session_core.hpp"

#include "frame_records.hpp"
#include "message_builders.hpp"
#include "stream_wire.hpp"
#include "scene_wire.hpp"
#include "stream_wire.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <span>

namespace ocean::server {

protocol::SceneUpdate SessionCore::scene_update(const AnnouncedScene& scene, std::uint32_t request_id) const {
  return protocol::SceneUpdate{request_id, scene.from, scene_wire::to_wire(scene.scene), scene.serial};
}

// Both sides of every stream switch scene at its first tick with no keyframe: the encoders learn
// it now, the clients by the SceneUpdate (sent a lead ahead, so it arrives before that tick's
// frames; a client that missed it refuses those frames as unknown_scene and asks for a key).
void SessionCore::announce(const std::vector<AnnouncedScene>& scenes, std::optional<std::uint64_t> requester,
                          std::uint32_t request_id) {
  for (const AnnouncedScene& scene : scenes) {
    const model::SceneParams model = scene_wire::to_scene(scene_wire::to_wire(scene.scene));
    for (auto& stream : streams_) stream->set_scene(scene.from, scene.serial, model);
    for (const auto& session : sessions_.snapshot())  // a full control queue closes its session
      send_control(*session, protocol::encode(scene_update(scene, requester == session->id ? request_id : 0)));
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
  check_admin_changes(now);  // token checks and changes waiting for the admin budget
  announce(scenes_.announce(tick_));
  scenes_.forget_before(tick_ > protocol::kMaxFrameLag ? tick_ - protocol::kMaxFrameLag : 0);
  for (auto& stream : streams_)
    for (const ProfileFrame& frame : frames->frames)
      if (frame.profile == &stream->profile()) add_truth(*stream, frame.frame);

  bundles_.clear();  // the bytes of last tick's bundles stay alive while queued
  std::vector<std::pair<const void*, codec::StateId>> bases;
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
    if (!take_key_budget(stream, tick, now_s)) {
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

// The key budget is in bytes: a modeled mobile key (tens of bytes) costs the links and the
// server next to nothing, a desktop key with coefficients thousands of times more.
bool SessionCore::take_key_budget(ProfileStream& stream, Tick tick, double now_s) {
  // A key larger than the burst waits for a full bucket rather than forever.
  const double bytes = std::min(static_cast<double>(stream.key(tick).bytes), key_budget_.burst());
  return key_budget_.try_take_leaving(bytes, 0.0, now_s);
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

bool SessionCore::is_key_tick(const ProfileStream& stream, Tick tick) const {
  const auto frames = std::max<long>(1, std::lround(options_.key_period_s * stream.profile().rate_hz));
  return tick % (static_cast<Tick>(stream.tick_step()) * static_cast<Tick>(frames)) == 0;
}

void SessionCore::forget_unwatched_streams() {
  for (auto& stream : streams_) {
    const bool watched = std::any_of(sessions_.begin(), sessions_.end(),
                                     [&](const auto& session) { return session->stream == stream.get(); });
    if (!watched && stream->forget_states()) ++streams_released_;
  }
}

// A root's deltas cost a synthesis of the profile's grid each frame: a profile's roots together
// may cost root_samples_per_tick grid samples a tick (at least 2 roots). The cap the merges keep
// is that, at most max_roots.
std::size_t SessionCore::root_budget(const ProfileStream& stream) const {
  const double grid = stream.profile().grid;
  const double per_tick = grid * grid / static_cast<double>(stream.tick_step());
  const double fits = std::floor(options_.root_samples_per_tick / per_tick);
  return std::max<std::size_t>(2, static_cast<std::size_t>(std::clamp(fits, 0.0, 1e6)));
}

std::size_t SessionCore::root_cap(const ProfileStream& stream) const {
  return std::min(options_.max_roots, root_budget(stream));
}

// Sessions keyed at different ticks hold different states forever (a key is lossy), so every
// root costs its own encodes each tick. Beyond the cap, the smallest roots old enough are
// keyed again onto the root this key tick starts (the joiners' root, which it starts anyway),
// as many as it takes to be within the cap and as the key budget pays for now, after the keys
// of the sessions waiting for one: merged sessions must all take this tick's key, or they would
// only scatter into new roots. The largest root is never merged (re-keying most clients to
// absorb a few would be a key storm), a session pays at most one extra key per
// root_merge_age_s, and never a frame. Where one more root would exceed the profile's root
// budget (desktop), the joiners wait for a key tick with room (a joiner waits; the sessions
// served keep their tick time); cheap roots (mobile) let them in and the merges catch up.
bool SessionCore::limit_roots(ProfileStream& stream, Tick tick, double now_s) {
  std::map<Tick, std::vector<Session*>> roots;
  std::size_t waiting = 0;  // sessions that need a key to show anything: they start a root now
  for (const auto& session : sessions_) {
    if (session->stream != &stream) continue;
    if (session->need_key || (session->key_requested && key_due(*session, now_s))) ++waiting;
    else if (const auto root = session->baselines.root_tick()) roots[*root].push_back(session.get());
  }
  // Between joins the roots are consolidated to two (the largest and the one merged onto this
  // key), so a quiet server pays two encodes a tick, not the cap's.
  const std::size_t cap = waiting > 0 ? root_cap(stream) : std::min<std::size_t>(2, root_cap(stream));
  // Joiners wait only where one more root would cost more than the budget (desktop beyond 2);
  // cheap roots (mobile: 32 fit) let them in at once, and the merges catch up.
  const std::size_t budget = root_budget(stream);
  const auto room = [&](std::size_t roots_after) { return waiting == 0 || roots_after <= budget; };
  if (roots.size() + (waiting > 0 ? 1 : 0) <= cap || !stream.can_key(tick)) return true;
  Tick largest = 0;
  std::size_t largest_size = 0;
  for (const auto& [root, members] : roots)
    if (members.size() > largest_size) {
      largest = root;
      largest_size = members.size();
    }
  const double min_age_ticks = options_.root_merge_age_s * host_.config.tick_rate_hz;
  std::vector<std::pair<std::size_t, Tick>> old;  // (sessions, root)
  for (const auto& [root, members] : roots)
    if (root != largest && static_cast<double>(tick - root) >= min_age_ticks) old.emplace_back(members.size(), root);
  // After merging m roots there are roots - m + 1. Without joiners, merging one lowers nothing.
  const std::size_t least = waiting > 0 ? 1 : 2;
  std::size_t merge = std::min(old.size(), roots.size() + 1 - cap);
  const bool enter_anyway = room(roots.size() + 1);  // the joiners start their root, merge or not
  if (merge < least) return enter_anyway;
  std::sort(old.begin(), old.end());
  // The budget pays the waiting joiners' keys first, unless they wait for this merge: then it
  // goes first and must leave one joiner's key.
  const double key_bytes = static_cast<double>(stream.key(tick).bytes);
  const double reserve = static_cast<double>(enter_anyway ? waiting : 1) * key_bytes;
  for (; merge >= least; --merge) {
    std::size_t sessions = 0;
    for (std::size_t i = 0; i < merge; ++i) sessions += old[i].first;
    if (key_budget_.try_take_leaving(static_cast<double>(sessions) * key_bytes, reserve, now_s)) break;
  }
  // A root whose keys the budget's burst can never hold (large explicit keys, a small budget)
  // cannot be merged: then the joiners start a root beyond the cap rather than wait for good.
  if (merge < least)
    return enter_anyway || static_cast<double>(old.front().first) * key_bytes + reserve > key_budget_.burst();
  for (std::size_t i = 0; i < merge; ++i)
    for (Session* session : roots[old[i].second]) session->rekey = true;
  host_.metrics.root_merges.inc(static_cast<double>(merge));
  spdlog::debug("tick {} profile {}: {} key roots and {} joining; the {} smallest old enough are keyed again", tick,
                stream.profile().name, roots.size(), waiting, merge);
  return room(roots.size() + 1 - merge);
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
