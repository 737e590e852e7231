// Sessions end to end over loopback: handshake, keys and deltas on TCP and UDP, reconstructions
// equal to the encoder's, shared encodings, refusals, timeouts and Bye on shutdown.
#include "session_harness.hpp"

#include "ocean.hpp"
#include "scene_model.hpp"

#include <chrono>
#include <cmath>

using namespace ocean::server;
using namespace ocean::server::test;
namespace proto = ocean::protocol;

namespace {

proto::Hello hello_for(std::uint8_t profile, ocean::wire::Transport transport, std::uint64_t bandwidth_bps = 0) {
  return proto::Hello{profile, bandwidth_bps, transport, "test"};
}

}  // namespace

TEST_CASE("clients on TCP and UDP reconstruct exactly what the encoder sent") {
  SessionHarness harness(session_test_config());
  auto tcp_mobile = harness.client();
  auto udp_mobile = harness.client();
  auto udp_lite = harness.client();    // 15 Hz under 30 Hz ticks: every 2nd tick
  auto tcp_choice = harness.client();  // profile 0: the server's choice
  tcp_mobile->hello(hello_for(1, ocean::wire::Transport::tcp));
  udp_mobile->hello(hello_for(1, ocean::wire::Transport::udp));
  udp_lite->hello(hello_for(4, ocean::wire::Transport::udp));
  tcp_choice->hello(hello_for(0, ocean::wire::Transport::tcp));
  const std::vector<SessionTestClient*> all{tcp_mobile.get(), udp_mobile.get(), udp_lite.get(), tcp_choice.get()};

  REQUIRE(pump_until(all, [&] {
    for (auto* c : all)
      if (c->completed_heights.size() < 20) return false;
    return udp_mobile->udp_frame_chunks > 20 && udp_lite->udp_frame_chunks > 10;
  }));
  CHECK(udp_mobile->udp_ready);
  CHECK(tcp_mobile->udp_frame_chunks == 0);
  CHECK(tcp_mobile->welcome->udp_port == 0);
  CHECK(udp_mobile->welcome->udp_cookie.size() >= 8);
  CHECK(udp_lite->welcome->stream.profile_id == 4);
  CHECK(tcp_choice->welcome->stream.profile_id == 1);  // first offered, no budget given
  for (const auto& [tick, heights] : udp_lite->completed_heights) CHECK(tick % 2 == 0);
  for (auto* c : all) {
    CHECK(c->errors.empty());
    CHECK(c->key_ticks.size() == 1);  // one key, then deltas only
    harness.check_reconstructions(*c);
  }
  harness.stop();
  for (auto* c : all) {
    pump_until({c}, [&] { return !c->byes.empty(); }, std::chrono::seconds(5));
    REQUIRE(c->byes.size() == 1);
    CHECK(c->byes[0].reason == ocean::wire::ByeReason::server_shutdown);
  }
  // Encodes per tick equal the distinct baselines served, never the number of sessions.
  for (const CoreTickStats& stats : harness.ticks()) CHECK(stats.encodes == stats.distinct_baselines);
}

TEST_CASE("clients that join in one tick share one encoding per tick") {
  // Lite streams every 2nd tick (66 ms apart): four Hellos sent back to back land in one frame
  // interval, or at worst straddle one boundary.
  SessionHarness harness(session_test_config());
  std::vector<std::unique_ptr<SessionTestClient>> clients;
  std::vector<SessionTestClient*> all;
  for (int i = 0; i < 4; ++i) {
    clients.push_back(harness.client());
    all.push_back(clients.back().get());
  }
  for (auto* c : all) c->hello(hello_for(4, ocean::wire::Transport::tcp));
  REQUIRE(pump_until(all, [&] {
    for (auto* c : all)
      if (c->completed_heights.size() < 4) return false;
    return true;
  }));
  harness.stop();
  const std::vector<CoreTickStats> ticks = harness.ticks();
  REQUIRE(!ticks.empty());
  const CoreTickStats& last = ticks.back();
  CHECK(last.sessions_served == 4);
  CHECK(last.encodes == last.distinct_baselines);
  CHECK(last.encodes <= 2);  // at worst the joins straddled one tick boundary
  for (auto* c : all) harness.check_reconstructions(*c);
}

TEST_CASE("a profile that is not offered is refused with the offered ids") {
  SessionHarness harness(session_test_config());
  auto client = harness.client();
  client->hello(hello_for(2, ocean::wire::Transport::tcp));  // desktop: valid, not offered
  REQUIRE(pump_until({client.get()}, [&] { return client->closed(); }));
  REQUIRE(client->errors.size() == 1);
  CHECK(client->errors[0].code == proto::Reason::profile_unavailable);
  CHECK(client->errors[0].text.find("1 (mobile)") != std::string::npos);
  CHECK(!client->welcome);
}

