// ClientConnection: sockets, timer and reconnection around a ClientSession.
#include "client_connection.hpp"

#include <algorithm>
#include <asio/connect.hpp>
#include <asio/post.hpp>
#include <asio/write.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ocean::client {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::vector<ServerEndpoint> server_list(const ClientConnectionConfig& config) {
  if (!config.servers.empty()) return config.servers;
  return {ServerEndpoint{config.host, config.port}};
}

std::chrono::steady_clock::time_point to_time_point(double seconds) {
  return std::chrono::steady_clock::time_point(
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds)));
}

}  // namespace

double ClientConnection::now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::shared_ptr<ClientConnection> ClientConnection::create(asio::io_context& io, ClientConnectionConfig config,
                                                           FrameCallback on_frame, ConnectionLinks links) {
  return std::make_shared<ClientConnection>(io, std::move(config), std::move(on_frame), std::move(links));
}

ClientConnection::ClientConnection(asio::io_context& io, ClientConnectionConfig config, FrameCallback on_frame,
                                   ConnectionLinks links)
    : io_(io),
      config_(std::move(config)),
      servers_(server_list(config_)),
      on_frame_(std::move(on_frame)),
      links_(std::move(links)),
      resolver_(io),
      tcp_(io),
      udp_(io),
      timer_(io),
      read_buffer_(std::max<std::size_t>(config_.read_buffer_bytes, 1024)),
      udp_buffer_(2048),  // above kMaxDatagram, so an oversized datagram is seen whole and refused
      backoff_s_(config_.reconnect_min_s) {
  if (config_.websocket) {
    config_.session.transport = wire::Transport::tcp;  // a browser's path: no UDP beside it
    websocket_ = std::make_unique<WebSocketClient>(config_.websocket_seed, protocol::kDefaultMaxMessageBytes);
  }
}

void ClientConnection::start() {
  stopped_ = false;
  do_resolve();
}

void ClientConnection::stop() {
  stopped_ = true;
  if (session_ && session_->state() != ClientSession::State::closed) session_->quit(now_s());
  if (!writing_) teardown("stopped");  // else the write completion tears down once Bye is out
  timer_.cancel();
  timer_armed_ = false;
}

void ClientConnection::do_resolve() {
  down_ = false;
  ++counters_.connect_attempts;
  const std::uint64_t generation = ++generation_;
  const ServerEndpoint& target = server();
  resolver_.async_resolve(
      target.host, target.port,
      [self = shared_from_this(), generation](std::error_code ec, asio::ip::tcp::resolver::results_type results) {
        if (generation != self->generation_ || self->stopped_) return;
        if (ec) return self->teardown("resolve " + self->server().host + ": " + ec.message());
        asio::async_connect(self->tcp_, results,
                            [self, generation](std::error_code ec2, const asio::ip::tcp::endpoint&) {
                              if (generation != self->generation_ || self->stopped_) return;
                              if (ec2)
                                return self->teardown("connect " + self->server().host + ":" + self->server().port +
                                                      ": " + ec2.message());
                              self->on_connected();
                            });
      });
}

ClientSessionEvents ClientConnection::session_events() {
  ClientSessionEvents events;
  events.send_tcp = [this](std::span<const std::uint8_t> bytes) { send_tcp(bytes); };
  events.send_udp = [this](std::span<const std::uint8_t> bytes) { send_udp(bytes); };
  events.on_welcome = [this](const protocol::Welcome& welcome) {
    framer_.set_max_message_bytes(welcome.max_message_bytes);
    if (websocket_) websocket_->set_max_message_bytes(welcome.max_message_bytes);
    if (welcome.udp_port != 0 && config_.session.transport == wire::Transport::udp) open_udp(welcome);
    if (on_welcome_) on_welcome_(welcome);
  };
  events.on_scene_update = [this](const protocol::SceneUpdate& update) {
    if (on_scene_update_) on_scene_update_(update);
  };
  events.on_frame = [this](const codec::ReconstructedFrame& frame, Tick tick) {
    backoff_s_ = config_.reconnect_min_s;  // this server works: the next failure retries quickly
    if (on_frame_) on_frame_(frame, tick, now_s());
  };
  events.on_closed = [this](const std::string& why) {
    // Not from inside the session's own call stack: tear down once it has returned.
    asio::post(io_, [self = shared_from_this(), generation = generation_, why] {
      if (generation != self->generation_) return;
      if (self->stopped_ && self->writing_) return;  // stop(): the write completion closes once Bye is out
      self->teardown(why);
    });
  };
  return events;
}

