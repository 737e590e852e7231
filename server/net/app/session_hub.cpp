#include "session_hub.hpp"

#include "server_log.hpp"
#include "tick_clock.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <malloc.h>
#include <random>

namespace ocean::server {

namespace {

Tick tick_now(const ServerConfig& config) {
  const std::int64_t tick = TickClock(config.tick_rate_hz, config.epoch_unix_ms).tick_at(system_unix_ns());
  return static_cast<Tick>(std::max<std::int64_t>(0, tick));
}

SessionCoreHost host_of(Server& server, std::function<void(TimelineChange)> propose, std::uint64_t origin) {
  return SessionCoreHost{server.config(), server.schedule(), server.metrics(), server.cookie_key(), server,
                         server.config().udp_public_port ? static_cast<std::uint16_t>(server.config().udp_public_port)
                                                         : server.udp_port(),
                         [&server](const model::SceneParams& scene, std::int64_t from) { server.request_scene(scene, from); },
                         [&server](const std::vector<model::VesselTrack>& vessels, std::int64_t from) {
                           server.request_vessels(vessels, from);
                         },
                         std::move(propose), origin};
}

std::uint64_t random_origin() {
  std::random_device random;
  return (static_cast<std::uint64_t>(random()) << 32 | random()) | 1;  // never 0
}

// A warning about overload at most this often.
constexpr double kWarnEvery_s = 10.0;

}  // namespace

SessionHub::SessionHub(Server& server, SessionCoreOptions options)
    : server_(server),
      timeline_origin_(random_origin()),
      core_(host_of(server,
                    server.config().timeline.empty() ? std::function<void(TimelineChange)>()
                                                     : [this](TimelineChange change) { timeline_->propose(std::move(change)); },
                    timeline_origin_),
            options, tick_now(server.config())),
      budget_(server.config().admission_target.value_or(AdmissionBudget::kDefaultTarget)),
      connect_rate_(server.config().connect_rate_per_ip, std::max(10.0, 2.0 * server.config().connect_rate_per_ip)),
      connect_rate_rejects_(server.metrics().rejects("connect_rate")) {
  server_.set_connection_handler(
      [this](asio::ip::tcp::socket socket, const StreamTransport& transport) { on_connection(std::move(socket), transport); });
  server_.set_datagram_handler([this](std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& sender) {
    const Instant now = now_instant();
    core_.on_datagram(bytes, sender, now);
    server_.flush();
    account(now_instant().monotonic_s - now.monotonic_s, now.monotonic_s);
  });
  server_.set_frame_sink([this](const std::shared_ptr<const TickFrames>& frames) { on_frames(frames); });
  server_.set_stop_handler([this] { core_.stop(); });
  if (!server.config().timeline.empty()) follow_timeline();
}

SessionHub::~SessionHub() { timeline_.reset(); }

void SessionHub::on_connection(asio::ip::tcp::socket socket, const StreamTransport& transport) {
  {
    std::error_code error;
    const asio::ip::tcp::endpoint peer = socket.remote_endpoint(error);
    if (error) return;  // gone already
    if (!connect_rate_.allow(peer.address(), now_instant().monotonic_s)) {
      // Closed before it costs a session: churn from one range stays cheap, and is not counted as
      // the cost of serving sessions (AdmissionBudget).
      connect_rate_rejects_.inc();
      log_reject(transport.name, peer.address().to_string(), "connect_rate");
      socket.close(error);
      return;
    }
  }
  if (const int bytes = core_.options().socket_send_buffer_bytes; bytes > 0) {
    std::error_code ignored;
    socket.set_option(asio::socket_base::send_buffer_size(bytes), ignored);
  }
  // A connection refused before its Hello (a failed handshake) never reaches the core: counted here.
  const TransportContext context{server_.config(), core_.options().send_queue_bytes, server_.web_port().value_or(0),
                                 server_.tls_context(),
                                 [this, name = transport.name](const std::string& reason, const std::string& peer) {
                                   server_.metrics().rejects(reason).inc();
                                   log_reject(name, peer, reason);
                                 }};
  core_.open(transport.open(std::move(socket), context), now_instant());
}

void SessionHub::on_frames(const std::shared_ptr<const TickFrames>& frames) {
  const Instant now = now_instant();
  const ServerConfig& config = server_.config();
  const double scheduled_s = static_cast<double>(config.epoch_unix_ms) / 1000.0 +
                             static_cast<double>(frames->tick) / static_cast<double>(config.tick_rate_hz);
  server_.metrics().loop_lag_seconds.observe(std::max(0.0, static_cast<double>(now.unix_ms) / 1000.0 - scheduled_s));
  core_.set_holding(timeline_holds(*frames));
  core_.on_frames(frames, now);
  server_.flush();
  // A desktop stream's states are about 1 MB each, hundreds while its viewers watched. Once the
  // stream is released they are free, and so, over the next seconds, are the queues and buffers
  // of its closing sessions; glibc keeps freed memory inside its heaps unless asked to hand it
  // back, so it is asked once a second for ten seconds after a release.
  const auto tick_rate = static_cast<std::int64_t>(config.tick_rate_hz);
  if (core_.streams_released() != streams_released_) {
    streams_released_ = core_.streams_released();
    trim_until_tick_ = frames->tick + 10 * tick_rate;
  }
  if (frames->tick <= trim_until_tick_ && frames->tick % tick_rate == 0) malloc_trim(0);
  if (timeline_ && frames->tick % tick_rate == 0) publish_timeline_metrics();
  const double served_s = now_instant().monotonic_s - now.monotonic_s;
  server_.metrics().serve_seconds.observe(served_s);
  window_session_ticks_ += static_cast<double>(core_.session_count());
  ++window_ticks_;
  account(served_s, now.monotonic_s);
}

void SessionHub::account(double busy_s, double now_s) {
  window_busy_s_ += busy_s;
  if (window_start_s_ == 0.0) {
    window_start_s_ = now_s;
    window_schedule_ = this_thread_schedule();
  }
  const double wall_s = now_s - window_start_s_;
  if (wall_s < 1.0 || window_ticks_ == 0) return;
  const double sessions = window_session_ticks_ / window_ticks_;
  // The kernel's figures count what timing the handlers misses: the thread's wait for its core
  // when another process or thread keeps it busy. Every tick is late then while the handlers
  // report little work (a busy loop beside the server: timed work 32 %, on time 39 %).
  LoadPeriod period{window_busy_s_, 0.0, wall_s, sessions, window_busy_s_};
  const std::optional<ThreadSchedule> schedule = this_thread_schedule();
  if (schedule && window_schedule_) {
    period.waited_s = std::max(0.0, schedule->waited_s - window_schedule_->waited_s);
    period.ran_s = std::max(0.0, schedule->ran_s - window_schedule_->ran_s);
  }
  window_schedule_ = schedule;
  budget_.observe(period);
  // --admission-target off: the load is still measured and shown, the door is --max-clients alone.
  const bool admitting_by_load = server_.config().admission_target.has_value();
  const std::size_t capacity = admitting_by_load ? budget_.capacity() : AdmissionBudget::kUnlimited;
  core_.set_session_limit(capacity);
  ServerMetrics& metrics = server_.metrics();
  metrics.network_busy_ratio.set(budget_.busy_share());
  metrics.network_cpu_wait_ratio.set(budget_.wait_share());
  metrics.admission_capacity.set(capacity == AdmissionBudget::kUnlimited ? 0.0 : static_cast<double>(capacity));
  const bool at_capacity = static_cast<std::size_t>(sessions) >= capacity;
  if ((at_capacity || budget_.over_target()) && now_s - last_warning_s_ >= kWarnEvery_s) {
    last_warning_s_ = now_s;
    if (admitting_by_load)
      spdlog::warn("overload: serving {:.0f} sessions, the network thread was {:.0f}% busy ({:.0f}% waiting for a "
                   "CPU); admitting at most {} (new clients beyond it are refused as server_full)",
                   sessions, 100.0 * budget_.busy_share(), 100.0 * budget_.wait_share(), capacity);
    else
      spdlog::warn("overload: serving {:.0f} sessions, the network thread was {:.0f}% busy ({:.0f}% waiting for a "
                   "CPU); --admission-target off: still admitting up to --max-clients",
                   sessions, 100.0 * budget_.busy_share(), 100.0 * budget_.wait_share());
  }
  window_start_s_ = now_s;
  window_busy_s_ = 0.0;
  window_session_ticks_ = 0.0;
  window_ticks_ = 0;
}

}  // namespace ocean::server
