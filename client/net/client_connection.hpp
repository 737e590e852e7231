// ClientConnection: the Asio edge of one client - TCP connect and framed reads, the UDP socket
// from the Welcome, one steady_timer driving its ClientSession, optional PacketLinks on every
// direction, and reconnection with backoff, round robin over replica servers. Many share one
// io_context and one thread.
#pragma once

#include "tick.hpp"

#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <asio/ip/udp.hpp>
#include <asio/steady_timer.hpp>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "client_session.hpp"
#include "packet_link.hpp"
#include "server_list.hpp"
#include "tcp_framer.hpp"
#include "websocket_client.hpp"

namespace ocean::client {

struct ClientConnectionConfig {
  std::string host = "127.0.0.1";
  std::string port = "7100";  // the server's TCP port
  // Replicas (servers started with one config stream identical frames, README-server.md). Empty:
  // {host, port} is the only server. Otherwise host/port are ignored; the first attempt goes to
  // servers[0], and after every failed attempt or dropped connection the next attempt goes to
  // the next entry, round robin, after the usual backoff. A new server means a new session, which
  // starts from a keyframe.
  std::vector<ServerEndpoint> servers;
  ClientSessionConfig session;
  bool reconnect = true;
  double reconnect_min_s = 0.25;  // first retry delay; doubles per failure up to reconnect_max_s
  double reconnect_max_s = 5.0;
  // A server that refused the Hello as server_full is at its capacity: with no other replica to
  // try, the next attempt waits this long (0.75x to 1.25x, so refused clients do not return in
  // step), as the refusal's text asks, instead of adding to the load with quick retries.
  double server_full_retry_s = 10.0;
  std::size_t read_buffer_bytes = 16 * 1024;
  // Reach the server's --ws-listen port as a browser does: the WebSocket upgrade, then every
  // message one binary frame (WebSocketClient); no UDP (the session's transport is TCP).
  bool websocket = false;
  std::uint64_t websocket_seed = 1;  // the upgrade keys' and frame masks' randomness
  // A server (or a proxy before it) that takes the connection but never answers the upgrade.
  double websocket_upgrade_timeout_s = 10.0;
};

struct ConnectionCounters {
  std::uint64_t connect_attempts = 0;
  std::uint64_t connects = 0;     // TCP connections established (each starts a new session)
  std::uint64_t disconnects = 0;
  std::uint64_t udp_receive_errors = 0;
  std::uint64_t failovers = 0;    // times a failure or drop moved the next attempt to another server
  std::string last_close_reason;
  std::string last_refusal;       // the close reason of the last refused Hello, kept across retries
};

class ClientConnection : public std::enable_shared_from_this<ClientConnection> {
 public:
  using FrameCallback = std::function<void(const codec::ReconstructedFrame&, Tick tick, double arrival_s)>;
  // Called when a session ends, before it is replaced, so its stats can be read.
  using SessionEndCallback = std::function<void(const ClientSession&, const std::string& why)>;

  static std::shared_ptr<ClientConnection> create(asio::io_context& io, ClientConnectionConfig config,
                                                  FrameCallback on_frame, ConnectionLinks links = {});

  void start();
  // Sends Bye{client_quit} (when no TCP link sits in between), closes, and stops reconnecting.
  void stop();

  void set_on_session_end(SessionEndCallback callback) { on_session_end_ = std::move(callback); }
  void set_on_welcome(std::function<void(const protocol::Welcome&)> callback) { on_welcome_ = std::move(callback); }
  // Every SceneUpdate, as it arrives (ahead of its effective tick).
  void set_on_scene_update(std::function<void(const protocol::SceneUpdate&)> callback) {
    on_scene_update_ = std::move(callback);
  }

  // The current (or, between connections, the last) session; null before the first connect.
  const ClientSession* session() const { return session_.get(); }
  const ConnectionCounters& counters() const { return counters_; }
  const ConnectionLinks& links() const { return links_; }
  bool connected() const { return connected_; }
  // The server connected to, or being tried (between connections: the next one to try).
  const ServerEndpoint& server() const { return servers_[server_index_]; }
  std::size_t server_index() const { return server_index_; }

  // The clock every session and link of this library runs on: steady_clock in seconds.
  static double now_s();

  ClientConnection(asio::io_context& io, ClientConnectionConfig config, FrameCallback on_frame,
                   ConnectionLinks links);  // use create()

 private:
  void do_resolve();
  void on_connected();
  void do_read();
  void on_tcp_bytes(std::size_t n, double now);
  void on_websocket_bytes(std::size_t n, double now);
  std::string feed_websocket(std::span<const std::uint8_t> bytes, double now);  // why it ends, or empty
  void on_message(std::span<const std::uint8_t> message, double now);  // a whole message off the stream
  void do_write();
  void open_udp(const protocol::Welcome& welcome);
  void do_udp_read();
  void send_tcp(std::span<const std::uint8_t> bytes);
  void send_udp(std::span<const std::uint8_t> bytes);
  void write_tcp(std::vector<std::uint8_t> bytes);
  void write_udp(std::span<const std::uint8_t> bytes);
  void pump_links(double now);
  bool links_idle() const;
  void arm_timer();
  void on_timer();
  void teardown(const std::string& why);
  ClientSessionEvents session_events();

  asio::io_context& io_;
  ClientConnectionConfig config_;
  std::vector<ServerEndpoint> servers_;  // config_.servers, or {host, port}; never empty
  std::size_t server_index_ = 0;
  FrameCallback on_frame_;
  ConnectionLinks links_;
  SessionEndCallback on_session_end_;
  std::function<void(const protocol::Welcome&)> on_welcome_;
  std::function<void(const protocol::SceneUpdate&)> on_scene_update_;

  asio::ip::tcp::resolver resolver_;
  asio::ip::tcp::socket tcp_;
  asio::ip::udp::socket udp_;
  asio::steady_timer timer_;
  protocol::TcpFramer framer_;
  std::unique_ptr<WebSocketClient> websocket_;  // config_.websocket: the stream's framing instead of framer_
  double upgrade_due_ = 0.0;                    // the upgrade's answer is owed by then
  std::vector<std::uint8_t> read_buffer_;
  std::vector<std::uint8_t> udp_buffer_;
  std::deque<std::vector<std::uint8_t>> write_queue_;
  bool writing_ = false;

  std::unique_ptr<ClientSession> session_;
  ConnectionCounters counters_;
  std::uint64_t generation_ = 0;  // bumped per connection; completions of an older one are ignored
  bool connected_ = false;
  bool down_ = false;  // torn down since the last connect attempt
  bool stopped_ = false;
  bool waiting_reconnect_ = false;
  double reconnect_at_ = 0.0;
  double backoff_s_ = 0.0;
  std::minstd_rand jitter_{std::random_device{}()};
  bool timer_armed_ = false;
  double timer_due_ = 0.0;
};

}  // namespace ocean::client
