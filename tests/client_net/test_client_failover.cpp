// ClientConnection failover over a list of replica servers: each server here is a FakeServer
// behind a loopback TCP acceptor that steps a frame every 20 ms (TCP only). A replica that
// dies sends the client to the next one in the list, round robin, each time starting a new
// session from a keyframe.
#include <catch2/catch.hpp>

#include <asio/write.hpp>
#include <chrono>
#include <memory>
#include <optional>

#include "client_connection.hpp"
#include "fake_server.hpp"

using namespace ocean;
using namespace ocean::client;
using namespace ocean::client::test;

namespace {

// One replica: FakeServer's frames over a real TCP connection. first_tick tells replicas apart.
// A completion already queued when the host is closed or destroyed still runs (cancel cannot
// recall it), so every handler checks the shared `alive_` flag before touching the host.
class ReplicaHost {
 public:
  ReplicaHost(asio::io_context& io, std::uint16_t port, std::uint32_t first_tick)
      : acceptor_(io, asio::ip::tcp::endpoint(asio::ip::address_v4::loopback(), port)),
        socket_(io),
        timer_(io),
        server_(fake_options()) {
    while (server_.tick() + 1 < first_tick) server_.step();
    do_accept();
    arm_timer();
  }
  ~ReplicaHost() { *alive_ = false; }
  ReplicaHost(const ReplicaHost&) = delete;
  ReplicaHost& operator=(const ReplicaHost&) = delete;

  std::uint16_t port() const { return port_; }
  const FakeServer& server() const { return server_; }
  int hellos() const { return hellos_; }

  void close() {
    *alive_ = false;
    std::error_code ec;
    socket_.close(ec);
    acceptor_.close(ec);
    timer_.cancel();
  }

 private:
  static FakeServerOptions fake_options() {
    FakeServerOptions options;
    options.offer_udp = false;
    return options;
  }

  void do_accept() {
    acceptor_.async_accept([this, alive = alive_](std::error_code ec, asio::ip::tcp::socket s) {
      if (!*alive || ec) return;
      socket_ = std::move(s);
      framer_.reset();
      do_read();
    });
  }

  void do_read() {
    socket_.async_read_some(asio::buffer(buffer_), [this, alive = alive_](std::error_code ec, std::size_t n) {
      if (!*alive || ec) return;
      std::span<const std::uint8_t> rest(buffer_.data(), n);
      while (!rest.empty()) {
        const auto r = framer_.feed(rest);
        rest = rest.subspan(r.consumed);
        if (r.status != protocol::TcpFramer::Status::good) break;
        const auto v = protocol::verify_message(framer_.message(), {protocol::Sender::client, wire::Transport::tcp});
        if (v && v.message->body_type() == wire::Body::Hello) ++hellos_;
        server_.on_tcp(framer_.message(), ClientConnection::now_s());
      }
      flush();
      do_read();
    });
  }

  void arm_timer() {
    timer_.expires_after(std::chrono::milliseconds(20));
    timer_.async_wait([this, alive = alive_](std::error_code ec) {
      if (!*alive || ec) return;
      server_.step();
      flush();
      arm_timer();
    });
  }

  void flush() {
    if (server_.to_client_tcp.empty()) return;
    auto out = std::make_shared<protocol::Bytes>();
    for (const protocol::Bytes& message : server_.to_client_tcp) out->insert(out->end(), message.begin(), message.end());
    server_.to_client_tcp.clear();
    if (!socket_.is_open()) return;
    asio::async_write(socket_, asio::buffer(*out), [out](std::error_code, std::size_t) {});
  }

  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
  asio::ip::tcp::acceptor acceptor_;
  std::uint16_t port_ = acceptor_.local_endpoint().port();
  asio::ip::tcp::socket socket_;
  asio::steady_timer timer_;
  FakeServer server_;
  protocol::TcpFramer framer_;
  std::array<std::uint8_t, 4096> buffer_{};
  int hellos_ = 0;
};

template <typename Done>
bool run_until(asio::io_context& io, Done done, double seconds = 5.0) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done() && std::chrono::steady_clock::now() < until) io.run_for(std::chrono::milliseconds(5));
  return done();
}

// A port nothing listens on: bound once to learn a free one, then released.
std::uint16_t closed_port(asio::io_context& io) {
  asio::ip::tcp::acceptor probe(io, asio::ip::tcp::endpoint(asio::ip::address_v4::loopback(), 0));
  return probe.local_endpoint().port();
}

ServerEndpoint loopback(std::uint16_t port) { return {"127.0.0.1", std::to_string(port)}; }

struct Shown {
  std::size_t server;      // connection->server_index() when it was shown
  std::uint32_t tick;
  std::uint64_t keys;      // keyframes the session had completed by then
  bool exact;              // equals what that replica's encoder says the client shows
};

}  // namespace

