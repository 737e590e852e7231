// The server against the client library (client/net ClientConnection): several clients on both
// transports in one io_context, every complete frame they show equal to the encoder's.
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
