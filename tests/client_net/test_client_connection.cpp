// ClientConnection over loopback against the real server core (LoopbackCore: SessionCore behind
// real sockets on the test's io_context): handshake and frames, reconnection after the server
// restarts, a PacketLink delaying the TCP downlink, UDP proof.
#include <catch2/catch.hpp>

#include <asio/read.hpp>
#include <asio/write.hpp>
#include <chrono>
#include <optional>
#include <queue>

#include "client_connection.hpp"
#include "loopback_core.hpp"
#include "run_until.hpp"

using namespace ocean;
using namespace ocean::client;

namespace {

using ocean::test::LoopbackCore;
using ocean::test::run_until;
constexpr std::size_t kFrames = 5;

struct Received {
  std::uint32_t tick;
  double arrival;
  bool exact;
};

// got[from, from + count) are consecutive ticks from `first` on, each equal to what the encoder sent.
void check_run(const std::vector<Received>& got, std::size_t from, std::size_t count, Tick first) {
  REQUIRE(got.size() >= from + count);
  CHECK(got[from].tick >= first);
  for (std::size_t i = from; i < from + count; ++i) {
    INFO("frame " << i << " tick " << got[i].tick);
    CHECK(got[i].exact);
    if (i > from) CHECK(got[i].tick == got[i - 1].tick + 1);
  }
}

// A fixed-delay link: the simplest PacketLink a load test could plug in.
struct DelayLink {
  double delay_s;
  std::queue<std::pair<double, std::vector<std::uint8_t>>> q;
  void send(std::vector<std::uint8_t> b, double now) { q.emplace(now + delay_s, std::move(b)); }
  template <typename F>
  void deliver(double now, F&& f) {
    while (!q.empty() && q.front().first <= now) {
      auto b = std::move(q.front().second);
      q.pop();
      f(std::move(b));
    }
  }
  double next_due() const { return q.empty() ? -1.0 : q.front().first; }
};

}  // namespace

TEST_CASE("connection: loopback handshake and frames, then reconnect after the server restarts", "[connection]") {
  asio::io_context io;
  auto server = std::make_unique<LoopbackCore>(io, 0, 10);
  const std::uint16_t port = server->port();
  std::vector<Received> got;
  ClientConnectionConfig config;
  config.port = std::to_string(port);
  config.reconnect_min_s = 0.05;
  config.session.transport = wire::Transport::tcp;
  auto connection = ClientConnection::create(io, config, [&](const codec::ReconstructedFrame& f, std::uint32_t tick, double at) {
    const codec::EncodedFrame* sent = server ? server->sent_frame(tick) : nullptr;
    got.push_back({tick, at, sent && sent->reconstruction.height == f.height && sent->reconstruction.slope_x == f.slope_x});
  });
  int session_ends = 0;
  connection->set_on_session_end([&](const ClientSession& s, const std::string&) {
    ++session_ends;
    CHECK(s.stats().frames_complete >= kFrames);
  });
  connection->start();
  REQUIRE(run_until(io, [&] { return got.size() >= kFrames; }));
  check_run(got, 0, kFrames, 10);
  CHECK(server->hellos() == 1);
  CHECK(connection->session()->path() == ClientSession::Path::tcp);  // the Hello asked for TCP
  CHECK(connection->counters().connects == 1);

  // The server goes away; the client notices, retries, and comes back when it returns.
  server->close();
  REQUIRE(run_until(io, [&] { return !connection->connected(); }));
  io.run_for(std::chrono::milliseconds(200));  // a failed attempt or two
  server.reset();
  const std::size_t before = got.size();
  server = std::make_unique<LoopbackCore>(io, port, 500);
  REQUIRE(run_until(io, [&] { return got.size() >= before + kFrames; }));
  check_run(got, before, kFrames, 500);
  CHECK(server->hellos() == 1);
  CHECK(connection->counters().connects == 2);
  CHECK(connection->counters().disconnects == 1);
  CHECK(connection->counters().connect_attempts >= 3);
  CHECK(session_ends == 1);
  CHECK(connection->session()->stats().keyframes_complete == 1);  // a new session starts from a key

  connection->stop();
  REQUIRE(run_until(io, [&] { return server->byes() == 1; }, 2.0));
}

