// ClientExchange: a real handshake and a few ticks of streaming between a ClientSession and the
// client tests' FakeServer, logged as the server -> client messages in arrival order. The client
// harness replays its Welcome; make_corpus writes the whole log as seeds.
#pragma once

#include <cstdint>
#include <vector>

#include "client_session.hpp"
#include "fake_server.hpp"

namespace ocean::fuzz {

struct ServerMessage {
  wire::Transport transport = wire::Transport::tcp;
  protocol::Bytes bytes;
};

inline std::vector<ServerMessage> record_client_exchange(int ticks) {
  client::test::FakeServer server;
  std::vector<ServerMessage> log;
  client::ClientSessionEvents events;
  events.send_tcp = [&](std::span<const std::uint8_t> b) { server.on_tcp(b, 0.0); };
  events.send_udp = [&](std::span<const std::uint8_t> b) { server.on_udp(b, 0.0); };
  client::ClientSession session({}, events);
  double now = 0.0;
  auto deliver = [&] {
    // The session answers while it reads, so take the outboxes before handing them over.
    while (!server.to_client_tcp.empty() || !server.to_client_udp.empty()) {
      std::vector<protocol::Bytes> tcp, udp;
      tcp.swap(server.to_client_tcp);
      udp.swap(server.to_client_udp);
      for (auto& b : tcp) {
        session.on_tcp_message(b, now);
        log.push_back({wire::Transport::tcp, std::move(b)});
      }
      for (auto& b : udp) {
        session.on_udp_datagram(b, now);
        log.push_back({wire::Transport::udp, std::move(b)});
      }
    }
  };
  session.start(now);
  deliver();
  for (int i = 0; i < ticks; ++i) {
    now += server.tick_period_s();
    server.step();
    session.update(now);
    deliver();
  }
  return log;
}

// The Welcome a real server sent (the first TCP message of the exchange).
inline const protocol::Bytes& real_welcome() {
  static const protocol::Bytes welcome = record_client_exchange(0).front().bytes;
  return welcome;
}

}  // namespace ocean::fuzz
