// ClientConnection failover over a list of replica servers: each server here is the real server
// core behind loopback sockets (LoopbackCore), stepping a frame every 20 ms (TCP only). A replica
// that dies sends the client to the next one in the list, round robin, each time starting a new
// session from a keyframe.
#include <catch2/catch.hpp>

#include <asio/write.hpp>
#include <chrono>
#include <memory>
#include <optional>

#include "client_connection.hpp"
#include "loopback_core.hpp"
#include "run_until.hpp"

using namespace ocean;
using namespace ocean::client;

namespace {

using ocean::test::LoopbackCore;
using ReplicaHost = LoopbackCore;

// Replicas stream their own timelines, far apart, so a shown tick names its replica.
constexpr Tick kReplicaA = 1, kReplicaB = 100000, kReplicaA2 = 200000;

ClientConnectionConfig failover_config(std::vector<ServerEndpoint> servers) {
  ClientConnectionConfig config;
  config.servers = std::move(servers);
  config.reconnect_min_s = 0.05;
  config.session.transport = wire::Transport::tcp;
  return config;
}

using ocean::test::run_until;

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
  replicas.push_back(std::make_unique<ReplicaHost>(io, 0, kReplicaA));
  replicas.push_back(std::make_unique<ReplicaHost>(io, 0, kReplicaB));
  const std::uint16_t port_a = replicas[0]->port();

  const ClientConnectionConfig config = failover_config({loopback(port_a), loopback(replicas[1]->port())});
  std::vector<Shown> shown;
  std::shared_ptr<ClientConnection> connection;
  connection = ClientConnection::create(io, config, [&](const codec::ReconstructedFrame& f, std::uint32_t tick, double) {
    const std::size_t i = connection->server_index();
    const codec::EncodedFrame* sent = replicas[i] ? replicas[i]->sent_frame(tick) : nullptr;
    shown.push_back({i, tick, connection->session()->stats().keyframes_complete,
                     sent && sent->reconstruction.height == f.height && sent->reconstruction.slope_x == f.slope_x});
  });
  connection->start();
  REQUIRE(run_until(io, [&] { return shown.size() >= 10; }));
  CHECK(connection->server() == config.servers[0]);
  CHECK(connection->counters().failovers == 0);

  // Replica `dead` dies: the client moves to `next` (its nth connection), whose stream starts with
  // one keyframe. Returns where the new session's frames start in `shown`.
  auto fail_over = [&](std::size_t dead, std::size_t next, std::uint64_t nth) {
    replicas[dead]->close();
    replicas[dead].reset();
    const std::size_t before = shown.size();
    REQUIRE(run_until(io, [&] { return shown.size() >= before + 10; }));
    CHECK(connection->server() == config.servers[next]);
    CHECK(connection->counters().failovers == nth - 1);
    CHECK(connection->counters().connects == nth);
    CHECK(replicas[next]->hellos() == 1);
    return before;
  };
  const std::size_t before_b = fail_over(0, 1, 2);
  // A comes back on its port and B dies: the list wraps around to A.
  replicas[0] = std::make_unique<ReplicaHost>(io, port_a, kReplicaA2);
  const std::size_t before_a = fail_over(1, 0, 3);

  // Every frame matched its own replica's encoder; each session began with its one keyframe and
  // its ticks came from that replica's timeline.
  for (std::size_t i = 0; i < shown.size(); ++i) {
    INFO("frame " << i << " tick " << shown[i].tick << " from server " << shown[i].server);
    CHECK(shown[i].exact);
    CHECK(shown[i].keys == 1);
    const bool first_of_session = i == 0 || i == before_b || i == before_a;
    if (!first_of_session) CHECK(shown[i].tick > shown[i - 1].tick);
  }
  CHECK(shown[0].tick < kReplicaB);
  CHECK(shown[before_b].tick >= kReplicaB);
  CHECK(shown[before_b].tick < kReplicaA2);
  CHECK(shown[before_a].tick >= kReplicaA2);

  connection->stop();
  io.run_for(std::chrono::milliseconds(20));
}

TEST_CASE("failover: a replica that refuses the first connection is skipped for the next", "[connection][failover]") {
  asio::io_context io;
  const std::uint16_t dead_port = closed_port(io);
  ReplicaHost alive(io, 0, kReplicaA);
  const ClientConnectionConfig config = failover_config({loopback(dead_port), loopback(alive.port())});
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
  ReplicaHost alive(io, 0, kReplicaA);
  ClientConnectionConfig config = failover_config({});
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
