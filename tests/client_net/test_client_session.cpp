// ClientSession against the real server core (and FakeServer where the server must misbehave or
// the sea must be noisy): handshake, UDP proof, closed-loop reconstruction, acks, loss.
#include <catch2/catch.hpp>

#include <algorithm>

#include "frame_predictor.hpp"
#include "session_harness.hpp"

using namespace ocean;
using namespace ocean::client;
using namespace ocean::client::test;

namespace {

bool is_chunk_of(const protocol::Bytes& datagram, Tick tick, std::uint16_t index) {
  if (datagram.empty() || datagram[0] != static_cast<std::uint8_t>(protocol::DatagramKind::frames)) return false;
  std::vector<protocol::FrameRecord> records;
  if (!protocol::decode_frame_block(std::span(datagram).subspan(1), records)) return false;
  return records.back().tick == tick && records.back().index == index;
}

}  // namespace

TEST_CASE("session: handshake, UDP proof and a lossless stream reproduce the encoder exactly", "[session]") {
  CoreSessionHarness h;
  h.start();
  REQUIRE(h.session.state() == ClientSession::State::awaiting_welcome);
  h.run_ticks(60);
  const ClientStats& s = h.session.stats();
  CHECK(h.session.state() == ClientSession::State::streaming);
  CHECK(h.session.path() == ClientSession::Path::udp);
  CHECK(h.server.udp_hellos == 1);
  CHECK(h.server.keyframes_sent == 1);
  CHECK(s.keyframes_complete == 1);
  CHECK(h.delivered.size() == 60);  // every tick from the key on
  CHECK(h.frame_mismatches == 0);
  CHECK(h.acks_checked >= 12);  // one per ack interval (0.1 s, checked every 33 ms tick) while frames complete
  CHECK(h.ack_mismatches == 0);
  REQUIRE(s.latest_tick);
  CHECK(*s.latest_tick == h.server.tick());
  CHECK(s.udp.messages_in > 50);  // deltas moved to UDP
  CHECK(s.rejected_total() == 0);
  CHECK(s.codec_rejected_total() == 0);
  CHECK(s.pongs_received >= 1);
  CHECK(s.rtt_smoothed_s > 0.0);
  CHECK(s.rtt_smoothed_s < 0.1);
  CHECK(h.session.stream_rtt_s() == 0.0);  // deltas on UDP
  CHECK(h.session.welcome()->session_id == h.server.session_id());
}

TEST_CASE("session: a TCP-only session names its stream's round trip, the handshake's until a Pong comes",
          "[session]") {
  ClientSessionConfig config;
  config.transport = wire::Transport::tcp;
  CoreSessionHarness h(config);
  h.start();
  CHECK(h.session.stream_rtt_s() == 0.0);
  h.run_ticks(1);  // the Hello out at 0, the Welcome back a tick later
  REQUIRE(h.session.state() == ClientSession::State::streaming);
  CHECK(h.session.path() == ClientSession::Path::tcp);
  CHECK(h.session.stats().handshake_rtt_s == Approx(h.server.tick_period_s()));
  CHECK(h.session.stats().pongs_received == 0);
  CHECK(h.session.stream_rtt_s() == h.session.stats().handshake_rtt_s);
  h.run_ticks(3);
  REQUIRE(h.session.stats().pongs_received >= 1);  // the Ping went with the first update after the Welcome
  CHECK(h.session.stats().rtt_smoothed_s == Approx(h.server.tick_period_s()));
  CHECK(h.session.stream_rtt_s() == h.session.stats().rtt_smoothed_s);
}

TEST_CASE("session: UDP loss and reordering never corrupt a frame, acks name exactly the complete ticks",
          "[session]") {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    CoreSessionHarness h({}, UdpImpairment{0.15, 0.3, seed});
    h.start();
    h.run_ticks(300);
    const ClientStats& s = h.session.stats();
    INFO("seed " << seed);
    CHECK(h.frame_mismatches == 0);
    CHECK(h.ack_mismatches == 0);
    CHECK(h.acks_checked > 60);  // about one per ack interval (0.1 s, checked every tick)
    CHECK(h.datagrams_dropped > 30);          // the link lost ~15 % of them
    CHECK(s.frames_complete > 200);           // the server's redundant copies bring most frames through
    CHECK(h.server.keyframes_sent <= 3);      // the stream recovers from acked baselines, not keys
    REQUIRE(s.latest_tick);
    CHECK(h.server.tick() - *s.latest_tick <= 3);
    CHECK(h.session.state() == ClientSession::State::streaming);
  }
}