TEST_CASE("failover: a dropped replica sends the client to the next one, round robin, keyframe first",
          "[connection][failover]") {
  asio::io_context io;
  std::vector<std::unique_ptr<ReplicaHost>> replicas;
  replicas.push_back(std::make_unique<ReplicaHost>(io, 0, 1));
  replicas.push_back(std::make_unique<ReplicaHost>(io, 0, 300));
  const std::uint16_t port_a = replicas[0]->port();

  ClientConnectionConfig config;
  config.servers = {loopback(port_a), loopback(replicas[1]->port())};
  config.reconnect_min_s = 0.05;
  std::vector<Shown> shown;
  std::shared_ptr<ClientConnection> connection;
  connection = ClientConnection::create(io, config, [&](const codec::ReconstructedFrame& f, std::uint32_t tick, double) {
    const std::size_t i = connection->server_index();
    const codec::EncodedFrame* sent = replicas[i] ? replicas[i]->server().sent_frame(tick) : nullptr;
    shown.push_back({i, tick, connection->session()->stats().keyframes_complete,
                     sent && sent->reconstruction.height == f.height && sent->reconstruction.slope_x == f.slope_x});
  });
  connection->start();
  REQUIRE(run_until(io, [&] { return shown.size() >= 10; }));
  CHECK(connection->server() == config.servers[0]);
  CHECK(connection->counters().failovers == 0);

  // Replica A dies: the next attempt goes to B, whose stream starts with one keyframe.
  replicas[0]->close();
  replicas[0].reset();
  const std::size_t before_b = shown.size();
  REQUIRE(run_until(io, [&] { return shown.size() >= before_b + 10; }));
  CHECK(connection->server() == config.servers[1]);
  CHECK(connection->counters().failovers == 1);
  CHECK(connection->counters().connects == 2);
  CHECK(replicas[1]->hellos() == 1);

  // A comes back on its port and B dies: the list wraps around to A.
  replicas[0] = std::make_unique<ReplicaHost>(io, port_a, 600);
  replicas[1]->close();
  replicas[1].reset();
  const std::size_t before_a = shown.size();
  REQUIRE(run_until(io, [&] { return shown.size() >= before_a + 10; }));
  CHECK(connection->server() == config.servers[0]);
  CHECK(connection->counters().failovers == 2);
  CHECK(connection->counters().connects == 3);
  CHECK(replicas[0]->hellos() == 1);

  // Every frame matched its own replica's encoder; each session began with its one keyframe and
  // its ticks came from that replica's timeline.
  for (std::size_t i = 0; i < shown.size(); ++i) {
    INFO("frame " << i << " tick " << shown[i].tick << " from server " << shown[i].server);
    CHECK(shown[i].exact);
    CHECK(shown[i].keys == 1);
    const bool first_of_session = i == 0 || i == before_b || i == before_a;
    if (!first_of_session) CHECK(shown[i].tick > shown[i - 1].tick);
  }
  CHECK(shown[0].tick < 300);
  CHECK(shown[before_b].tick >= 300);
  CHECK(shown[before_b].tick < 600);
  CHECK(shown[before_a].tick >= 600);

  connection->stop();
  io.run_for(std::chrono::milliseconds(20));
}

TEST_CASE("failover: a replica that refuses the first connection is skipped for the next", "[connection][failover]") {
  asio::io_context io;
  const std::uint16_t dead_port = closed_port(io);
  ReplicaHost alive(io, 0, 1);
  ClientConnectionConfig config;
  config.servers = {loopback(dead_port), loopback(alive.port())};
  config.reconnect_min_s = 0.05;
  int frames = 0;
  auto connection = ClientConnection::create(io, config, [&](const codec::ReconstructedFrame&, std::uint32_t, double) { ++frames; });
  connection->start();
  REQUIRE(run_until(io, [&] { return frames >= 3; }));
  CHECK(connection->server() == config.servers[1]);
  CHECK(connection->counters().connect_attempts == 2);
  CHECK(connection->counters().connects == 1);
  CHECK(connection->counters().failovers == 1);
  CHECK(connection->counters().last_close_reason.find("127.0.0.1:" + std::to_string(dead_port)) != std::string::npos);
  connection->stop();
  io.run_for(std::chrono::milliseconds(20));
}

TEST_CASE("failover: without a server list, host and port name the one server", "[connection][failover]") {
  asio::io_context io;
  ReplicaHost alive(io, 0, 1);
  ClientConnectionConfig config;
  config.port = std::to_string(alive.port());
  int frames = 0;
  auto connection = ClientConnection::create(io, config, [&](const codec::ReconstructedFrame&, std::uint32_t, double) { ++frames; });
  CHECK(connection->server() == ServerEndpoint{"127.0.0.1", config.port});
  connection->start();
  REQUIRE(run_until(io, [&] { return frames >= 3; }));
  CHECK(connection->counters().failovers == 0);
  connection->stop();
  io.run_for(std::chrono::milliseconds(20));
}
