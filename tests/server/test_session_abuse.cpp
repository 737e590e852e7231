// Sessions under abuse: admin vs viewer parameter changes, malformed and oversized messages on
// both transports while a good client keeps streaming, a reader that stops (bounded memory), and
// no UDP amplification before an address is proven.
#include "session_harness.hpp"

using namespace ocean::server;
using namespace ocean::server::test;
namespace proto = ocean::protocol;

namespace {

proto::Hello tcp_hello(std::uint8_t profile = 1) { return proto::Hello{profile, 0, ocean::wire::Transport::tcp, "t"}; }

}  // namespace

TEST_CASE("an admin's ParamChange reaches every client at one tick, a viewer's is refused") {
  ServerConfig config = session_test_config();
  config.admin_token = "s3cret-token";
  SessionHarness harness(config);
  auto admin = harness.client();
  auto viewer = harness.client();
  admin->hello(tcp_hello());
  viewer->hello(proto::Hello{1, 0, ocean::wire::Transport::udp, "viewer"});
  const std::vector<SessionTestClient*> all{admin.get(), viewer.get()};
  REQUIRE(pump_until(all, [&] { return admin->completed_heights.size() > 3 && viewer->completed_heights.size() > 3; }));

  proto::ParamChange change;
  change.admin_token = "wrong";
  change.request_id = 7;
  change.wind_speed_mps = 20.0;
  viewer->send_tcp(proto::encode(change));
  REQUIRE(pump_until(all, [&] { return !viewer->errors.empty(); }));
  CHECK(viewer->errors[0].code == proto::Reason::unauthorized);
  const std::size_t before = viewer->completed_heights.size();
  REQUIRE(pump_until(all, [&] { return viewer->completed_heights.size() > before + 3; }));  // still streaming
  CHECK(viewer->scene_updates.empty());
  CHECK(admin->scene_updates.empty());

  change.admin_token = "s3cret-token";
  change.request_id = 9;
  admin->send_tcp(proto::encode(change));
  REQUIRE(pump_until(all, [&] { return !admin->scene_updates.empty() && !viewer->scene_updates.empty(); }));
  const proto::SceneUpdate& a = admin->scene_updates[0];
  const proto::SceneUpdate& v = viewer->scene_updates[0];
  CHECK(a.request_id == 9);
  CHECK(v.request_id == 0);
  CHECK(a.effective_tick == v.effective_tick);
  CHECK(a.scene.wind_speed_mps == 20.0);
  CHECK(v.scene == a.scene);
  // Announced ahead of its tick; every stream goes on through it with no new key (CODEC.md 7.5),
  // every frame on either side of the change exactly what the encoder sent.
  CHECK(a.effective_tick > admin->completed_heights.rbegin()->first);
  REQUIRE(pump_until(all, [&] {
    for (auto* c : all)
      if (c->completed_heights.rbegin()->first < a.effective_tick + 10) return false;
    return true;
  }));
  for (auto* c : all) {
    CHECK(c->key_ticks.size() == 1);
    CHECK(c->completed_heights.count(a.effective_tick) + c->completed_heights.count(a.effective_tick + 1) > 0);
    harness.check_reconstructions(*c);
  }
  CHECK(admin->errors.empty());
}

