// SessionCore: every client session of a server, the mirror of the client's ClientSession: pure
// (bytes and instants in; bytes out through Links, events out through observers and metrics),
// so tests drive it directly and any transport plugs in as a Link.
// It answers the handshake, proves UDP addresses with stateless cookies, applies admin changes,
// and each tick feeds one ProfileStream per offered profile and sends every session a key or a
// delta against its baseline, sharing encodings between sessions; keyframe requests, timeouts and
// Bye on stop. Single-threaded: the caller serialises every call.
#pragma once

#include "tick_frames.hpp"
#include "admission.hpp"
#include "bundle_key.hpp"
#include "keying_policy.hpp"
#include "link.hpp"
#include "message_types.hpp"
#include "profile_stream.hpp"
#include "scene_announcements.hpp"
#include "server_config.hpp"
#include "server_metrics.hpp"
#include "session.hpp"
#include "session_table.hpp"
#include "timeline_change.hpp"
#include "udp_cookie.hpp"
#include "wire_limits.hpp"

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <unordered_map>
#include <variant>
#include <vector>

namespace ocean::server {

struct SessionCoreOptions {
  std::size_t send_queue_bytes = 1u << 20;     // per session; frames beyond it are dropped
  double key_interval_s = 1.0;                 // at most one requested or re-sync key per second
  std::int64_t cookie_lifetime_ms = 3'600'000; // a UdpHello may (re)prove the address this long
  int socket_send_buffer_bytes = 0;            // SO_SNDBUF of client sockets; 0 = the OS default
  // Sharing (README-server.md "Fan-out"): baselines on a grid of this many frames; keys only on
  // a grid of this period; beyond its root cap (KeyingPolicy::root_cap), the smallest roots of a profile older
  // than root_merge_age_s are keyed again onto the current one. The cap is max_roots, or fewer for
  // a profile whose roots together would synthesize more than root_samples_per_tick grid samples
  // a tick (a desktop root, 256 x 256, costs about 6 ms a tick), but never fewer than 2; and while
  // one more root would exceed that budget, a joiner waits (at most about root_merge_age_s).
  std::uint32_t baseline_align_frames = 4;
  double key_period_s = 0.5;
  std::size_t max_roots = 4;
  double root_merge_age_s = 2.0;
  double root_samples_per_tick = 131072.0;
  // A scene change reaches every client this long before it takes effect (a SceneUpdate on TCP
  // must arrive before the first frame of the new scene, even on a slow link).
  double scene_lead_s = 1.0;
  // Load budgets (README-server.md "Overload"): key bytes per second over all sessions (burst:
  // half a second of it), and distinct delta encodes per profile and tick.
  double key_bytes_per_s = 2'000'000.0;
  std::size_t max_encodes_per_tick = 64;
  // A proven UDP address moves to another port only after this long without a valid datagram
  // from it (a replayed UdpHello cannot take a live stream; a NAT rebinding still moves it).
  // Each time the old address speaks again and takes its stream back, the session's next move
  // waits four times as long, up to udp_rebind_quiet_max_s.
  double udp_rebind_quiet_s = 0.5;
  double udp_rebind_quiet_max_s = 60.0;
  // ParamChanges with a wrong admin token a connection may send before it is closed.
  int token_failures_per_connection = 3;
  // Admin tokens looked at per second over all connections (and its burst), first come first
  // served: however many addresses guess, they guess this fast together, and a right token waits
  // its turn instead of being refused with them. Applied changes per second (and burst): each one
  // rebuilds every stream's scene model and sends every viewer a SceneUpdate.
  double token_checks_per_s = 5.0;
  double token_check_burst = 10.0;
  double scene_changes_per_s = 1.0;
  double scene_change_burst = 4.0;
  // HeightQuery (PROTOCOL.md 8): answered per connection at most this often (and burst); refused
  // beyond, and a connection refused as often again (it ignores the waits) is closed.
  // Points answered per second over every connection (and burst): about 0.1 us each on one core.
  double height_queries_per_s = 60.0;
  double height_query_burst = 30.0;
  double query_points_per_s = 1'000'000.0;
  double query_point_burst = 200'000.0;
};

// What the core needs from the server around it; none of it a socket or a clock.
struct SessionCoreHost {
  const ServerConfig& config;
  const SceneSchedule& schedule;
  ServerMetrics& metrics;
  const CookieKey& cookie_key;
  DatagramSocket& datagrams;
  std::uint16_t udp_port = 0;  // announced in the Welcome
  // An accepted admin change: the simulation switches to `scene` at tick `from`.
  std::function<void(const model::SceneParams& scene, std::int64_t from)> request_scene;
  // An accepted vessel command: the simulation's fleet from tick `from` on.
  std::function<void(const std::vector<model::VesselTrack>& vessels, std::int64_t from)> request_vessels = nullptr;
  // With a fleet timeline (--timeline): an accepted change goes to its log, stamped with its tick,
  // and is applied when the log hands it back (apply_logged), here as on every other replica.
  // timeline_origin tells this replica's own entries from the others'.
  std::function<void(TimelineChange change)> propose = nullptr;
  std::uint64_t timeline_origin = 0;
};

// What the last tick did, for metrics and tests.
struct CoreTickStats {
  Tick tick = 0;
  std::size_t sessions_served = 0;     // sessions sent a frame this tick
  std::size_t encodes = 0;             // encoder runs this tick, all profiles
  std::size_t distinct_baselines = 0;  // distinct (profile, baseline or key) among those sessions
};

class SessionCore {
 public:
  // Called for every frame queued to a session, after its links have it: a client on another
  // thread may complete the frame first (tests compare reconstructions with it).
  using FrameObserver = std::function<void(std::uint64_t session_id, const SharedFrame& frame)>;
  using TickObserver = std::function<void(const CoreTickStats& stats)>;

