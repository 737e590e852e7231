// Server: owns the network io_context and everything on it (signals, the client TCP acceptor and
// UDP socket, the metrics endpoint) plus the tick loop on its own simulation thread. Frames reach
// the network thread through a small queue; the session hub plugs in through the frame, connection,
// datagram and stop handlers.
#pragma once

#include "bounded_queue.hpp"
#include "datagram_batch.hpp"
#include "datagram_port.hpp"
#include "frame_producer.hpp"
#include "link.hpp"
#include "metrics.hpp"
#include "http_server.hpp"
#include "server_config.hpp"
#include "server_metrics.hpp"
#include "stream_transport.hpp"
#include "tick_loop.hpp"
#include "tls_credentials.hpp"
#include "udp_cookie.hpp"
#include "web_files.hpp"

#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <asio/ip/udp.hpp>
#include <asio/signal_set.hpp>
#include <asio/steady_timer.hpp>

#include <array>
#include <atomic>
#include <condition_variable>
#include <thread>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>
#include <span>
#include <string>
#include <string_view>

namespace ocean::server {

// SO_RCVBUF and SO_SNDBUF asked for the UDP socket (the kernel caps them at net.core.*mem_max).
inline constexpr int kUdpSocketBufferBytes = 4 << 20;
// Descriptors kept free for the metrics endpoint, the log and the UDP socket: a client
// connection that would leave fewer is closed at once, so /healthz stays answerable.
inline constexpr long kReserveDescriptors = 16;
// After SIGTERM, sessions have this long to flush their Bye before every link is closed.
inline constexpr double kStopGraceS = 1.5;

class Server : public DatagramSocket {
 public:
  // All run on the network thread.
  using FrameSink = std::function<void(const std::shared_ptr<const TickFrames>&)>;
  // A connection accepted by the listener of `transport` (stream_transport.hpp).
  using ConnectionHandler = std::function<void(asio::ip::tcp::socket, const StreamTransport& transport)>;
  using DatagramHandler = std::function<void(std::span<const std::uint8_t>, const asio::ip::udp::endpoint&)>;
  using StopHandler = std::function<void()>;

  // Binds every socket and builds the simulation; throws std::system_error (address in use...)
  // or model::ParamError. The config must have passed validate_server_config.
  explicit Server(ServerConfig config);
  ~Server() override;
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Until then, accepted connections and datagrams are refused with a logged reason.
  void set_frame_sink(FrameSink sink) { frame_sink_ = std::move(sink); }
  void set_connection_handler(ConnectionHandler handler) { connection_handler_ = std::move(handler); }
  void set_datagram_handler(DatagramHandler handler) { datagram_handler_ = std::move(handler); }
  // Runs on the network thread when shutdown begins, before the context runs dry (Bye to all).
  void set_stop_handler(StopHandler handler) { stop_handler_ = std::move(handler); }
  // Thread-safe; runs on the probes' thread at each /readyz once the first frame is out: "" when
  // the server is ready, else why not (the fleet's timeline is stale).
  void set_readiness_check(std::function<std::string()> check) {
    std::lock_guard lock(readiness_mutex_);
    readiness_check_ = std::move(check);
  }
  // Thread-safe: the simulation switches to this scene at tick `from` (admin ParamChange; the
  // hub announced it to the clients first).
  void request_scene(const model::SceneParams& scene, std::int64_t from);
  void request_vessels(const std::vector<model::VesselTrack>& vessels, std::int64_t from);
  // Scene and fleet requests made so far (TickFrames::requests_taken counts those in a tick's frames).
  std::uint64_t requests_made() {
    std::lock_guard lock(scene_request_mutex_);
    return requests_made_;
  }
  // The config's schedule, checked (immutable).
  const SceneSchedule& schedule() const { return schedule_; }
  // Sends one datagram without blocking; false when the socket refused it (the frame is lost).
  bool send_datagram(std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& to) override;
  void send_shared(const SharedBytes& bytes, const asio::ip::udp::endpoint& to) override;
  void flush() override;  // sends the queued datagrams (sendmmsg)

  // Runs the network side on the calling thread until SIGINT, SIGTERM or stop().
  void run();
  // Thread-safe: closes the listeners, stops the tick loop, and lets run() return.
  void stop();

