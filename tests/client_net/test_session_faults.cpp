// ClientSession under faults: malformed and random input on both paths, refusals, UDP fallback.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <set>

#include "session_harness.hpp"

using namespace ocean;
using namespace ocean::client;
using namespace ocean::client::test;

namespace {

// Garbage of every shape the framing and verifier must refuse.
std::vector<protocol::Bytes> bad_inputs(std::uint64_t seed, const protocol::Bytes& valid) {
  std::mt19937_64 rng(seed);
  std::vector<protocol::Bytes> out;
  for (int i = 0; i < 300; ++i) {
    protocol::Bytes b(rng() % 400);
    for (auto& x : b) x = static_cast<std::uint8_t>(rng());
    out.push_back(b);
    if (b.size() >= 12) {  // a correct size prefix and identifier around random bytes
      const auto n = static_cast<std::uint32_t>(b.size() - 4);
      std::memcpy(b.data(), &n, 4);
      std::memcpy(b.data() + 8, "OCNP", 4);
      out.push_back(b);
    }
  }
  out.push_back({});
  // `valid` is a message as TCP carries it; on UDP the same bytes are a kind byte short, so both
  // paths see bad framing.
  out.push_back(protocol::Bytes(valid.begin(), valid.end() - 1));                  // truncated
  protocol::Bytes longer = valid;
  longer.push_back(0);
  out.push_back(longer);                                                           // trailing byte
  protocol::Bytes wrong_id = valid;
  wrong_id[8] = 'X';
  out.push_back(wrong_id);
  out.push_back(protocol::Bytes(1300, 0));                                         // oversized datagram
  return out;
}

}  // namespace

TEST_CASE("session: malformed and random bytes on TCP and UDP are rejected with a reason and change nothing",
          "[session][faults]") {
  ClientSessionConfig config;
  config.close_on_bad_tcp_message = false;
  CoreSessionHarness h(config);
  protocol::Bytes a_chunk;
  h.drop_down = [&](const protocol::Bytes& b) {
    a_chunk = b;
    return false;
  };
  h.start();
  h.run_ticks(30);
  REQUIRE(!a_chunk.empty());
  const ClientStats before = h.session.stats();
  const auto ticks_before = h.session.decoder()->complete_ticks();
  const std::size_t delivered_before = h.delivered.size();
  h.client_tcp.clear();
  h.client_udp.clear();

  // The same records as a TCP message: its corruptions exercise the TCP framing and verifier.
  REQUIRE(a_chunk[0] == static_cast<std::uint8_t>(protocol::DatagramKind::frames));
  const protocol::Bytes a_message =
      protocol::encode(protocol::FrameData{protocol::Bytes(a_chunk.begin() + 1, a_chunk.end())});
  std::size_t fed = 0;
  for (const auto& b : bad_inputs(11, a_message)) {
    h.session.on_udp_datagram(b, h.now);
    h.session.on_tcp_message(b, h.now);
    fed += 2;
  }
  const ClientStats& after = h.session.stats();
  // Refused by the framing or verifier, or - random bytes that happen to parse as a frames
  // datagram - every record by the codec (its CRC): each input has its reason.
  const std::uint64_t by_codec = after.codec_rejected_total() - before.codec_rejected_total();
  CHECK(after.rejected_total() - before.rejected_total() + by_codec >= fed);
  CHECK(after.udp.rejected + after.tcp.rejected - before.udp.rejected - before.tcp.rejected + by_codec >= fed);
  std::set<protocol::Reason> reasons;
  for (std::size_t r = 0; r < after.rejected_by_reason.size(); ++r)
    if (after.rejected_by_reason[r] != before.rejected_by_reason[r]) reasons.insert(static_cast<protocol::Reason>(r));
  CHECK(reasons.count(protocol::Reason::truncated));
  CHECK(reasons.count(protocol::Reason::trailing_bytes));
  CHECK(reasons.count(protocol::Reason::bad_identifier));
  CHECK(reasons.count(protocol::Reason::oversized));
  CHECK(reasons.count(protocol::Reason::empty));
  CHECK(reasons.size() >= 6);
  CHECK(h.session.decoder()->complete_ticks() == ticks_before);
  CHECK(after.frames_complete == before.frames_complete);
  CHECK(after.chunks_accepted == before.chunks_accepted);
  CHECK(h.delivered.size() == delivered_before);
  CHECK(h.client_tcp.empty());  // nothing was sent in answer
  CHECK(h.client_udp.empty());
  CHECK(h.session.state() == ClientSession::State::streaming);

  // Every single-byte corruption of a chunk already taken: refused by the verifier or the codec.
  for (std::size_t i = 0; i < a_chunk.size(); ++i) {
    protocol::Bytes b = a_chunk;
    b[i] ^= 0x5a;
    h.session.on_udp_datagram(b, h.now);
  }
  CHECK(h.session.decoder()->complete_ticks() == ticks_before);
  CHECK(h.session.stats().frames_complete == before.frames_complete);
  CHECK(h.delivered.size() == delivered_before);

  // And the stream carries on.
  h.drop_down = nullptr;
  h.run_ticks(10);
  CHECK(h.session.stats().frames_complete == before.frames_complete + 10);
  CHECK(h.frame_mismatches == 0);
}

TEST_CASE("session: by default a bad TCP message closes the session, naming the reason", "[session][faults]") {
  CoreSessionHarness h;
  h.start();
  h.run_ticks(5);
  protocol::Bytes bad = protocol::encode(protocol::Pong{});
  bad[9] = 'X';
  h.session.on_tcp_message(bad, h.now);
  CHECK(h.session.state() == ClientSession::State::closed);
  REQUIRE(h.closed.size() == 1);
  CHECK(h.closed[0].find("bad_identifier") != std::string::npos);
  CHECK(h.session.stats().rejected_by_reason[static_cast<std::size_t>(protocol::Reason::bad_identifier)] == 1);
}

