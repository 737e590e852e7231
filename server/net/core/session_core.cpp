#include "session_core.hpp"

#include "epoch_wake.hpp"

#include "core_helpers.hpp"
#include "message_builders.hpp"
#include "message_readers.hpp"
#include "server_log.hpp"
#include "stream_transport.hpp"
#include "verify_message.hpp"
#include "stream_wire.hpp"

#include <sodium.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

namespace ocean::server {

using core::cookie_endpoint;

SessionCore::SessionCore(SessionCoreHost host, SessionCoreOptions options, Tick start_tick)
    : host_(std::move(host)),
      options_(options),
      scenes_(host_.schedule, static_cast<Tick>(std::lround(options.scene_lead_s * host_.config.tick_rate_hz))),
      admission_(AdmissionLimits{host_.config.max_handshakes, host_.config.max_handshakes_per_ip,
                                 host_.config.max_connections_per_ip}),
      tick_(start_tick),
      keying_(KeyingOptions{options.key_period_s, options.max_roots, options.root_samples_per_tick, options.root_merge_age_s,
                            options.key_bytes_per_s},
              host_.config.tick_rate_hz, 0.0),
      token_checks_(options.token_checks_per_s, options.token_check_burst, 0.0),
      scene_changes_(options.scene_changes_per_s, options.scene_change_burst, 0.0),
      query_points_(options.query_points_per_s, options.query_point_burst, 0.0),
      vessels_(host_.config.vessels) {
  for (const std::string& name : host_.config.profiles) {
    const Profile* profile = find_profile(std::string_view(name));
    if (!profile) continue;
    const codec::StreamConfig config = stream_config(*profile, host_.config.scene);
    if (const std::string error = codec::validate(config); !error.empty()) {
      spdlog::warn("profile {} is not offered to clients: {}", profile->name, error);
      continue;
    }
    streams_.push_back(std::make_unique<ProfileStream>(*profile, config, builds_));
    if (config.has_wake()) streams_.back()->set_vessels(host_.config.vessels);
  }
  if (streams_.empty()) throw std::invalid_argument("--profiles: no offered profile can be streamed by the codec");
  // The scenes in force now and within the lead, before the first tick: a Hello may come first.
  announce(scenes_.start(tick_));
  // Made up front (no allocation per datagram), except the two no peer can cause: "ok" is not a
  // refusal and a misaligned buffer is a receiver bug; those slots share an internal_error series.
  for (std::size_t r = 0; r < datagram_rejects_.size(); ++r) {
    const auto reason = static_cast<protocol::Reason>(r);
    const bool peer_caused = reason != protocol::Reason::ok && reason != protocol::Reason::misaligned_buffer;
    datagram_rejects_[r] = &host_.metrics.rejects(protocol::to_string(peer_caused ? reason : protocol::Reason::internal_error));
  }
}

codec::StreamConfig SessionCore::stream_config(const Profile& profile, const model::SceneParams& scene) const {
  codec::StreamConfig config =
      codec::StreamConfig::from_profile(profile, scene.patch_x_m, scene.patch_z_m, scene.gravity_mps2,
                                        model::wire_depth(scene.depth_m));
  config.tick_rate_hz = static_cast<std::uint16_t>(host_.config.tick_rate_hz);
  if (host_.config.has_wake())
    config.wake = WakeLattice{profile.wake_grid, host_.config.wake_size_m, host_.config.wake_origin_x_m,
                              host_.config.wake_origin_z_m, host_.config.wake_decay_per_s, 1e-6,
                              static_cast<std::uint32_t>(sim::wake_epoch_ticks(host_.config.tick_rate_hz))};
  return config;
}

std::uint64_t SessionCore::new_session_id() const {
  std::uint64_t id = 0;
  while (id == 0 || sessions_.contains(id)) randombytes_buf(&id, sizeof id);
  return id;
}

std::size_t SessionCore::max_queued_bytes() const {
  std::size_t most = 0;
  for (const auto& session : sessions_) most = std::max(most, session->link->queued_bytes());
  return most;
}

std::size_t SessionCore::peak_queued_bytes() const {
  std::size_t most = peak_closed_queued_bytes_;
  for (const auto& session : sessions_) most = std::max(most, session->link->peak_queued_bytes());
  return most;
}

// ---- stream links ----

void SessionCore::open(std::shared_ptr<StreamLink> link, const Instant& now) {
  auto session = std::make_shared<Session>();
  session->link = std::move(link);
  session->opened_s = session->last_heard_s = now.monotonic_s;
  std::weak_ptr<Session> weak = session;
  handshaking_.push_back(session);
  session->link->start(
      [this, weak](std::span<const std::uint8_t> bytes, const Instant& at) {
        if (auto s = weak.lock()) on_message(s, bytes, at);
      },
      [this, weak](const std::string& reason) {
        if (auto s = weak.lock()) on_closed(s, reason);
      });
  if (stopping_) return refuse(*session, protocol::Reason::server_full, "server_full: the server is shutting down");
  // Viewer slots are checked at the Hello: a connection that has said nothing holds only a
  // handshake, which has its own budget and deadline.
  std::string limit = admission_.admit(session->link->address());
  if (limit == "handshakes_full" || limit == "address_handshakes_full") {
    evict_oldest_handshake(*session, limit);
    limit = admission_.admit(session->link->address());
  }
  if (!limit.empty())
    return refuse(*session, protocol::Reason::server_full,
                  "server_full: too many connections waiting for their Hello (" + limit +
                      "; --max-handshakes, --max-handshakes-per-ip, --max-connections-per-ip)",
                  limit);
  session->admitted = true;
}

// A full handshake budget closes its oldest waiting connection (of the same address when that
// address's share is full), not the newcomer: a real client says Hello at once and is through
// before a reconnect loop comes round again, so sockets that stay silent only push each other out.
void SessionCore::evict_oldest_handshake(const Session& newcomer, const std::string& limit) {
  const asio::ip::address address = newcomer.link->address();
  std::shared_ptr<Session> oldest;
  for (const auto& waiting : handshaking_)
    if (waiting.get() != &newcomer && waiting->admitted && !waiting->welcomed &&
        (limit == "handshakes_full" || waiting->link->address() == address)) {
      oldest = waiting;
      break;
    }
  if (!oldest) return;
  host_.metrics.rejects("handshake_evicted").inc();
  log_reject(oldest->link->transport(), oldest->peer(), "handshake_evicted");
  oldest->link->close("handshake_evicted");  // at once: the budget is needed now
}

void SessionCore::on_closed(const std::shared_ptr<Session>& session, const std::string& reason) {
  session->closed = true;
  peak_closed_queued_bytes_ = std::max(peak_closed_queued_bytes_, session->link->peak_queued_bytes());
  if (session->welcomed) {
    log_disconnect(session->id, session->transport(), session->peer(), reason);
    host_.metrics.sessions_ended(reason).inc();
    sessions_.erase(session->id);
    update_client_gauges();
  }
  std::erase(handshaking_, session);
  if (session->admitted) admission_.closed(session->link->address(), session->welcomed);
  session->admitted = false;
}

void SessionCore::send_control(Session& session, protocol::Bytes bytes) {
  if (!session.link->open()) return;
  if (!session.link->has_control_room(bytes.size())) {
    // It keeps asking (Pings, bad ParamChanges) but reads nothing: memory stays bounded.
    host_.metrics.rejects("send_queue_full").inc();
    log_reject(session.link->transport(), session.peer(), "send_queue_full");
    session.link->close("send_queue_full");
    return;
  }
  session.link->send(share(std::move(bytes)));
}

void SessionCore::refuse(Session& session, protocol::Reason reason, const std::string& text, std::string_view label) {
  const std::string_view name = label.empty() ? protocol::to_string(reason) : label;
  session.ending = true;
  log_reject(session.link->transport(), session.peer(), name);
  host_.metrics.rejects(name).inc();
  send_control(session, protocol::encode(protocol::Error{reason, text.substr(0, protocol::kMaxTextBytes)}));
  session.link->close_after_flush(1.0);
}

void SessionCore::answer_error(Session& session, protocol::Reason reason, const std::string& text, std::string_view what) {
  const std::string_view name = protocol::to_string(reason);
  if (!what.empty())
    log_limited(spdlog::level::warn, name, session.peer(), "{} refused session={} peer={} reason={}: {}", what, session.id,
                session.peer(), name, text);
  host_.metrics.rejects(name).inc();
  send_control(session, protocol::encode(protocol::Error{reason, text.substr(0, protocol::kMaxTextBytes)}));
}

void SessionCore::end(Session& session, wire::ByeReason reason, const std::string& text) {
  session.ending = true;
  send_control(session, protocol::encode(protocol::Bye{reason, text}));
  session.link->close_after_flush(1.0);
}

void SessionCore::on_message(const std::shared_ptr<Session>& session, std::span<const std::uint8_t> bytes,
                             const Instant& now) {
  if (bytes.empty()) {
    const protocol::Reason reason = session->link->framing_failure();
    return refuse(*session, reason, std::string(protocol::to_string(reason)) +
                                        " in the TCP size prefix: expected a message of 12.." +
                                        std::to_string(protocol::kDefaultMaxMessageBytes) + " bytes");
  }
  const protocol::Verified verified =
      protocol::verify_message(bytes, {protocol::Sender::client, wire::Transport::tcp, protocol::kDefaultMaxMessageBytes});
  if (!verified) return refuse(*session, verified.reason, protocol::describe(verified));
  session->last_heard_s = now.monotonic_s;
  const wire::Message& message = *verified.message;
  if (!session->welcomed) {
    if (message.body_type() != wire::Body::Hello)
      return refuse(*session, protocol::Reason::unexpected_message, "unexpected_message: expected Hello first");
    return on_hello(session, *message.body_as_Hello(), now);
  }
  // The connection already names the session: a message naming another one is dropped and
  // counted (a confused or hostile client), and changes nothing.
  if (const std::uint64_t named = core::named_session(message); named != 0 && named != session->id) {
    host_.metrics.rejects(protocol::to_string(protocol::Reason::bad_session)).inc();
    return;
  }
  switch (message.body_type()) {
    case wire::Body::Ack:
    case wire::Body::KeyframeRequest:
    case wire::Body::Ping:
      return on_session_message(*session, message, *session->link, now);
    case wire::Body::SetTransport:
      session->wants_udp = message.body_as_SetTransport()->transport() == wire::Transport::udp;
      // PROTOCOL.md 5.6: a key, then TCP only; at most one key per key interval, so switching
      // back and forth cannot ask for keys faster than KeyframeRequests can.
      if (!session->wants_udp) {
        if (key_due(*session, now.monotonic_s)) session->need_key = true;
        else session->key_requested = true;
      }
      return update_client_gauges();
    case wire::Body::ParamChange:
      return on_param_change(session, *message.body_as_ParamChange(), now);
    case wire::Body::HeightQuery:
      return on_height_query(session, *message.body_as_HeightQuery(), now);
    case wire::Body::Bye:
      return session->link->close("client_bye");
    default:
      return refuse(*session, protocol::Reason::unexpected_message, "unexpected_message: a Hello after the Welcome");
  }
}

void SessionCore::on_session_message(Session& session, const wire::Message& message, Link& reply, const Instant& now) {
  switch (message.body_type()) {
    case wire::Body::Ack:
      session.baselines.on_ack({message.body_as_Ack()->latest_tick64(), message.body_as_Ack()->ack_bits()});
      break;
    case wire::Body::KeyframeRequest:
      session.key_requested = true;
      break;
    case wire::Body::Ping: {
      const wire::Ping& ping = *message.body_as_Ping();
      protocol::Bytes pong = protocol::encode(protocol::Pong{ping.seq(), ping.client_time_us(), tick_, now.unix_ms});
      if (&reply == session.link.get()) return send_control(session, std::move(pong));
      reply.send(share(protocol::message_datagram(pong)));
      break;
    }
    default:
      break;
  }
}

ProfileStream* SessionCore::choose_profile(std::uint8_t wanted, std::uint64_t bandwidth_bps) const {
  if (wanted != 0) {
    for (const auto& stream : streams_)
      if (stream->profile().id == wanted) return stream.get();
    return nullptr;
  }
  // Server's choice: the first offered profile whose delta rate fits 80 % of the budget, else the
  // lightest (smallest grid). The rate is measured once the profile streams; before that it is
  // estimated at half a byte per sample and frame.
  ProfileStream* lightest = streams_.front().get();
  for (const auto& stream : streams_)
    if (stream->profile().grid < lightest->profile().grid) lightest = stream.get();
  if (bandwidth_bps == 0) return streams_.front().get();
  for (const auto& stream : streams_) {
    const double grid = stream->profile().grid;
    const double frame_bytes = stream->mean_delta_bytes() > 0.0 ? stream->mean_delta_bytes() : 0.5 * grid * grid;
    const double bps = frame_bytes * 8.0 * stream->profile().rate_hz;
    if (bps <= 0.8 * static_cast<double>(bandwidth_bps)) return stream.get();
  }
  return lightest;
}

void SessionCore::on_hello(const std::shared_ptr<Session>& session, const wire::Hello& wire_hello, const Instant& now) {
  const protocol::Hello hello = protocol::read(wire_hello);
  ProfileStream* stream = choose_profile(hello.profile_id, hello.bandwidth_bps);
  if (!stream) {
    std::string offered;
    for (const auto& s : streams_)
      offered += (offered.empty() ? "" : ", ") + std::to_string(s->profile().id) + " (" + std::string(s->profile().name) + ")";
    return refuse(*session, protocol::Reason::profile_unavailable,
                  "profile_unavailable in Hello.profile_id: " + std::to_string(hello.profile_id) +
                      " is not offered; offered: " + offered);
  }
  if (sessions_.size() >= static_cast<std::size_t>(host_.config.max_clients))
    return refuse(*session, protocol::Reason::server_full,
                  "server_full: " + std::to_string(host_.config.max_clients) + " clients connected (--max-clients)");
  if (sessions_.size() >= session_limit_)
    return refuse(*session, protocol::Reason::server_full,
                  "server_full: at its measured capacity of " + std::to_string(session_limit_) +
                      " sessions; retry in 10 s or use another replica");
  std::erase(handshaking_, session);
  admission_.welcomed(session->link->address());
  session->id = new_session_id();
  session->stream = stream;
  session->baselines = BaselineTracker(stream->tick_step() * options_.baseline_align_frames);
  session->welcomed = true;
  session->wants_udp = hello.transport == wire::Transport::udp;
  session->bytes_per_s = static_cast<double>(hello.bandwidth_bps) / 8.0;
  session->udp_bucket = TokenBucket(session->bytes_per_s, std::max(0.25 * session->bytes_per_s, 2.0 * protocol::kMaxDatagram),
                                    now.monotonic_s);
  session->link->set_rate(session->bytes_per_s);
  session->cookie = mint_cookie(host_.cookie_key, session->id, cookie_endpoint(session->link->address()), now.unix_ms,
                                options_.cookie_lifetime_ms);
  send_control(*session, protocol::encode(welcome(*session)));
  for (const AnnouncedScene& later : scenes_.after(tick_)) send_control(*session, protocol::encode(scene_update(later, 0)));
  if (session->closed) return;  // a full control queue closed it: nothing to serve
  sessions_.insert(session);
  host_.metrics.sessions_started.inc();
  log_connect(session->id, session->wants_udp ? "udp" : session->link->transport(), session->peer(), stream->profile().name);
  update_client_gauges();
  // The key follows on the next key tick of the profile, shared by everyone who joined since.
}

protocol::Welcome SessionCore::welcome(const Session& session) const {
  protocol::Welcome welcome;
  welcome.session_id = session.id;
  const AnnouncedScene& scene = scenes_.in_force(tick_);
  welcome.stream = codec::wire_stream(session.stream->config());
  welcome.scene = scene.scene;
  welcome.stream.depth_m = model::wire_depth(welcome.scene.depth_m);  // the depth in force now; SceneUpdates carry later ones
  welcome.scene_serial = scene.serial;
  for (const auto& s : streams_) welcome.offered_profiles.push_back(s->profile().id);
  welcome.epoch_unix_ms = host_.config.epoch_unix_ms;
  welcome.current_tick = tick_;
  welcome.tick_period_s = 1.0 / host_.config.tick_rate_hz;
  if (session.wants_udp) {
    welcome.udp_port = host_.udp_port;
    welcome.udp_cookie.assign(session.cookie.begin(), session.cookie.end());
  }
  welcome.max_message_bytes = protocol::kDefaultMaxMessageBytes;
  if (session.stream->config().has_wake()) welcome.vessels = vessels_;
  return welcome;
}

void SessionCore::update_client_gauges() {
  for (const auto& stream : streams_) {
    // Every transport the server offers starts at 0, so that the last viewer of one leaving sets it
    // back to 0 (a transport missing here kept its last count for good).
    std::map<std::string_view, double> by_transport{{"udp", 0.0}};
    for (const StreamTransport& transport : stream_transports())
      if (listen_address(transport, host_.config)) by_transport[transport.name] = 0.0;
    for (const auto& session : sessions_)
      if (session->stream == stream.get()) by_transport[session->transport()] += 1.0;
    for (const auto& [transport, count] : by_transport) host_.metrics.clients(stream->profile().name, transport).set(count);
  }
}

void SessionCore::stop() {
  stopping_ = true;
  for (const auto& session : sessions_.snapshot()) end(*session, wire::ByeReason::server_shutdown, "server shutting down");
  const std::vector<std::shared_ptr<Session>> handshaking = handshaking_;  // close() erases from it
  for (const auto& session : handshaking) session->link->close("server_shutdown");
}

void SessionCore::abort(const std::string& reason) {
  stopping_ = true;
  std::vector<std::shared_ptr<Session>> all = handshaking_;  // close() erases from both
  for (const auto& session : sessions_) all.push_back(session);
  for (const auto& session : all) session->link->close(reason);
}

}  // namespace ocean::server