  // start_tick: the tick now (a Hello may come before the first frames).
  SessionCore(SessionCoreHost host, SessionCoreOptions options, Tick start_tick);
  SessionCore(const SessionCore&) = delete;
  SessionCore& operator=(const SessionCore&) = delete;

  // A new connection of any stream transport; the core starts reading it.
  void open(std::shared_ptr<StreamLink> link, const Instant& now);
  // One datagram that arrived on the server's UDP socket.
  void on_datagram(std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& sender, const Instant& now);
  // The frames of one tick, from the simulation.
  void on_frames(const std::shared_ptr<const TickFrames>& frames, const Instant& now);
  // Shutdown: Bye to every session; no frames after this.
  void stop();
  // Closes every link now, without a goodbye (the process is going away); no frames after this.
  void abort(const std::string& reason);
  // The sessions the host can serve (its measured capacity, AdmissionBudget): a Hello beyond it
  // is refused as server_full with a retry hint; admitted sessions keep their service.
  void set_session_limit(std::size_t limit) { session_limit_ = limit; }

  // The fleet timeline's entry `index`, in log order: announced and applied at its tick, its admin
  // answered when this replica took it. `history`: read before the first tick is served (the log
  // as it stood when this replica started): an entry whose tick has passed sets the sea from that
  // tick. Read later, such an entry is late: applied as well, counted, and every session keyed
  // again (last_late_entry() names the newest).
  void apply_logged(std::uint64_t index, const TimelineChange& change, bool history = false);
  // A change this replica took that its log refused or never confirmed: its admin is told why.
  void refuse_logged(const TimelineChange& change, const std::string& reason);
  std::optional<std::uint64_t> last_late_entry() const { return last_late_entry_; }
  // While set, ticks feed the encoders and the clocks but no session is served a frame (the fleet
  // timeline's hold: what this replica would stream may not be the log's sea).
  void set_holding(bool holding) { holding_ = holding; }

