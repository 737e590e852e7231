// SessionHub: every client session of a Server. Answers the TCP handshake, proves UDP addresses
// with stateless cookies, and each tick feeds one ProfileStream per offered profile and sends every
// session a key or a delta against its baseline, sharing encodings between sessions. Also admin
// parameter changes, keyframe requests, timeouts and Bye on shutdown. Network thread only.
#pragma once

#include "profile_stream.hpp"
#include "scene_announcements.hpp"
#include "server.hpp"
#include "session.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace ocean::server {

struct SessionHubOptions {
  std::size_t send_queue_bytes = 1u << 20;     // per session; frames beyond it are dropped
  double key_interval_s = 1.0;                 // at most one requested or re-sync key per second
  double handshake_timeout_s = 5.0;            // a connection must send its Hello within this
  std::int64_t cookie_lifetime_ms = 3'600'000; // a UdpHello may (re)prove the address this long
  int socket_send_buffer_bytes = 0;            // SO_SNDBUF of client sockets; 0 = the OS default
  // Sharing (README-server.md "Fan-out"): baselines on a grid of this many frames; keys only on
  // a grid of this period (a joiner waits at most this long); beyond max_roots key roots of a
  // profile, one root older than root_merge_age_s is keyed again per key tick.
  std::uint32_t baseline_align_frames = 4;
  double key_period_s = 0.5;
  std::size_t max_roots = 8;
  double root_merge_age_s = 10.0;
  // A scene change reaches every client this long before it takes effect (a SceneUpdate on TCP
  // must arrive before the first frame of the new scene, even on a slow link).
  double scene_lead_s = 1.0;
};

// What the last tick did, for metrics and tests.
struct HubTickStats {
  Tick tick = 0;
  std::size_t sessions_served = 0;     // sessions sent a frame this tick
  std::size_t encodes = 0;             // encoder runs this tick, all profiles
  std::size_t distinct_baselines = 0;  // distinct (profile, baseline or key) among those sessions
};

class SessionHub {
 public:
  // Called for every frame queued to a session (tests compare reconstructions with it).
  using FrameObserver = std::function<void(std::uint64_t session_id, const SharedFrame& frame)>;
  using TickObserver = std::function<void(const HubTickStats& stats)>;

  SessionHub(Server& server, SessionHubOptions options = {});
  SessionHub(const SessionHub&) = delete;
  SessionHub& operator=(const SessionHub&) = delete;

  void set_frame_observer(FrameObserver observer) { observer_ = std::move(observer); }
  void set_tick_observer(TickObserver observer) { tick_observer_ = std::move(observer); }
  const HubTickStats& last_tick() const { return last_tick_; }
  std::size_t session_count() const { return sessions_.size(); }
  std::size_t max_queued_bytes() const;  // over all sessions, now
  std::size_t peak_queued_bytes() const; // over all sessions, ever (closed ones included)
  // Before proof, the UDP bytes received and answered (anti-amplification).
  std::uint64_t unproven_bytes_in() const { return unproven_bytes_in_; }
  std::uint64_t unproven_bytes_out() const { return unproven_bytes_out_; }
  const std::vector<std::unique_ptr<ProfileStream>>& streams() const { return streams_; }

 private:
  void on_connection(asio::ip::tcp::socket socket);
  void on_tcp_message(const std::shared_ptr<Session>& session, std::span<const std::uint8_t> bytes);
  void on_hello(const std::shared_ptr<Session>& session, const wire::Hello& hello);
  void on_param_change(const std::shared_ptr<Session>& session, const wire::ParamChange& change);
  void on_datagram(std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& sender);
  void on_frames(const std::shared_ptr<const TickFrames>& frames);
  void on_stop();

  void serve(Session& session, Tick tick, double now_s, std::vector<std::pair<const void*, codec::StateId>>& bases);
  bool send_udp_frame(Session& session, Tick tick, const SharedFrame& frame, double now_s);
  SharedBytes bundle_of(const std::vector<const RecentFrame*>& copies, const SharedFrame& newest);
  void limit_roots(ProfileStream& stream, Tick tick);
  bool is_key_tick(const ProfileStream& stream, Tick tick) const;
  void sweep_timeouts(double now_s);
  // Tells every stream and every session of scenes that take effect within the lead.
  void announce(const std::vector<AnnouncedScene>& scenes, std::optional<std::uint64_t> requester = {},
                std::uint32_t request_id = 0);
  protocol::SceneUpdate scene_update(const AnnouncedScene& scene, std::uint32_t request_id) const;
  void refuse(Session& session, protocol::Reason reason, const std::string& text);
  void end(Session& session, wire::ByeReason reason, const std::string& text);
  void send_control(Session& session, protocol::Bytes bytes);
  void drop_datagram(protocol::Reason reason, const asio::ip::udp::endpoint& sender);
  void update_client_gauges();
  ProfileStream* choose_profile(std::uint8_t wanted, std::uint64_t bandwidth_bps) const;
  codec::StreamConfig stream_config(const Profile& profile, const sim::SceneParams& scene) const;
  std::uint64_t new_session_id() const;

  Server& server_;
  SessionHubOptions options_;
  std::vector<std::unique_ptr<ProfileStream>> streams_;
  std::map<std::uint64_t, std::shared_ptr<Session>> sessions_;  // welcomed, by id
  std::vector<std::shared_ptr<Session>> handshaking_;
  SceneAnnouncements scenes_;
  Tick tick_ = 0;
  bool have_tick_ = false;
  bool stopping_ = false;
  HubTickStats last_tick_;
  FrameObserver observer_;
  TickObserver tick_observer_;
  std::array<Counter*, 29> datagram_rejects_{};  // by protocol::Reason, made up front: no allocation per datagram
  alignas(8) std::array<std::uint8_t, protocol::kMaxDatagram> datagram_{};
  std::map<std::vector<const codec::Chunk*>, SharedBytes> bundles_;  // this tick's, by their chunks
  std::uint64_t unproven_bytes_in_ = 0;
  std::uint64_t unproven_bytes_out_ = 0;
  std::size_t peak_closed_queued_bytes_ = 0;
};

}  // namespace ocean::server
