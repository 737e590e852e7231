// Key roots (README-server.md "Fan-out"): sessions keyed at different ticks cost one encode each
// per tick, so a profile keeps at most its root cap: the smallest old roots are keyed again onto
// the current key tick, and a joiner waits while no root is old enough to make room. In memory,
// with the real simulation and a fake clock: the encodes never exceed the cap, no session loses
// a frame to a merge, joiners wait a bounded time, and keys stay within the key byte budget.
#include <catch2/catch.hpp>

#include "core_rig.hpp"
#include "memory_links.hpp"
#include "message_builders.hpp"
#include "verify_message.hpp"

#include <algorithm>
#include <map>
#include <set>

using namespace ocean;
using namespace ocean::server;
using ocean::test::CoreRig;
using ocean::test::MemoryDatagrams;
using ocean::test::MemoryLink;
namespace proto = ocean::protocol;

namespace {

struct Sent {
  Tick tick;
  bool key;
  std::size_t bytes;
};

// TCP viewers of the mobile profile joining a core with the server's fan-out grid, recording
// every frame the core sends each of them and every tick's encodes.
struct RootsRig {
  explicit RootsRig(SessionCoreOptions options) : rig(ocean::test::core_test_config(), options, datagrams, 7701, 0) {
    rig.core().set_frame_observer([this](std::uint64_t session, const SharedFrame& frame) {
      sent[session].push_back({frame.encoded->reconstruction.tick, frame.encoded->key, frame.bytes});
    });
    rig.core().set_tick_observer([this](const CoreTickStats& stats) { encodes[stats.tick] = stats.encodes; });
  }
  std::uint64_t join(int port) {
    auto link = std::make_shared<MemoryLink>("127.0.0.1:" + std::to_string(port));
    rig.core().open(link, CoreRig::at(now));
    link->deliver(proto::encode(proto::Hello{1, 0, wire::Transport::tcp, "t"}), CoreRig::at(now));
    links.push_back(link);
    for (proto::Bytes& message : link->take()) {
      const auto verified = proto::verify_message(message, {proto::Sender::server, wire::Transport::tcp});
      if (verified && verified.message->body_type() == wire::Body::Welcome) return verified.message->body_as_Welcome()->session_id();
    }
    return 0;
  }
  void step() {
    now += rig.tick_period_s();
    rig.step(now);
    for (auto& link : links) link->take();  // a reader that keeps up
  }
  MemoryDatagrams datagrams;
  CoreRig rig;
  double now = 0.0;
  std::vector<std::shared_ptr<MemoryLink>> links;
  std::map<std::uint64_t, std::vector<Sent>> sent;
  std::map<Tick, std::size_t> encodes;
};

SessionCoreOptions fan_out_options() {
  SessionCoreOptions options;
  options.key_period_s = 0.5;  // key ticks every 15 ticks at 30 Hz
  options.baseline_align_frames = 4;
  options.max_roots = 2;
  options.root_merge_age_s = 1.0;
  options.root_samples_per_tick = 2.0 * 64 * 64;  // roots as costly as desktop ones: a budget of 2
  return options;
}

// The bytes of one modeled mobile key of this scene.
std::size_t mobile_key_bytes() {
  RootsRig probe(fan_out_options());
  REQUIRE(probe.join(40999) != 0);
  for (int k = 0; k < 16; ++k) probe.step();
  REQUIRE(!probe.sent.begin()->second.empty());
  return probe.sent.begin()->second.front().bytes;
}

}  // namespace