  void set_frame_observer(FrameObserver observer) { observer_ = std::move(observer); }
  void set_tick_observer(TickObserver observer) { tick_observer_ = std::move(observer); }
  const SessionCoreOptions& options() const { return options_; }
  const CoreTickStats& last_tick() const { return last_tick_; }
  std::size_t session_count() const { return sessions_.size(); }
  // Times a stream nobody receives dropped its encoder states (then the server may hand the
  // memory back to the system).
  std::uint64_t streams_released() const { return streams_released_; }
  const Admission& admission() const { return admission_; }
  std::size_t max_queued_bytes() const;  // over all sessions, now
  std::size_t peak_queued_bytes() const; // over all sessions, ever (closed ones included)
  // Before proof, the UDP bytes received and answered (anti-amplification).
  std::uint64_t unproven_bytes_in() const { return unproven_bytes_in_; }
  std::uint64_t unproven_bytes_out() const { return unproven_bytes_out_; }
  const std::vector<std::unique_ptr<ProfileStream>>& streams() const { return streams_; }

 private:
  void on_message(const std::shared_ptr<Session>& session, std::span<const std::uint8_t> bytes, const Instant& now);
  void on_closed(const std::shared_ptr<Session>& session, const std::string& reason);
  void evict_oldest_handshake(const Session& newcomer, const std::string& limit);
  void on_hello(const std::shared_ptr<Session>& session, const wire::Hello& hello, const Instant& now);
  // Admin ParamChanges (core_admin.cpp): queued for their token check, checked at the admin rate
  // first come first served, applied at the change rate.
  void on_param_change(const std::shared_ptr<Session>& session, const wire::ParamChange& change, const Instant& now);
  void check_admin_changes(const Instant& now);
  bool token_refused(Session& session, const std::string& token, std::string_view message);
  std::optional<std::vector<model::VesselTrack>> fleet_after(Session& session, const protocol::VesselCommand& command,
                                                             Tick from);
  void apply_param_change(Session& session, const protocol::ParamChange& change, const Instant& now);
  // servable_scene over the profiles this server offers: "" or why one cannot carry the scene.
  std::string unservable(const model::SceneParams& scene) const;
  // Admin HeightQuery (core_queries.cpp): a connection's first right token passes the admin queue,
  // later queries with it are answered at once, at the query rate, from the newest tick's frames.
  void on_height_query(const std::shared_ptr<Session>& session, const wire::HeightQuery& query, const Instant& now);
  void answer_height_query(Session& session, const protocol::HeightQuery& query);
  bool query_rate_refused(Session& session, std::size_t points, const Instant& now);
  // Ack, KeyframeRequest and Ping mean the same on any transport; `reply` carries the Pong.
  void on_session_message(Session& session, const wire::Message& message, Link& reply, const Instant& now);
  void on_udp_hello(Session& session, const wire::Message& message, std::size_t datagram_bytes, bool proven,
                    const asio::ip::udp::endpoint& sender, const Instant& now);
  bool reclaim_udp(Session& session, const wire::Message& message, const asio::ip::udp::endpoint& sender);
  double rebind_quiet_s(const Session& session) const;