TEST_CASE("connection: a PacketLink on the TCP downlink delays every message", "[connection]") {
  asio::io_context io;
  LoopbackCore server(io, 0, 1);
  ConnectionLinks links;
  links.tcp_down = std::make_unique<PacketLinkAdapter<DelayLink>>(DelayLink{0.15, {}});
  ClientConnectionConfig config;
  config.port = std::to_string(server.port());
  config.session.transport = wire::Transport::tcp;
  std::vector<double> arrivals;
  auto connection = ClientConnection::create(
      io, config, [&](const codec::ReconstructedFrame&, std::uint32_t, double at) { arrivals.push_back(at); },
      std::move(links));
  const double started = ClientConnection::now_s();
  connection->start();
  REQUIRE(run_until(io, [&] { return arrivals.size() >= kFrames; }));
  CHECK(arrivals.front() - started >= 0.15);
  CHECK(arrivals.front() - started < 1.0);
  connection->stop();
  io.run_for(std::chrono::milliseconds(20));
}

TEST_CASE("connection: the UDP socket from the Welcome proves itself and carries deltas", "[connection]") {
  asio::io_context io;
  LoopbackCore server(io, 0, 1);
  ClientConnectionConfig config;
  config.port = std::to_string(server.port());
  std::vector<Received> got;
  auto connection = ClientConnection::create(io, config, [&](const codec::ReconstructedFrame& f, std::uint32_t tick, double at) {
    const codec::EncodedFrame* sent = server.sent_frame(tick);
    got.push_back({tick, at, sent && sent->reconstruction.height == f.height});
  });
  connection->start();
  REQUIRE(run_until(io, [&] {
    const ClientSession* session = connection->session();
    return session && session->path() == ClientSession::Path::udp && session->stats().udp.messages_in >= 1 + kFrames &&
           got.size() >= 2 * kFrames;
  }));
  check_run(got, 0, got.size(), 1);
  const ClientSession& session = *connection->session();
  CHECK(session.stats().udp_hellos_sent >= 1);
  CHECK(session.stats().udp.messages_in >= 1 + kFrames);  // UdpReady + the deltas
  CHECK(session.stats().udp.bytes_out >= protocol::kUdpHelloMinBytes);
  connection->stop();
  io.run_for(std::chrono::milliseconds(20));
}

TEST_CASE("connection: a client refused as server_full waits the retry time instead of hammering", "[connection]") {
  asio::io_context io;
  server::ServerConfig server_config = ocean::test::core_test_config();
  server_config.max_clients = 1;
  LoopbackCore server(io, 0, 10, server_config);
  auto make = [&](double full_retry_s) {
    ClientConnectionConfig config;
    config.port = std::to_string(server.port());
    config.reconnect_min_s = 0.05;
    config.server_full_retry_s = full_retry_s;
    config.session.transport = wire::Transport::tcp;
    return ClientConnection::create(io, config, [](const codec::ReconstructedFrame&, std::uint32_t, double) {});
  };
  auto first = make(0.6);
  first->start();
  REQUIRE(run_until(io, [&] { return first->connected() && first->session() && first->session()->welcome().has_value(); }));
  auto refused = make(0.6);
  refused->start();
  REQUIRE(run_until(io, [&] { return refused->counters().connect_attempts >= 1 && !refused->connected(); }));
  io.run_for(std::chrono::milliseconds(400));  // under 0.75 x 0.6 s: no second attempt yet
  CHECK(refused->counters().connect_attempts == 1);
  CHECK(refused->counters().last_close_reason.find("server_full") != std::string::npos);
  REQUIRE(run_until(io, [&] { return refused->counters().connect_attempts >= 2; }, 3.0));  // then it retries
  refused->stop();
  first->stop();
  io.run_for(std::chrono::milliseconds(100));
}