  asio::io_context& context() { return context_; }
  const ServerConfig& config() const { return config_; }
  ServerMetrics& metrics() { return metrics_; }
  const CookieKey& cookie_key() const { return cookie_key_; }
  // The port a stream transport listens on; nullopt when the config leaves it off.
  std::optional<std::uint16_t> port_of(std::string_view transport) const;
  std::uint16_t tcp_port() const { return listeners_.front()->port; }
  std::optional<std::uint16_t> ws_port() const { return port_of("ws"); }
  std::uint16_t udp_port() const { return udp_port_; }
  std::optional<std::uint16_t> metrics_port() const { return metrics_port_; }
  std::optional<std::uint16_t> web_port() const { return web_http_ ? std::optional(web_port_) : std::nullopt; }
  // The browser listeners' TLS context in force (--tls-cert, reloaded on SIGHUP); null in the clear.
  std::shared_ptr<asio::ssl::context> tls_context() const { return tls_ ? tls_->current() : nullptr; }
  bool ready() const { return ready_.load(); }  // a first frame reached the network side

 private:
  void do_await_stop();
  asio::ip::udp::socket open_udp_beside_tcp();
  // A stream transport's listener: its acceptor and the pause after running out of descriptors.
  struct Listener {
    Listener(asio::io_context& context, const StreamTransport& t, const ListenAddress& address)
        : transport(t), acceptor(open_tcp_acceptor(context, address, std::string(t.role))), backoff(context),
          port(acceptor.local_endpoint().port()) {}
    const StreamTransport& transport;
    asio::ip::tcp::acceptor acceptor;
    asio::steady_timer backoff;
    std::uint16_t port;
  };
  void open_listeners();
  std::string listening_line() const;
  void do_accept(Listener& listener);
  bool descriptors_low(asio::ip::tcp::socket& socket, std::string_view transport);
  void back_off_accept(Listener& listener);
  void on_datagram(std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& from);
  void do_stop();
  void on_tick(const TickDecision& decision);  // simulation thread
  void drain_frames();                          // network thread
  void stop_http();                             // stops and joins the probes' (and web page's) thread
  HttpReply handle_http(const HttpRequest& request);

  ServerConfig config_;
  std::optional<TlsCredentials> tls_;  // --tls-cert and --tls-key, read before any listener opens
  asio::io_context context_{1};
  // /metrics, /healthz and /readyz run on their own thread, so a probe is answered however busy
  // the network thread is; /healthz reports that thread stalled from its heartbeat instead.
  asio::io_context http_context_{1};
  std::thread http_thread_;
  std::atomic<std::int64_t> heartbeat_ms_{0};  // steady ms when the network thread last served a tick
  asio::signal_set signals_;
  MetricsRegistry registry_;
  ServerMetrics metrics_;
  CookieKey cookie_key_;
  std::vector<std::unique_ptr<Listener>> listeners_;  // the primary (--listen) first
  std::unique_ptr<DatagramPort> udp_;  // the bound UDP socket, read outside asio's reactor
  std::unique_ptr<HttpServer> metrics_http_;
  // --web-listen: the browser viewer's files, on the probes' thread (served from memory).
  std::optional<WebFiles> web_files_;
  std::unique_ptr<HttpServer> web_http_;
  std::uint16_t web_port_ = 0;
  std::uint16_t udp_port_ = 0;
  std::optional<std::uint16_t> metrics_port_;

  FrameSink frame_sink_;
  ConnectionHandler connection_handler_;
  DatagramHandler datagram_handler_;
  StopHandler stop_handler_;
  // After a stop, ends run() if the goodbyes have not drained within kStopGraceS. A thread, not
  // a timer: a pending timer would itself keep the context running for the whole grace.
  std::thread stop_watchdog_;
  std::mutex run_mutex_;
  std::condition_variable run_returned_cv_;
  bool run_returned_ = false;  // guarded by run_mutex_
  std::mutex scene_request_mutex_;
  std::vector<std::pair<model::SceneParams, std::int64_t>> scene_requests_;  // guarded by scene_request_mutex_
  std::uint64_t requests_made_ = 0;  // guarded by scene_request_mutex_
  std::vector<std::pair<std::vector<model::VesselTrack>, std::int64_t>> vessel_requests_;  // the same

  DatagramBatch batch_;

  SceneSchedule schedule_;
  FrameProducer producer_;  // used only on the simulation thread
  BoundedQueue<std::shared_ptr<const TickFrames>> frames_{4};
  std::atomic<bool> ready_{false};
  std::mutex readiness_mutex_;
  std::function<std::string()> readiness_check_;
  bool stopping_ = false;
  TickLoop tick_loop_;      // last: its thread must stop before anything it touches goes away
};

}  // namespace ocean::server
