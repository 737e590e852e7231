// SessionHarness: one ClientSession and one server in one process (yojimbo style), joined by a
// simulated link: TCP in order, UDP server->client with seeded loss and reordering. Each tick the
// server sends at t and the client receives at t + half a tick. Checks every delivered frame
// against the encoder and every Ack against the decoder as they happen.
// The server is the real SessionCore (CoreSessionHarness, through tests/support's CorePeer), or
// FakeServer where a test needs a server that misbehaves or a synthetic, noisy sea.
#pragma once

#include <functional>
#include <random>

#include "client_session.hpp"
#include "core_peer.hpp"
#include "fake_server.hpp"

namespace ocean::client::test {

struct UdpImpairment {
  double loss = 0.0;     // probability a server->client datagram is dropped
  double reorder = 0.0;  // probability a datagram swaps places with the one after it
  std::uint64_t seed = 1;
};

template <class Server>
class BasicSessionHarness {
 public:
  template <class... ServerArgs>
  BasicSessionHarness(ClientSessionConfig client_config, UdpImpairment udp, ServerArgs&&... server_args)
      : server(std::forward<ServerArgs>(server_args)...), rng_(udp.seed), udp_(udp), session(std::move(client_config), events()) {}

  // Drops server->client datagrams this returns true for (after the random loss).
  std::function<bool(const protocol::Bytes&)> drop_down;
  bool drop_client_udp = false;  // black-holes client->server datagrams

  void start() { session.start(now); }

  void run_ticks(int ticks) {
    const double half = server.tick_period_s() / 2;
    for (int i = 0; i < ticks; ++i) {
      now += half;
      for (auto& b : take(client_tcp)) server.on_tcp(b, now);
      for (auto& b : take(client_udp))
        if (!drop_client_udp) server.on_udp(b, now);
      server.step(now);
      now += half;
      for (auto& b : take(server.to_client_tcp)) session.on_tcp_message(b, now);
      for (auto& b : impair(take(server.to_client_udp))) session.on_udp_datagram(b, now);
      session.update(now);
    }
  }

  // The server stalls (a pause, an overloaded thread): `seconds` pass with nothing processed or
  // sent; what the client sends meanwhile waits for the next run_ticks.
  void stall(double seconds) {
    const double step = server.tick_period_s();
    for (const double until = now + seconds; now < until;) {
      now += step;
      session.update(now);
    }
  }

  Server server;
  double now = 1000.0;
  std::vector<protocol::Bytes> client_tcp, client_udp;
  std::vector<std::uint32_t> delivered;  // ticks handed to on_frame
  int frame_mismatches = 0;              // delivered frames that differ from the encoder's reconstruction
  int ack_mismatches = 0;                // Acks naming a tick that is not complete, or missing one that is
  int acks_checked = 0;
  int datagrams_dropped = 0;             // server->client datagrams the link lost
  std::vector<std::string> closed;

 private:
  static std::vector<protocol::Bytes> take(std::vector<protocol::Bytes>& from) {
    std::vector<protocol::Bytes> out;
    out.swap(from);
    return out;
  }

  std::vector<protocol::Bytes> impair(std::vector<protocol::Bytes> in) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<protocol::Bytes> out;
    for (auto& b : in) {
      if (u(rng_) < udp_.loss || (drop_down && drop_down(b))) {
        ++datagrams_dropped;
        continue;
      }
      out.push_back(std::move(b));
    }
    for (std::size_t i = 0; i + 1 < out.size(); ++i)
      if (u(rng_) < udp_.reorder) std::swap(out[i], out[i + 1]);
    return out;
  }

  void check_ack(std::span<const std::uint8_t> bytes, wire::Transport transport) {
    protocol::Bytes copy(bytes.begin(), bytes.end());
    const auto v = protocol::verify_message(copy, {protocol::Sender::client, transport});
    if (!v || v.message->body_type() != wire::Body::Ack) return;
    ++acks_checked;
    const auto* ack = v.message->body_as_Ack();
    const protocol::AckWindow w{ack->latest_tick64(), ack->ack_bits()};
    const codec::Decoder* d = session.decoder();
    for (Tick age = 0; age <= protocol::kAckWindowTicks && age <= w.latest_tick; ++age) {
      const Tick t = w.latest_tick - age;
      const bool complete = d->is_complete(t);
      // Exactly the complete ticks, and the client's state for each equals the encoder's.
      if (w.contains(t) != complete) ++ack_mismatches;
      // (The encoder forgets states 32 ticks behind its newest truth: those cannot be compared.)
      if (complete && server.sent_state(t) && !(*server.sent_state(t) == *d->state(t))) ++ack_mismatches;
    }
  }

  ClientSessionEvents events() {
    ClientSessionEvents e;
    e.send_tcp = [this](std::span<const std::uint8_t> b) {
      check_ack(b, wire::Transport::tcp);
      client_tcp.emplace_back(b.begin(), b.end());
    };
    e.send_udp = [this](std::span<const std::uint8_t> b) {
      check_ack(b, wire::Transport::udp);
      client_udp.emplace_back(b.begin(), b.end());
    };
    e.on_frame = [this](const codec::ReconstructedFrame& f, std::uint32_t tick) {
      delivered.push_back(tick);
      const codec::EncodedFrame* sent = server.sent_frame(tick);
      if (!sent || sent->reconstruction.height != f.height || sent->reconstruction.slope_x != f.slope_x ||
          sent->reconstruction.slope_z != f.slope_z)
        ++frame_mismatches;
    };
    e.on_closed = [this](const std::string& why) { closed.push_back(why); };
    return e;
  }

  std::mt19937_64 rng_;
  UdpImpairment udp_;

 public:
  ClientSession session;  // last: its events capture the members above
};

class SessionHarness : public BasicSessionHarness<FakeServer> {
 public:
  SessionHarness(FakeServerOptions server_options, ClientSessionConfig client_config = {}, UdpImpairment udp = {})
      : BasicSessionHarness(std::move(client_config), udp, server_options) {}
};

class CoreSessionHarness : public BasicSessionHarness<ocean::test::CorePeer> {
 public:
  explicit CoreSessionHarness(ClientSessionConfig client_config = {}, UdpImpairment udp = {},
                              server::ServerConfig server_config = ocean::test::core_test_config())
      : BasicSessionHarness(std::move(client_config), udp, std::move(server_config)) {}
};

}  // namespace ocean::client::test