void ClientConnection::on_connected() {
  std::error_code ec;
  tcp_.set_option(asio::ip::tcp::no_delay(true), ec);
  ++counters_.connects;
  connected_ = true;
  framer_.reset();
  framer_.set_max_message_bytes(protocol::kDefaultMaxMessageBytes);
  session_ = std::make_unique<ClientSession>(config_.session, session_events());
  if (websocket_) {  // the session starts once the server has taken the upgrade
    websocket_->set_max_message_bytes(protocol::kDefaultMaxMessageBytes);  // until this session's Welcome
    upgrade_due_ = now_s() + config_.websocket_upgrade_timeout_s;
    const std::string request = websocket_->upgrade_request(server().host, server().port);
    write_queue_.emplace_back(request.begin(), request.end());
    if (!writing_) do_write();
  } else {
    session_->start(now_s());
  }
  do_read();
  arm_timer();
}

void ClientConnection::do_read() {
  tcp_.async_read_some(asio::buffer(read_buffer_),
                       [self = shared_from_this(), generation = generation_](std::error_code ec, std::size_t n) {
                         if (generation != self->generation_) return;
                         if (ec) return self->teardown("TCP read: " + ec.message());
                         self->on_tcp_bytes(n, now_s());
                         if (generation != self->generation_) return;
                         self->do_read();
                         self->arm_timer();
                       });
}

void ClientConnection::on_tcp_bytes(std::size_t n, double now) {
  if (websocket_) return on_websocket_bytes(n, now);
  std::span<const std::uint8_t> rest(read_buffer_.data(), n);
  const std::uint64_t generation = generation_;
  while (!rest.empty()) {
    const protocol::TcpFramer::Result result = framer_.feed(rest);
    rest = rest.subspan(result.consumed);
    if (result.status == protocol::TcpFramer::Status::bad)
      return teardown(std::string("TCP framing: ") + std::string(protocol::to_string(result.reason)));
    if (result.status == protocol::TcpFramer::Status::need_more) break;
    on_message(framer_.message(), now);
    if (generation != generation_) return;
  }
}

void ClientConnection::on_websocket_bytes(std::size_t n, double now) {
  const std::uint64_t generation = generation_;
  const bool was_open = websocket_->open();
  std::string error = feed_websocket({read_buffer_.data(), n}, now);
  if (generation != generation_) return;
  if (error.empty() && !was_open && websocket_->open()) {
    session_->start(now);  // the upgrade is taken: Hello, then what came behind the answer
    error = feed_websocket({}, now);
    if (generation != generation_) return;
  }
  if (error.empty()) return;
  // A server that ends a session says why first (a Bye, an Error) and closes its socket after:
  // read together, the session's reason is the one to keep.
  const bool said = session_ && session_->state() == ClientSession::State::closed;
  teardown(said ? session_->close_reason() : error);
}

std::string ClientConnection::feed_websocket(std::span<const std::uint8_t> bytes, double now) {
  const std::uint64_t generation = generation_;
  return websocket_->feed(
      bytes,
      [&](std::span<const std::uint8_t> message) {  // ClientSession aligns what it verifies
        if (generation == generation_) on_message(message, now);
      },
      [&](std::vector<std::uint8_t> reply) {  // a Pong, framed already
        if (generation != generation_) return;
        write_queue_.push_back(std::move(reply));
        if (!writing_) do_write();
      });
}