TEST_CASE("malformed and oversized input is refused while other clients keep streaming") {
  SessionHarness harness(session_test_config());
  auto good = harness.client();
  good->hello(proto::Hello{1, 0, ocean::wire::Transport::udp, "good"});
  REQUIRE(pump_until({good.get()}, [&] { return good->udp_ready && good->completed_heights.size() > 5; }));

  auto oversized = harness.client();
  oversized->send_tcp(proto::Bytes{0xff, 0xff, 0xff, 0x7f, 0, 0, 0, 0});  // a 2 GiB size prefix
  auto garbage = harness.client();
  proto::Bytes junk(64, 0xab);
  junk[0] = 60;  // a plausible prefix, then no FlatBuffer
  junk[1] = junk[2] = junk[3] = 0;
  garbage->send_tcp(junk);
  auto early = harness.client();
  early->send_tcp(proto::encode(proto::Ping{1, {}, 1, 1}));  // not a Hello
  const std::vector<SessionTestClient*> bad{oversized.get(), garbage.get(), early.get()};
  REQUIRE(pump_until(bad, [&] { return oversized->closed() && garbage->closed() && early->closed(); }));
  REQUIRE(oversized->errors.size() == 1);
  CHECK(oversized->errors[0].code == proto::Reason::oversized);
  REQUIRE(garbage->errors.size() == 1);
  CHECK(garbage->errors[0].code == proto::Reason::bad_identifier);
  REQUIRE(early->errors.size() == 1);
  CHECK(early->errors[0].code == proto::Reason::unexpected_message);

  // UDP: junk, an oversized datagram, a forged UdpHello, an Ack with a wrong cookie.
  auto attacker = harness.client();
  attacker->send_udp(proto::Bytes(100, 0x55));
  attacker->send_udp(proto::Bytes(1300, 0));
  proto::Bytes forged_cookie = good->welcome->udp_cookie;
  forged_cookie[20] ^= 1;
  attacker->send_udp(proto::encode(proto::UdpHello{good->welcome->session_id, forged_cookie}));
  attacker->send_udp(proto::encode(proto::Ack{good->welcome->session_id, forged_cookie, 1, 0}));
  const std::size_t before = good->completed_heights.size();
  REQUIRE(pump_until({good.get(), attacker.get()}, [&] { return good->completed_heights.size() > before + 10; }));
  CHECK(attacker->udp_bytes_in == 0);  // nothing answered any of it
  harness.check_reconstructions(*good);
  harness.stop();
  // Before proof the server never sent more UDP bytes than it received.
  CHECK(harness.hub().core().unproven_bytes_out() <= harness.hub().core().unproven_bytes_in());
  CHECK(harness.hub().core().unproven_bytes_out() > 0);  // the good client's UdpReady
}

TEST_CASE("a TCP client that stops reading never grows the server's send queue") {
  SessionCoreOptions options;
  options.send_queue_bytes = 4 * 1024;
  options.socket_send_buffer_bytes = 4096;
  SessionHarness harness(session_test_config(60), options);
  auto stalled = harness.client(4096);
  auto healthy = harness.client();
  stalled->hello(tcp_hello());
  healthy->hello(tcp_hello());
  REQUIRE(pump_until({stalled.get(), healthy.get()}, [&] {
    return stalled->completed_heights.size() > 2 && healthy->completed_heights.size() > 2;
  }));
  stalled->reading_paused = true;
  // Its stream (about 4 KB/s of small deltas on TCP) fills the socket buffers, then the send queue,
  // until the server has dropped frames for it many times (once its baseline is too old, one key
  // per key tick); meanwhile the healthy client streams.
  // Its Acks (of the last tick it read) keep it from timing out.
  const proto::Bytes keep_alive = proto::encode(
      proto::Ack{stalled->welcome->session_id, {}, stalled->completed_heights.rbegin()->first, 0});
  const std::size_t healthy_before = healthy->completed_heights.size();
  REQUIRE(pump_until({stalled.get(), healthy.get()}, [&] {
    stalled->send_tcp(keep_alive);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    return harness.server().metrics().send_queue_drops.value() > 10;
  }, std::chrono::seconds(40)));
  CHECK(healthy->completed_heights.size() > healthy_before);
  stalled->reading_paused = false;
  const std::size_t stalled_before = stalled->completed_heights.size();
  REQUIRE(pump_until({stalled.get(), healthy.get()}, [&] { return stalled->completed_heights.size() > stalled_before + 20; }));
  harness.stop();
  CHECK(harness.hub().core().peak_queued_bytes() <= options.send_queue_bytes);
  CHECK(harness.hub().core().peak_queued_bytes() > options.send_queue_bytes / 2);  // the bound was reached
  harness.check_reconstructions(*stalled);  // and it resumed on a valid baseline
  harness.check_reconstructions(*healthy);
}
