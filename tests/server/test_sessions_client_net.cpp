// The server against the client library (client/net ClientConnection): several clients on both
// transports in one io_context, every complete frame they show equal to the encoder's; and over
// WebSocket as a browser connects (no UDP), its refusals and an upgrade nobody answers.
#include "client_connection.hpp"
#include "session_harness.hpp"

#include <asio/io_context.hpp>

using namespace ocean::server;
using namespace ocean::server::test;

TEST_CASE("client/net connections stream from the server on TCP and UDP") {
  SessionHarness harness(session_test_config());
  asio::io_context io;
  struct Seen {
    std::uint64_t session_id = 0;
    std::map<std::uint32_t, std::vector<float>> complete;
  };
  std::vector<Seen> seen(3);
  std::vector<std::shared_ptr<ocean::client::ClientConnection>> connections;
  const ocean::wire::Transport transports[] = {ocean::wire::Transport::udp, ocean::wire::Transport::tcp,
                                               ocean::wire::Transport::udp};
  for (std::size_t i = 0; i < seen.size(); ++i) {
    ocean::client::ClientConnectionConfig config;
    config.port = std::to_string(harness.server().tcp_port());
    config.reconnect = false;
    config.session.profile_id = 1;  // mobile: its rate equals the tick rate
    config.session.transport = transports[i];
    auto connection = ocean::client::ClientConnection::create(
        io, config, [&seen, i](const ocean::codec::ReconstructedFrame& frame, ocean::Tick tick, double) {
          if (frame.complete) seen[i].complete[tick] = frame.height;
        });
    connection->set_on_welcome([&seen, i](const ocean::protocol::Welcome& welcome) { seen[i].session_id = welcome.session_id; });
    connection->start();
    connections.push_back(connection);
  }
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  auto done = [&] {
    for (const Seen& s : seen)
      if (s.complete.size() < 30) return false;
    return true;
  };
  while (!done() && std::chrono::steady_clock::now() < end) io.run_for(std::chrono::milliseconds(20));
  REQUIRE(done());
  for (auto& connection : connections) connection->stop();
  io.run_for(std::chrono::milliseconds(200));
  harness.stop();
  for (const Seen& s : seen) {
    REQUIRE(s.session_id != 0);
    for (const auto& [tick, heights] : s.complete) REQUIRE(harness.sent_height(s.session_id, tick) == heights);
  }
}

TEST_CASE("client/net over WebSocket: frames as the encoder sent them, a refusal's reason kept, a silent upgrade ended") {
  ServerConfig config = session_test_config();
  config.stream_listen["ws"] = ListenAddress{"127.0.0.1", 0};
  config.max_clients = 1;
  SessionHarness harness(config);
  asio::io_context io;
  std::uint64_t session_id = 0;
  std::map<std::uint32_t, std::vector<float>> complete;
  auto make = [&](std::uint16_t port, bool keep) {
    ocean::client::ClientConnectionConfig c;
    c.port = std::to_string(port);
    c.reconnect = false;
    c.websocket = true;
    c.websocket_upgrade_timeout_s = 0.5;
    c.session.profile_id = 1;
    return ocean::client::ClientConnection::create(
        io, c, [&complete, keep](const ocean::codec::ReconstructedFrame& frame, ocean::Tick tick, double) {
          if (keep && frame.complete) complete[tick] = frame.height;
        });
  };
  const auto run_until_done = [&](const std::function<bool()>& done) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!done() && std::chrono::steady_clock::now() < end) io.run_for(std::chrono::milliseconds(20));
    return done();
  };
  auto browser = make(*harness.server().ws_port(), true);
  browser->set_on_welcome([&](const ocean::protocol::Welcome& welcome) { session_id = welcome.session_id; });
  browser->start();
  REQUIRE(run_until_done([&] { return complete.size() >= 30; }));
  CHECK(browser->session()->path() == ocean::client::ClientSession::Path::tcp);  // no UDP beside a WebSocket
  CHECK(browser->session()->stats().udp_hellos_sent == 0);

  // The server is full: its Error and the close frame behind it may come in one read; the
  // Error's reason is the one kept.
  auto second = make(*harness.server().ws_port(), false);
  second->start();
  REQUIRE(run_until_done([&] { return !second->counters().last_close_reason.empty(); }));
  INFO("closed: " << second->counters().last_close_reason << "; refusal: " << second->counters().last_refusal);
  CHECK(second->counters().last_close_reason.find("server_full") != std::string::npos);

  // A listener that takes the connection and never answers the upgrade.
  asio::ip::tcp::acceptor mute(io, {asio::ip::make_address("127.0.0.1"), 0});
  asio::ip::tcp::socket held(io);
  mute.async_accept(held, [](std::error_code) {});
  auto unanswered = make(mute.local_endpoint().port(), false);
  unanswered->start();
  REQUIRE(run_until_done([&] { return !unanswered->counters().last_close_reason.empty(); }));
  CHECK(unanswered->counters().last_close_reason == "WebSocket upgrade: no answer within 0.5 s");

  browser->stop();
  io.run_for(std::chrono::milliseconds(200));
  harness.stop();
  REQUIRE(session_id != 0);
  for (const auto& [tick, heights] : complete) REQUIRE(harness.sent_height(session_id, tick) == heights);
}