void ClientConnection::on_message(std::span<const std::uint8_t> message, double now) {
  if (links_.tcp_down)
    links_.tcp_down->send(std::vector<std::uint8_t>(message.begin(), message.end()), now);
  else
    session_->on_tcp_message(message, now);
}

void ClientConnection::send_tcp(std::span<const std::uint8_t> bytes) {
  std::vector<std::uint8_t> copy(bytes.begin(), bytes.end());
  if (links_.tcp_up)
    links_.tcp_up->send(std::move(copy), now_s());
  else
    write_tcp(std::move(copy));
}

void ClientConnection::send_udp(std::span<const std::uint8_t> bytes) {
  if (links_.udp_up)
    links_.udp_up->send(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), now_s());
  else
    write_udp(bytes);
}

void ClientConnection::write_tcp(std::vector<std::uint8_t> bytes) {
  if (!connected_) return;
  write_queue_.push_back(websocket_ ? websocket_->frame(bytes) : std::move(bytes));
  if (!writing_) do_write();
}

void ClientConnection::do_write() {
  writing_ = true;
  asio::async_write(tcp_, asio::buffer(write_queue_.front()),
                    [self = shared_from_this(), generation = generation_](std::error_code ec, std::size_t) {
                      if (generation != self->generation_) return;
                      self->writing_ = false;
                      if (ec) return self->teardown("TCP write: " + ec.message());
                      self->write_queue_.pop_front();
                      if (!self->write_queue_.empty())
                        self->do_write();
                      else if (self->stopped_)
                        self->teardown("stopped");
                    });
}

void ClientConnection::open_udp(const protocol::Welcome& welcome) {
  std::error_code ec;
  const asio::ip::tcp::endpoint peer = tcp_.remote_endpoint(ec);
  if (ec) return;  // the TCP side is going down; teardown follows
  const asio::ip::udp::endpoint server(peer.address(), welcome.udp_port);
  if (udp_.is_open()) udp_.close(ec);
  udp_.open(server.protocol(), ec);
  if (!ec) udp_.non_blocking(true, ec);
  if (!ec) udp_.connect(server, ec);  // only the server's datagrams reach us
  if (ec) {
    udp_.close(ec);
    return;  // the session's UdpHello goes nowhere and it falls back to TCP
  }
  do_udp_read();
}

void ClientConnection::do_udp_read() {
  udp_.async_receive(asio::buffer(udp_buffer_),
                     [self = shared_from_this(), generation = generation_](std::error_code ec, std::size_t n) {
                       if (generation != self->generation_ || ec == asio::error::operation_aborted) return;
                       if (!self->udp_.is_open()) return;
                       const double now = now_s();
                       if (ec) {
                         ++self->counters_.udp_receive_errors;  // e.g. ICMP port unreachable: keep listening
                       } else if (self->links_.udp_down) {
                         self->links_.udp_down->send(
                             std::vector<std::uint8_t>(self->udp_buffer_.begin(), self->udp_buffer_.begin() + n), now);
                       } else {
                         self->session_->on_udp_datagram({self->udp_buffer_.data(), n}, now);
                       }
                       if (generation != self->generation_) return;
                       self->do_udp_read();
                       self->arm_timer();
                     });
}

void ClientConnection::write_udp(std::span<const std::uint8_t> bytes) {
  if (!udp_.is_open()) return;
  std::error_code ec;
  udp_.send(asio::buffer(bytes.data(), bytes.size()), 0, ec);  // would_block or refused: a lost datagram
}