TEST_CASE("a small bandwidth budget gets the lighter profile when the server chooses") {
  SessionHarness harness(session_test_config());
  auto client = harness.client();
  client->hello(hello_for(0, ocean::wire::Transport::tcp, 64'000));
  REQUIRE(pump_until({client.get()}, [&] { return client->welcome.has_value(); }));
  CHECK(client->welcome->stream.profile_id == 4);  // lite
}

TEST_CASE("the bandwidth budget is respected on UDP") {
  SessionHarness harness(session_test_config());
  auto client = harness.client();
  const std::uint64_t budget_bps = 200'000;
  client->hello(hello_for(1, ocean::wire::Transport::udp, budget_bps));
  REQUIRE(pump_until({client.get()}, [&] { return client->udp_ready && client->udp_bytes_in > 0; }));
  const std::size_t start_bytes = client->udp_bytes_in;
  const auto start = std::chrono::steady_clock::now();
  pump_until({client.get()}, [] { return false; }, std::chrono::milliseconds(2000));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double bytes = static_cast<double>(client->udp_bytes_in - start_bytes);
  // The bucket's burst is a quarter second of budget (at least two datagrams).
  CHECK(bytes <= budget_bps / 8.0 * (seconds + 0.25) + 2400);
  CHECK(bytes > 0);
}

TEST_CASE("on a lossy UDP link, each lost frame arrives in the next datagram's FrameBundle") {
  SessionHarness harness(session_test_config());
  auto client = harness.client();
  client->hello(hello_for(1, ocean::wire::Transport::udp));
  REQUIRE(pump_until({client.get()}, [&] { return client->udp_ready && client->udp_frame_chunks > 3; }));
  client->drop_udp_every = 5;
  const std::uint32_t from = client->completed_heights.rbegin()->first + 1;
  REQUIRE(pump_until({client.get()}, [&] { return client->completed_heights.rbegin()->first > from + 60; }));
  CHECK(client->udp_bundles > 5);
  // Every 5th datagram was dropped, yet no tick is missing: its copy came in the next one.
  const std::uint32_t to = client->completed_heights.rbegin()->first;
  std::vector<std::uint32_t> missing;
  for (ocean::Tick tick = from; tick <= to; ++tick)
    if (!client->completed_heights.count(tick)) missing.push_back(tick);
  INFO("missing ticks: " << missing.size());
  CHECK(missing.empty());
  CHECK(client->rejected_chunks == 0);
  harness.check_reconstructions(*client);
}

TEST_CASE("an Ack, KeyframeRequest or Ping on TCP naming another session changes nothing") {
  SessionHarness harness(session_test_config());
  auto a = harness.client();
  auto b = harness.client();
  a->hello(hello_for(1, ocean::wire::Transport::tcp));
  b->hello(hello_for(1, ocean::wire::Transport::tcp));
  const std::vector<SessionTestClient*> both{a.get(), b.get()};
  REQUIRE(pump_until(both, [&] { return a->completed_heights.size() > 3 && b->completed_heights.size() > 3; }));
  const std::uint64_t other = b->welcome->session_id;
  // a claims b's session: a KeyframeRequest that would give b (or a) a key must not.
  for (int i = 0; i < 3; ++i)
    a->send_tcp(ocean::protocol::encode(ocean::protocol::KeyframeRequest{other, {}, ocean::wire::KeyframeReason::lost_baseline}));
  a->send_tcp(ocean::protocol::encode(ocean::protocol::Ack{other, {}, 5, 0}));
  const std::size_t before = a->completed_heights.size();
  REQUIRE(pump_until(both, [&] { return a->completed_heights.size() > before + 40; }));  // > the 1 s key interval
  CHECK(a->key_ticks.size() == 1);
  CHECK(b->key_ticks.size() == 1);
  CHECK(a->errors.empty());
  CHECK(!a->closed());
  harness.check_reconstructions(*a);
}

TEST_CASE("a silent client is timed out with Bye") {
  ServerConfig config = session_test_config();
  config.idle_timeout_s = 0.5;
  SessionHarness harness(config);
  auto client = harness.client();
  client->hello(hello_for(1, ocean::wire::Transport::udp));
  client->send_acks = false;  // it only reads: silence is what the server measures
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (client->byes.empty() && std::chrono::steady_clock::now() < end) {
    client->pump();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  REQUIRE(client->byes.size() == 1);
  CHECK(client->byes[0].reason == ocean::wire::ByeReason::idle_timeout);
}

TEST_CASE("a session streams across tick 2^32, where the version-1 wire tick wrapped, within the bound of the sim") {
  ServerConfig config = session_test_config();
  const auto now_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                          std::chrono::system_clock::now().time_since_epoch()).count();
  const ocean::Tick wrap = ocean::Tick{1} << 32;
  // The server's tick is 1.5 s short of 2^32 when it starts.
  config.epoch_unix_ms = now_ms - static_cast<std::int64_t>((wrap - 45) * 1000 / 30);
  SessionHarness harness(config);
  auto client = harness.client();
  client->hello(hello_for(1, ocean::wire::Transport::udp));
  REQUIRE(pump_until({client.get()}, [&] {
    return !client->completed_heights.empty() && client->completed_heights.rbegin()->first > wrap + 30;
  }));
  CHECK(client->completed_heights.begin()->first < wrap);
  CHECK(client->key_ticks.size() == 1);
  harness.check_reconstructions(*client);
  ocean::sim::Ocean ocean(config.scene);
  ocean::sim::Frame truth;
  const double bound = 0.5 * client->welcome->stream.height_step_m + 1e-5;
  for (const auto& [tick, heights] : client->completed_heights) {
    ocean.evaluate_band(ocean::codec::tick_time_s(static_cast<std::int64_t>(tick), 30), 64, 64, truth,
                        ocean::sim::FrameRequest{true, false});
    double worst = 0.0;
    for (std::size_t i = 0; i < heights.size(); ++i)
      worst = std::max(worst, std::fabs(double(heights[i]) - double(truth.height[i])));
    INFO("tick " << tick);
    CHECK(worst <= bound);
  }
}