TEST_CASE("key roots stay within the cap: old roots merge onto a newer key, joiners wait for room, nobody loses a frame") {
  SessionCoreOptions options = fan_out_options();
  SECTION("with room for every key") {}
  SECTION("with a key budget that paces the merges (8 keys a second, burst 4)") {
    options.key_bytes_per_s = 8.0 * static_cast<double>(mobile_key_bytes());
  }
  RootsRig r(options);
  std::vector<std::uint64_t> ids;
  std::map<std::uint64_t, Tick> joined;
  for (int i = 0; i < 6; ++i) {  // one viewer per key tick: six roots without the cap
    ids.push_back(r.join(41000 + i));
    REQUIRE(ids.back() != 0);
    joined[ids.back()] = r.rig.tick();
    for (int k = 0; k < 15; ++k) r.step();
  }
  for (int k = 0; k < 120; ++k) r.step();  // 4 s: every root is old enough to merge

  std::size_t most = 0;
  for (const auto& [tick, n] : r.encodes) most = std::max(most, n);
  INFO("most encodes in a tick " << most);
  CHECK(most == 2);  // the cap held on every tick (a merge tick: the new key and the largest root)
  const Tick last = r.rig.tick();
  CHECK(r.rig.metrics().root_merges.value() >= 3.0);
  CHECK(r.rig.metrics().keys_deferred_roots.value() > 0.0);  // some joiner waited for room

  for (const std::uint64_t id : ids) {
    const std::vector<Sent>& frames = r.sent[id];
    REQUIRE(!frames.empty());
    CHECK(frames.front().key);
    // A joiner waits for a root old enough to merge (30 ticks) and the key tick after it, or for
    // the key budget to pay for the merge (8 keys a second).
    INFO("session " << id << " joined at tick " << joined[id] << ", first key at " << frames.front().tick);
    CHECK(frames.front().tick - joined[id] <= 60);
    // From its first key on, a frame every tick: keyed again or not, nobody waited.
    CHECK(frames.back().tick == last);
    CHECK(frames.size() == static_cast<std::size_t>(last - frames.front().tick + 1));
  }
  std::size_t keys = 0;
  for (const auto& [id, frames] : r.sent) {
    std::vector<Tick> key_ticks;
    for (const Sent& s : frames)
      if (s.key) key_ticks.push_back(s.tick);
    keys += key_ticks.size();
    // A session pays at most one extra key per root_merge_age_s (30 ticks).
    for (std::size_t i = 1; i < key_ticks.size(); ++i) CHECK(key_ticks[i] - key_ticks[i - 1] >= 30);
  }
  CHECK(keys > ids.size());  // merged sessions were keyed again
}

TEST_CASE("keys go out within the key byte budget, viewers beyond it wait for the next key ticks") {
  SessionCoreOptions options = fan_out_options();
  const std::size_t key_bytes = mobile_key_bytes();
  options.key_bytes_per_s = 2.5 * static_cast<double>(key_bytes);  // 2.5 keys a second, burst 1.25
  RootsRig r(options);
  for (int i = 0; i < 6; ++i) REQUIRE(r.join(41000 + i) != 0);  // six viewers in one tick
  for (int k = 0; k < 150; ++k) r.step();                        // 5 s
  std::vector<Tick> key_ticks;
  for (const auto& [id, frames] : r.sent) {
    REQUIRE(!frames.empty());  // everyone got a key in the end
    CHECK(frames.front().key);
    key_ticks.push_back(frames.front().tick);
  }
  REQUIRE(key_ticks.size() == 6);
  std::sort(key_ticks.begin(), key_ticks.end());
  // rate x time + burst: never more than 1.25 + 2.5 per second of keys by any tick (keys of
  // later ticks may be a few bytes larger or smaller than the probe's: 10 % slack).
  for (std::size_t i = 0; i < key_ticks.size(); ++i) {
    const double seconds = static_cast<double>(key_ticks[i] - key_ticks.front()) / 30.0;
    CHECK(static_cast<double>(i + 1) <= 1.1 * (1.25 + 2.5 * seconds));
  }
  CHECK(key_ticks.back() > key_ticks.front());  // the budget made some wait
  CHECK(r.rig.metrics().frames_skipped_load.value() > 0.0);
}

TEST_CASE("cheap roots let joiners in at once, and the merges bring them back to the cap") {
  SessionCoreOptions options = fan_out_options();
  options.root_samples_per_tick = 32.0 * 64 * 64;  // mobile roots: 32 fit the budget, the cap stays 2
  RootsRig r(options);
  std::map<std::uint64_t, Tick> joined;
  for (int i = 0; i < 6; ++i) {
    const std::uint64_t id = r.join(41000 + i);
    REQUIRE(id != 0);
    joined[id] = r.rig.tick();
    for (int k = 0; k < 15; ++k) r.step();
  }
  for (int k = 0; k < 120; ++k) r.step();
  CHECK(r.rig.metrics().keys_deferred_roots.value() == 0.0);
  for (const auto& [id, tick] : joined) {
    REQUIRE(!r.sent[id].empty());
    CHECK(r.sent[id].front().tick - tick <= 15);  // the next key tick
  }
  std::size_t most = 0;
  for (const auto& [tick, n] : r.encodes) most = std::max(most, n);
  CHECK(most >= 3);  // beyond the cap for a while
  const Tick last = r.rig.tick();
  for (Tick t = last - 14; t <= last; ++t) CHECK(r.encodes[t] <= 2);
}