void ClientConnection::pump_links(double now) {
  // While disconnected, what is still in flight belongs to the old connection: delivered nowhere.
  const bool live = connected_ && session_;
  if (links_.tcp_up)
    links_.tcp_up->deliver(now, [&](std::vector<std::uint8_t>&& b) { if (live) write_tcp(std::move(b)); });
  if (links_.udp_up)
    links_.udp_up->deliver(now, [&](std::vector<std::uint8_t>&& b) { if (live) write_udp(b); });
  const std::uint64_t generation = generation_;
  if (links_.tcp_down)
    links_.tcp_down->deliver(now, [&](std::vector<std::uint8_t>&& b) {
      if (live && generation == generation_) session_->on_tcp_message(b, now);
    });
  if (links_.udp_down)
    links_.udp_down->deliver(now, [&](std::vector<std::uint8_t>&& b) {
      if (live && generation == generation_) session_->on_udp_datagram(b, now);
    });
}

bool ClientConnection::links_idle() const {
  for (const PacketLink* link : {links_.tcp_up.get(), links_.tcp_down.get(), links_.udp_up.get(), links_.udp_down.get()})
    if (link && link->next_due() >= 0.0) return false;
  return true;
}

void ClientConnection::arm_timer() {
  if (stopped_) return;
  double due = kInfinity;
  if (waiting_reconnect_) due = reconnect_at_;
  if (connected_ && session_) due = std::min(due, session_->next_due());
  if (connected_ && websocket_ && !websocket_->open()) due = std::min(due, upgrade_due_);
  for (const PacketLink* link : {links_.tcp_up.get(), links_.tcp_down.get(), links_.udp_up.get(), links_.udp_down.get()})
    if (link && link->next_due() >= 0.0) due = std::min(due, link->next_due());
  if (!std::isfinite(due)) return;
  if (timer_armed_ && due >= timer_due_) return;  // the armed wait comes first anyway
  timer_armed_ = true;
  timer_due_ = due;
  timer_.expires_at(to_time_point(due));
  timer_.async_wait([self = shared_from_this()](std::error_code ec) {
    if (ec == asio::error::operation_aborted) return;  // re-armed earlier, or stopped
    self->timer_armed_ = false;
    self->on_timer();
  });
}

void ClientConnection::on_timer() {
  if (stopped_) return;
  const double now = now_s();
  pump_links(now);
  if (connected_ && websocket_ && !websocket_->open() && now >= upgrade_due_) {
    char why[64];
    std::snprintf(why, sizeof why, "WebSocket upgrade: no answer within %g s", config_.websocket_upgrade_timeout_s);
    teardown(why);
    return arm_timer();
  }
  if (connected_ && session_) session_->update(now);
  // Reconnect only once the old connection's packets have drained from the links.
  if (waiting_reconnect_ && now >= reconnect_at_ && links_idle()) {
    waiting_reconnect_ = false;
    do_resolve();
  }
  arm_timer();
}

void ClientConnection::teardown(const std::string& why) {
  if (down_) return;  // already torn down since the last attempt
  down_ = true;
  const bool was_connected = connected_;
  ++generation_;
  connected_ = false;
  std::error_code ec;
  resolver_.cancel();
  tcp_.close(ec);
  udp_.close(ec);
  write_queue_.clear();
  writing_ = false;
  framer_.reset();
  counters_.last_close_reason = why;
  if (session_ && session_->refusal()) counters_.last_refusal = why;
  if (was_connected) ++counters_.disconnects;
  if (was_connected && session_ && on_session_end_) on_session_end_(*session_, why);
  if (stopped_ || !config_.reconnect) return;
  const bool full = session_ && session_->refusal() == protocol::Reason::server_full;
  // This server failed or dropped us: the next attempt goes to the next replica.
  if (servers_.size() > 1) {
    server_index_ = (server_index_ + 1) % servers_.size();
    ++counters_.failovers;
  }
  waiting_reconnect_ = true;
  double wait_s = backoff_s_;
  if (full && servers_.size() <= 1)
    wait_s = std::max(wait_s, config_.server_full_retry_s * std::uniform_real_distribution<double>(0.75, 1.25)(jitter_));
  reconnect_at_ = now_s() + wait_s;
  backoff_s_ = std::min(config_.reconnect_max_s, backoff_s_ * 2.0);
  arm_timer();
}

}  // namespace ocean::client