TEST_CASE("session: a lost chunk leaves its frame incomplete and unacked, the next frame recovers", "[session]") {
  FakeServerOptions options;
  options.noise_m = 0.05;  // corrections everywhere: deltas of several chunks
  SessionHarness h(options);
  const std::uint32_t lost_tick = 20;
  h.drop_down = [&](const protocol::Bytes& b) { return is_chunk_of(b, lost_tick, 1); };
  h.start();
  h.run_ticks(40);
  REQUIRE(h.server.sent_frame(lost_tick));
  REQUIRE(!h.server.sent_frame(lost_tick)->key);
  REQUIRE(h.server.sent_frame(lost_tick)->chunks.size() >= 2);
  const codec::Decoder* d = h.session.decoder();
  CHECK(!d->is_complete(lost_tick));
  CHECK(std::find(h.delivered.begin(), h.delivered.end(), lost_tick) == h.delivered.end());
  for (const protocol::Ack& ack : h.server.acks)
    CHECK(!protocol::AckWindow{ack.latest_tick, ack.ack_bits}.contains(lost_tick));
  // The following frames are predicted from acked ticks and complete exactly.
  for (std::uint32_t t = lost_tick + 1; t <= lost_tick + 10; ++t)
    CHECK(std::find(h.delivered.begin(), h.delivered.end(), t) != h.delivered.end());
  CHECK(h.server.sent_frame(lost_tick + 1)->base.tick != lost_tick);
  CHECK(h.frame_mismatches == 0);
  CHECK(h.ack_mismatches == 0);
  CHECK(h.server.keyframes_sent == 1);
}

TEST_CASE("session: deltas from a baseline the client lost make it ask for a keyframe and recover",
          "[session]") {
  FakeServerOptions options;
  options.trust_acks = false;  // predicts from the last frame sent, acked or not
  SessionHarness h(options);
  h.drop_down = [&](const protocol::Bytes& b) { return is_chunk_of(b, 30, 0); };
  h.start();
  h.run_ticks(30);
  CHECK(h.server.keyframe_requests.empty());
  h.run_ticks(70);
  const ClientStats& s = h.session.stats();
  REQUIRE(!h.server.keyframe_requests.empty());
  CHECK(h.server.keyframe_requests.front() == wire::KeyframeReason::lost_baseline);
  CHECK(s.chunks_rejected_by_codec[static_cast<std::size_t>(codec::ChunkError::unknown_baseline)] > 20);
  CHECK(h.server.keyframes_sent == 2);
  REQUIRE(s.latest_tick);
  CHECK(h.server.tick() - *s.latest_tick <= 2);  // streaming again
  CHECK(h.frame_mismatches == 0);
}

TEST_CASE("predictor: the decoder's physics predicts the next frames within a quantization step",
          "[session][predictor]") {
  CoreSessionHarness h;
  h.start();
  h.run_ticks(30);
  const codec::Decoder& d = *h.session.decoder();
  FramePredictor predictor(d.config());
  const std::uint32_t latest = *d.newest_complete();
  codec::ReconstructedFrame predicted;
  REQUIRE(predictor.predict(d, latest + 3, predicted));
  CHECK(!predictor.predict(d, 0, predicted));  // before every complete frame held
  REQUIRE(predictor.predict(d, latest + 3, predicted));
  CHECK(predicted.tick == latest + 3);
  CHECK(!predicted.complete);
  h.run_ticks(3);
  const codec::EncodedFrame* actual = h.server.sent_frame(latest + 3);
  REQUIRE(actual);
  const auto& truth = actual->reconstruction;
  REQUIRE(predicted.height.size() == truth.height.size());
  double max_h = 0.0, max_s = 0.0;
  for (std::size_t i = 0; i < truth.height.size(); ++i) {
    max_h = std::max(max_h, static_cast<double>(std::fabs(predicted.height[i] - truth.height[i])));
    max_s = std::max(max_s, static_cast<double>(std::fabs(predicted.slope_x[i] - truth.slope_x[i])));
  }
  CHECK(max_h <= d.config().height_step_m);
  CHECK(max_s <= d.config().slope_step);
}

TEST_CASE("session: after a NAT rebinding the client proves its new port and stays on UDP", "[session]") {
  CoreSessionHarness h;
  h.start();
  h.run_ticks(60);
  REQUIRE(h.session.path() == ClientSession::Path::udp);
  const int hellos = h.server.udp_hellos;
  // The NAT gives the client's flow a new port: the server's datagrams to the old one are lost.
  h.server.client_udp = asio::ip::udp::endpoint(asio::ip::make_address("127.0.0.1"), 40777);
  const std::size_t before = h.delivered.size();
  h.run_ticks(90);
  CHECK(h.server.udp_hellos > hellos);  // it proved the new port
  CHECK(h.server.set_transport_tcp == 0);  // without giving up on UDP
  CHECK(h.session.path() == ClientSession::Path::udp);
  CHECK(h.server.metrics().udp_rebinds.value() == 1.0);
  CHECK(h.delivered.size() - before >= 60);  // frames flow again within about a second
  CHECK(h.frame_mismatches == 0);
  CHECK(h.session.stats().udp.messages_in > 100);
}
