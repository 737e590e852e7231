#include "server.hpp"

#include "server_log.hpp"

#include <asio/post.hpp>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <sys/resource.h>
#include <sys/socket.h>

namespace ocean::server {
namespace {

std::vector<const Profile*> offered_profiles(const ServerConfig& config) {
  std::vector<const Profile*> profiles;
  for (const std::string& name : config.profiles)
    if (const Profile* profile = find_profile(std::string_view(name))) profiles.push_back(profile);
  return profiles;
}

CookieKey cookie_key_from(const ServerConfig& config) {
  if (config.cookie_key.size() != kCookieKeyBytes) return random_cookie_key();
  CookieKey key;
  std::copy(config.cookie_key.begin(), config.cookie_key.end(), key.begin());
  return key;
}

asio::ip::udp::socket open_udp_socket(asio::io_context& context, const ListenAddress& address) {
  const asio::ip::udp::endpoint endpoint(asio::ip::make_address(address.host), address.port);
  asio::ip::udp::socket socket(context);
  std::error_code error;
  socket.open(endpoint.protocol(), error);
  if (!error) socket.bind(endpoint, error);
  if (error) throw std::system_error(error, "cannot bind UDP on " + address.to_string());
  // Every client's acks arrive on this one socket (30 a second each): a deep buffer rides out a
  // network thread that was descheduled for a moment instead of dropping acks (capped by the
  // kernel's net.core.rmem_max; failure is not fatal).
  socket.set_option(asio::socket_base::receive_buffer_size(kUdpSocketBufferBytes), error);
  socket.set_option(asio::socket_base::send_buffer_size(kUdpSocketBufferBytes), error);
  return socket;
}

SceneSchedule checked_schedule(const ServerConfig& config) {
  std::string error;
  SceneSchedule schedule = make_schedule(config, error);
  if (error.empty()) error = schedule.validate();
  if (!error.empty()) throw std::invalid_argument("schedule: " + error);
  return schedule;
}

// The configured UDP address, or the TCP host on the port TCP actually got.
ListenAddress udp_address(const ServerConfig& config, std::uint16_t tcp_port) {
  return config.udp_listen ? *config.udp_listen : ListenAddress{config.listen.host, tcp_port};
}

// --tls-cert and --tls-key, read now: a missing file or a key that is not the certificate's is a
// bad option (exit 2), found before any listener opens.
std::optional<TlsCredentials> tls_from(const ServerConfig& config) {
  if (config.tls_cert.empty()) return std::nullopt;
  std::string error;
  auto credentials = TlsCredentials::load(config.tls_cert, config.tls_key, error);
  if (!credentials) throw std::invalid_argument(error);
  return credentials;
}

}  // namespace

Server::Server(ServerConfig config)
    : config_(std::move(config)),
      tls_(tls_from(config_)),
      signals_(context_, SIGINT, SIGTERM, SIGHUP),
      metrics_(registry_),
      cookie_key_(cookie_key_from(config_)),
      schedule_(checked_schedule(config_)),
      producer_(schedule_, offered_profiles(config_),
                WakeSetup{config_.wake_size_m, config_.wake_origin_x_m, config_.wake_origin_z_m, config_.wake_decay_per_s,
                          config_.vessels, config_.tick_rate_hz, config_.wake_always}),
      tick_loop_(TickClock(config_.tick_rate_hz, config_.epoch_unix_ms),
                 [this](const TickDecision& decision) { on_tick(decision); }) {
  open_listeners();  // first: an address in use is told before the simulation is built
  // Fail now, with the option to change, rather than on the simulation thread at the first tick.
  const TickClock& clock = tick_loop_.clock();
  const double now_s = clock.sim_time_s(clock.tick_at(system_unix_ns()));
  if (!(std::fabs(now_s) <= kMaxSimTimeS))
    throw std::invalid_argument("--epoch " + std::to_string(config_.epoch_unix_ms) + ": the current time is " +
                                std::to_string(now_s) + " s from it; the simulation accepts at most " +
                                std::to_string(kMaxSimTimeS) + " s, so choose an epoch within ~31 years of now");
  // Builds the per-profile band evaluators before the first deadline (and surfaces any ParamError).
  (void)producer_.produce(clock.tick_at(system_unix_ns()), now_s);
  {
    asio::ip::udp::socket socket = open_udp_beside_tcp();
    udp_port_ = socket.local_endpoint().port();
    socket.non_blocking(true);  // a full socket buffer drops a datagram rather than stall the network thread
    udp_ = std::make_unique<DatagramPort>(context_, std::move(socket),
                                          [this](std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& from) {
                                            on_datagram(bytes, from);
                                          });
  }
  if (config_.metrics_listen) {
    metrics_http_ = std::make_unique<HttpServer>(http_context_, *config_.metrics_listen,
                                                        [this](const HttpRequest& r) { return handle_http(r); });
    metrics_port_ = metrics_http_->local_endpoint().port();
    metrics_http_->set_refused_callback([this](std::string_view reason, const std::string& peer) {
      metrics_.rejects(reason).inc();
      log_limited(spdlog::level::info, reason, peer, "reject transport=http peer={} reason={}", peer, reason);
    });
  }
  if (config_.web_listen) {
    const std::string root = config_.web_root.empty() ? default_web_root() : config_.web_root;
    if (root.empty())
      throw std::invalid_argument("--web-listen: no browser viewer found (build it with -DOCEAN_BUILD_WEB=ON, or give --web-root DIR)");
    std::string error;
    web_files_ = WebFiles::load(root, ws_port().value_or(0), error);
    if (!web_files_) throw std::invalid_argument(error);
    web_http_ = std::make_unique<HttpServer>(
        http_context_, *config_.web_listen, [this](const HttpRequest& r) { return web_files_->reply(r); },
        WebFiles::kMaxConnections, "web page");
    if (tls_) web_http_->set_tls([this] { return tls_->current(); });
    web_port_ = web_http_->local_endpoint().port();
    web_http_->set_refused_callback([this](std::string_view reason, const std::string& peer) {
      metrics_.rejects(reason).inc();
      log_limited(spdlog::level::info, reason, peer, "reject transport=web peer={} reason={}", peer, reason);
    });
  }
  for (const Profile* profile : offered_profiles(config_)) {
    metrics_.frames_computed(profile->name);
    metrics_.clients(profile->name, "udp");
    for (const auto& listener : listeners_) metrics_.clients(profile->name, listener->transport.name);
  }
  set_log_suppressed_hook([this](std::string_view reason) { metrics_.log_suppressed(reason).inc(); });
  do_await_stop();
}

// UDP shares the TCP port unless --udp-listen says otherwise. When the kernel picked that port
// (--listen HOST:0) it was free for TCP only: some other socket may hold it for UDP (a client's
// ephemeral port), so the server picks again rather than fail on a port nobody asked for.
asio::ip::udp::socket Server::open_udp_beside_tcp() {
  const bool kernel_picked = config_.listen.port == 0 && !config_.udp_listen;
  for (int attempt = 1;; ++attempt) {
    try {
      return open_udp_socket(context_, udp_address(config_, tcp_port()));
    } catch (const std::system_error& e) {
      if (!kernel_picked || e.code() != asio::error::address_in_use || attempt == 16) throw;
    }
    listeners_.front() = std::make_unique<Listener>(context_, stream_transports().front(), config_.listen);
  }
}

// "listening tcp=H:P udp=H:P ws=H:P|off metrics=... web=...[ tls=on]": tests and scripts read the ports here.
std::string Server::listening_line() const {
  const auto at = [](const ListenAddress* address, std::optional<std::uint16_t> port) {
    return address && port ? address->host + ":" + std::to_string(*port) : std::string("off");
  };
  const std::span<const StreamTransport> transports = stream_transports();
  std::string line = "listening " + std::string(transports.front().name) + "=" + at(&config_.listen, tcp_port());
  line += " udp=" + udp_address(config_, tcp_port()).host + ":" + std::to_string(udp_port_);
  for (const StreamTransport& t : transports.subspan(1)) {
    line += ' ';
    line += t.name;
    line += '=';
    line += at(listen_address(t, config_), port_of(t.name));
  }
  line += " metrics=" + at(config_.metrics_listen ? &*config_.metrics_listen : nullptr, metrics_port_);
  line += " web=" + at(config_.web_listen ? &*config_.web_listen : nullptr, web_http_ ? std::optional(web_port_) : std::nullopt);
  if (tls_) line += " tls=on";  // the page is https and the WebSocket wss
  return line;
}

Server::~Server() {
  {
    std::lock_guard lock(run_mutex_);
    run_returned_ = true;
  }
  run_returned_cv_.notify_all();
  if (stop_watchdog_.joinable()) stop_watchdog_.join();
  stop_http();
  set_log_suppressed_hook({});
  tick_loop_.stop();
}

void Server::run() {
  spdlog::info("{}", listening_line());
  tick_loop_.start();
  if (metrics_http_) metrics_http_->start();
  if (web_http_) web_http_->start();
  if (metrics_http_ || web_http_) http_thread_ = std::thread([this] { http_context_.run(); });
  for (const auto& listener : listeners_) do_accept(*listener);
  udp_->start();
  context_.run();
  stop_http();
  {
    std::lock_guard lock(run_mutex_);
    run_returned_ = true;
  }
  run_returned_cv_.notify_all();
  if (stop_watchdog_.joinable()) stop_watchdog_.join();
  tick_loop_.stop();
  spdlog::info("stopped");
}

void Server::stop() {
  asio::post(context_, [this] { do_stop(); });
}

void Server::do_await_stop() {
  signals_.async_wait([this](std::error_code error, int signal_number) {
    if (error) return;  // cancelled by do_stop
    if (signal_number == SIGHUP) {
      // Tools and operators send it expecting a reload, or nothing; it must never stop a server.
      // The TLS certificate is read again (a renewal); every other setting is read at start only.
      metrics_.sighups.inc();
      if (!tls_) {
        spdlog::info("signal SIGHUP received: nothing to reload (the configuration is read at start; restart the "
                     "server to change it); still serving");
      } else if (const std::string error = tls_->reload(); error.empty()) {
        spdlog::info("signal SIGHUP received: --tls-cert '{}' read again, in force for new connections; the rest "
                     "of the configuration is read at start only; still serving", tls_->cert_file());
      } else {
        metrics_.tls_reload_failures.inc();
        spdlog::error("signal SIGHUP received: {}; the certificate in force stays; still serving", error);
      }
      return do_await_stop();
    }
    spdlog::info("signal {} received, shutting down", signal_number == SIGINT ? "SIGINT" : "SIGTERM");
    do_stop();
  });
}

void Server::do_stop() {
  if (stopping_) return;
  stopping_ = true;
  std::error_code ignored;
  signals_.cancel(ignored);
  for (const auto& listener : listeners_) {
    listener->acceptor.close(ignored);
    listener->backoff.cancel();
  }
  udp_->close();
  if (metrics_http_) asio::post(http_context_, [this] { metrics_http_->stop(); });
  if (web_http_) asio::post(http_context_, [this] { web_http_->stop(); });
  tick_loop_.stop();  // joins the simulation thread; frames it already queued are drained below
  if (stop_handler_) stop_handler_();  // sessions say Bye while the context still runs
  // A client that reads slowly (or a network thread far behind) must not hold the exit.
  stop_watchdog_ = std::thread([this] {
    std::unique_lock lock(run_mutex_);
    if (run_returned_cv_.wait_for(lock, std::chrono::duration<double>(kStopGraceS), [this] { return run_returned_; })) return;
    spdlog::warn("shutdown: goodbyes not flushed within {} s; closing every connection", kStopGraceS);
    context_.stop();
  });
}

void Server::on_datagram(std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& from) {
  if (datagram_handler_) {
    datagram_handler_(bytes, from);
  } else {
    log_reject("udp", peer_text(from), "udp_no_session", true);
    metrics_.rejects("udp_no_session").inc();
  }
}

void Server::request_scene(const model::SceneParams& scene, std::int64_t from) {
  std::lock_guard lock(scene_request_mutex_);
  ++requests_made_;
  scene_requests_.emplace_back(scene, from);
}

void Server::request_vessels(const std::vector<model::VesselTrack>& vessels, std::int64_t from) {
  std::lock_guard lock(scene_request_mutex_);
  ++requests_made_;
  vessel_requests_.emplace_back(vessels, from);
}

bool Server::send_datagram(std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& to) {
  if (!udp_->is_open()) return false;
  return ::sendto(udp_->fd(), bytes.data(), bytes.size(), MSG_DONTWAIT, to.data(), to.size()) >= 0;
}

void Server::send_shared(const SharedBytes& bytes, const asio::ip::udp::endpoint& to) {
  if (udp_->is_open()) batch_.add(bytes, to, udp_->fd());
}

void Server::flush() {
  if (!udp_->is_open()) return;
  const std::uint64_t dropped = batch_.dropped();
  batch_.flush(udp_->fd());
  if (batch_.dropped() > dropped) metrics_.udp_send_drops.inc(static_cast<double>(batch_.dropped() - dropped));
}

void Server::on_tick(const TickDecision& decision) {
  const auto start = std::chrono::steady_clock::now();
  {
    std::lock_guard lock(scene_request_mutex_);
    for (const auto& [scene, from] : scene_requests_) producer_.override_scene(scene, from);
    scene_requests_.clear();
    for (auto& [vessels, from] : vessel_requests_) producer_.set_vessels(std::move(vessels), from);
    vessel_requests_.clear();
  }
  const double time_s = tick_loop_.clock().sim_time_s(decision.tick);
  std::shared_ptr<const TickFrames> frames = producer_.produce(decision.tick, time_s);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;

  if (producer_.scene_changed()) {
    metrics_.scene_changes.inc();
    spdlog::info("tick {}: scene change applied (wind {} m/s towards {} deg)", decision.tick,
                 producer_.scene().wind_speed_mps, producer_.scene().wind_dir_deg);
  }
  metrics_.ticks.inc();
  metrics_.current_tick.set(static_cast<double>(decision.tick));
  metrics_.tick_seconds.observe(elapsed.count());
  if (decision.late) metrics_.ticks_late.inc();
  if (decision.skipped > 0) {
    metrics_.ticks_skipped.inc(static_cast<double>(decision.skipped));
    spdlog::warn("tick {}: {} ticks skipped, the simulation fell behind", decision.tick, decision.skipped);
  }
  for (const ProfileFrame& frame : frames->frames) metrics_.frames_computed(frame.profile->name).inc();

  const auto pushed = frames_.push(std::move(frames));
  if (pushed.dropped) metrics_.frames_dropped.inc();
  if (pushed.was_empty) asio::post(context_, [this] { drain_frames(); });
}

void Server::stop_http() {
  if (!http_thread_.joinable()) return;
  if (metrics_http_) asio::post(http_context_, [this] { metrics_http_->stop(); });
  if (web_http_) asio::post(http_context_, [this] { web_http_->stop(); });
  http_context_.stop();
  http_thread_.join();
}

namespace {
std::int64_t steady_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
// /healthz fails when the network thread served no tick for this long (it serves ~30 a second).
constexpr std::int64_t kStalledMs = 5000;
}  // namespace

// One tick per handler: a network thread slower than the ticks would otherwise find a new one
// queued after each and never return to the loop, and a signal, an ack or an accept would wait
// behind every tick to come (a SIGTERM went unanswered for over 10 s that way under ASan).
void Server::drain_frames() {
  if (std::optional<std::shared_ptr<const TickFrames>> frames = frames_.pop()) {
    ready_.store(true);
    if (frame_sink_) frame_sink_(*frames);
    heartbeat_ms_.store(steady_ms());
  }
  // A push into an empty queue posts a drain itself; one into a non-empty queue relies on this.
  if (frames_.size() > 0) asio::post(context_, [this] { drain_frames(); });
  flush_log_summary();
}

HttpReply Server::handle_http(const HttpRequest& request) {
  if (request.target == "/metrics") {
    metrics_.update_process();
    return {200, "text/plain; version=0.0.4; charset=utf-8", registry_.render()};
  }
  if (request.target == "/healthz") {
    const std::int64_t beat = heartbeat_ms_.load();
    if (beat != 0 && steady_ms() - beat > kStalledMs)
      return {503, "text/plain; charset=utf-8",
              "stalled: the network thread served no tick for " + std::to_string((steady_ms() - beat) / 1000) + " s\n"};
    return {200, "text/plain; charset=utf-8", "ok\n"};
  }
  if (request.target == "/readyz") {
    if (!ready_.load()) return {503, "text/plain; charset=utf-8", "starting\n"};
    std::lock_guard lock(readiness_mutex_);
    const std::string why_not = readiness_check_ ? readiness_check_() : std::string();
    return why_not.empty() ? HttpReply{200, "text/plain; charset=utf-8", "ready\n"}
                           : HttpReply{503, "text/plain; charset=utf-8", why_not + "\n"};
  }
  return {404, "text/plain; charset=utf-8", "not found; try /metrics, /healthz or /readyz\n"};
}

}  // namespace ocean::server