TEST_CASE("session: UDP that never answers falls back to TCP after the timeout and keeps streaming",
          "[session][faults]") {
  CoreSessionHarness h;
  h.drop_client_udp = true;  // the path to the server's UDP port is black-holed
  h.start();
  h.run_ticks(45);  // 1.5 s
  CHECK(h.session.path() == ClientSession::Path::udp_proving);
  CHECK(h.session.stats().transport_fallbacks == 0);
  CHECK(h.session.stats().rtt_smoothed_s > 0.0);
  CHECK(h.session.stream_rtt_s() == 0.0);  // datagrams may still come: the jitter buffer learns them
  h.run_ticks(30);  // past 2 s
  const ClientStats& s = h.session.stats();
  CHECK(h.session.path() == ClientSession::Path::tcp);
  CHECK(h.session.stream_rtt_s() == s.rtt_smoothed_s);  // only the stream now: cover its retransmissions
  CHECK(s.transport_fallbacks == 1);
  CHECK(h.server.set_transport_tcp == 1);
  CHECK(s.udp_hellos_sent == 8);  // at 0, 0.25, ..., 1.75 s
  CHECK(h.server.udp_hellos == 0);  // none arrived
  h.run_ticks(30);
  CHECK(s.udp.messages_in == 0);
  CHECK(*s.latest_tick == h.server.tick());  // every frame on TCP
  CHECK(h.frame_mismatches == 0);
  CHECK(h.ack_mismatches == 0);
}

TEST_CASE("session: UDP going silent after it was proven falls back to TCP", "[session][faults]") {
  CoreSessionHarness h;
  h.start();
  h.run_ticks(30);
  REQUIRE(h.session.path() == ClientSession::Path::udp);
  h.drop_down = [](const protocol::Bytes&) { return true; };
  h.run_ticks(57);  // 1.9 s of silence
  CHECK(h.session.path() == ClientSession::Path::udp);
  h.run_ticks(6);
  CHECK(h.session.path() == ClientSession::Path::tcp);
  CHECK(h.server.set_transport_tcp == 1);
  h.run_ticks(30);
  // A keyframe on TCP after the fallback (and maybe one before it: the server ran out of acked
  // baselines after 32 ticks just as the client would have asked for one).
  CHECK(h.server.keyframes_sent >= 2);
  CHECK(*h.session.stats().latest_tick == h.server.tick());
  CHECK(h.frame_mismatches == 0);
}

TEST_CASE("session: an Error before the Welcome, a Bye, or an undecodable stream close it with the reason",
          "[session][faults]") {
  {
    CoreSessionHarness h;
    h.start();
    h.session.on_tcp_message(protocol::encode(protocol::Error{protocol::Reason::server_full, "full"}), h.now);
    CHECK(h.session.state() == ClientSession::State::closed);
    CHECK(h.session.close_reason().find("server_full") != std::string::npos);
  }
  {
    CoreSessionHarness h;
    h.start();
    h.run_ticks(3);
    h.session.on_tcp_message(protocol::encode(protocol::Error{protocol::Reason::unauthorized, "token"}), h.now);
    CHECK(h.session.state() == ClientSession::State::streaming);  // a refused request only
    CHECK(h.session.last_error().find("unauthorized") != std::string::npos);
    h.session.on_tcp_message(protocol::encode(protocol::Bye{wire::ByeReason::server_shutdown, "bye"}), h.now);
    CHECK(h.session.state() == ClientSession::State::closed);
    CHECK(h.session.close_reason().find("server_shutdown") != std::string::npos);
  }
  {
    FakeServerOptions options;
    options.broken_stream_params = true;  // a height step of 0: only a broken server sends it
    SessionHarness h(options);
    h.start();
    h.run_ticks(1);
    CHECK(h.session.state() == ClientSession::State::closed);
    CHECK(h.session.close_reason().find("height_step_m") != std::string::npos);
  }
}

TEST_CASE("session: a server that stalls silences both paths and does not push a UDP client to TCP",
          "[session][faults]") {
  CoreSessionHarness h;
  h.start();
  h.run_ticks(60);
  REQUIRE(h.session.path() == ClientSession::Path::udp);
  const std::uint64_t pings_before = h.session.stats().pings_sent;
  h.stall(3.0);  // past the 2 s UDP silence limit, with TCP as silent
  CHECK(h.session.path() == ClientSession::Path::udp);
  CHECK(h.session.stats().transport_fallbacks == 0);
  CHECK(h.session.stats().pings_sent > pings_before);  // it asked TCP whether the server is there
  h.run_ticks(60);  // the server catches up: the TCP Pong and the datagrams come back together
  const ClientStats& s = h.session.stats();
  CHECK(s.transport_fallbacks == 0);
  CHECK(h.server.set_transport_tcp == 0);
  CHECK(h.session.path() == ClientSession::Path::udp);
  CHECK(*s.latest_tick == h.server.tick());
  CHECK(h.frame_mismatches == 0);

  // Once TCP answers and UDP stays dark, it does fall back.
  h.drop_down = [](const protocol::Bytes&) { return true; };
  h.run_ticks(90);
  CHECK(h.session.stats().transport_fallbacks == 1);
  CHECK(h.session.path() == ClientSession::Path::tcp);
  h.drop_down = nullptr;
  h.run_ticks(30);
  CHECK(*h.session.stats().latest_tick == h.server.tick());
}