  void serve(Session& session, Tick tick, double now_s, std::vector<std::pair<const void*, codec::StateId>>& bases);
  void deliver(Session& session, Tick tick, const SharedFrame& frame, codec::StateId base, double now_s);
  void send_key(Session& session, ProfileStream& stream, Tick tick, double now_s);
  bool send_udp_frame(Session& session, Tick tick, const SharedFrame& frame, double now_s);
  void send_tcp_frame(Session& session, const SharedFrame& frame);
  bool tcp_frames_written(Session& session) const;
  const SharedBytes& bundle_of(const BundleKey& key);
  void publish_udp_tally();
  // Merges key roots beyond the cap; false when a new root would still exceed it (joiners wait).
  bool limit_roots(ProfileStream& stream, Tick tick, double now_s);
  void forget_unwatched_streams();  // once a second
  bool second_tick() const { return tick_ % static_cast<Tick>(host_.config.tick_rate_hz) == 0; }  // the first of each second
  bool is_key_tick(const ProfileStream& stream, Tick tick) const { return keying_.is_key_tick(keyed(stream), tick); }
  static KeyedStream keyed(const ProfileStream& stream);
  // A key interval has passed since the session's last key: a requested key may go out.
  bool key_due(const Session& session, double now_s) const { return now_s - session.last_key_s >= options_.key_interval_s; }
  void sweep_timeouts(double now_s);
  void record_tick_stats(std::vector<std::pair<const void*, codec::StateId>>& bases);
  // This tick's truth to a stream; values it must clamp are counted and logged.
  void add_truth(ProfileStream& stream, const sim::Frame& frame);
  // Tells every stream and every session of scenes that take effect within the lead.
  void announce(const std::vector<AnnouncedScene>& scenes, std::optional<std::uint64_t> requester = {},
                std::uint32_t request_id = 0);
  protocol::SceneUpdate scene_update(const AnnouncedScene& scene, std::uint32_t request_id) const;
  protocol::Welcome welcome(const Session& session) const;
  // Error{reason, text}, then close; counted as ocean_rejects_total{reason=label or the reason}.
  void refuse(Session& session, protocol::Reason reason, const std::string& text, std::string_view label = {});
  // Error{reason, text}, the connection kept (a request refused, not the client); counted as
  // refuse() counts, and logged at most a few times a second per address as "{what} refused ...".
  void answer_error(Session& session, protocol::Reason reason, const std::string& text, std::string_view what = {});
  void end(Session& session, wire::ByeReason reason, const std::string& text);
  void send_control(Session& session, protocol::Bytes bytes);
  void drop_datagram(protocol::Reason reason, const asio::ip::udp::endpoint& sender);
  void update_client_gauges();
  ProfileStream* choose_profile(std::uint8_t wanted, std::uint64_t bandwidth_bps) const;
  codec::StreamConfig stream_config(const Profile& profile, const model::SceneParams& scene) const;
  std::uint64_t new_session_id() const;

  SessionCoreHost host_;
  SessionCoreOptions options_;
  // The streams' scene models (the codec's arithmetic: no lock shared with the tick).
  std::shared_ptr<BuildQueue> builds_ = std::make_shared<BuildQueue>(kBackgroundNice);
  std::vector<std::unique_ptr<ProfileStream>> streams_;
  SessionTable sessions_;  // welcomed
  std::vector<std::shared_ptr<Session>> handshaking_;
  SceneAnnouncements scenes_;
  Admission admission_;
  Tick tick_ = 0;
  bool stopping_ = false;
  CoreTickStats last_tick_;
  FrameObserver observer_;
  TickObserver tick_observer_;
  std::array<Counter*, protocol::kReasonCount> datagram_rejects_{};  // by protocol::Reason, made up front: no allocation per datagram
  alignas(8) std::array<std::uint8_t, protocol::kMaxDatagram> datagram_{};
  std::unordered_map<BundleKey, SharedBytes, BundleKeyHash> bundles_;  // this tick's, by their chunks
  struct UdpTally {
    std::uint64_t frames = 0, bytes = 0, copies = 0;
  } udp_tally_;  // this tick's UDP frames, counted into the metrics once at its end
  std::uint64_t unproven_bytes_in_ = 0;
  std::uint64_t unproven_bytes_out_ = 0;
  std::size_t peak_closed_queued_bytes_ = 0;
  std::size_t session_limit_ = std::numeric_limits<std::size_t>::max();
  std::uint64_t rotate_from_ = 0;  // where this tick's walk over the sessions starts
  KeyingPolicy keying_;
  struct PendingChange {
    std::weak_ptr<Session> session;
    std::variant<protocol::ParamChange, protocol::HeightQuery> request;
  };
  std::deque<PendingChange> admin_queue_;  // one per connection at most, oldest first
  TokenBucket token_checks_;               // admin tokens looked at, all connections together
  TokenBucket scene_changes_;              // admin changes applied
  TokenBucket query_points_;               // HeightQuery points answered, all connections together
  // The newest tick's frames and the one before (a HeightQuery's heights and their rate of change).
  std::shared_ptr<const TickFrames> newest_frames_, previous_frames_;
  std::vector<model::VesselTrack> vessels_;  // the fleet, as the newest announcement leaves it
  std::optional<std::uint64_t> last_late_entry_;  // the newest timeline entry read after its tick
  bool holding_ = false;
  std::vector<const ProfileStream*> roots_full_;
  std::uint64_t streams_released_ = 0;  // this key tick: no new root, joiners wait
};

}  // namespace ocean::server
