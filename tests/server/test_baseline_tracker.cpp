// BaselineTracker (Quake 3 baselines) and TokenBucket: pure session policy, no sockets.
#include "wire_limits.hpp"
#include "baseline_tracker.hpp"
#include "token_bucket.hpp"

#include <catch2/catch.hpp>

using namespace ocean::server;
using ocean::codec::StateId;

namespace {
const auto held = [](StateId) { return true; };
}

TEST_CASE("UDP baselines are the newest acked state, TCP ones the last queued") {
  BaselineTracker tracker;
  tracker.record_sent(10, StateId{10, 1}, true);  // the key, on TCP
  tracker.record_sent(11, StateId{11, 2}, false);
  tracker.record_sent(12, StateId{12, 3}, false);
  CHECK(tracker.choose(13, true, held) == StateId{10, 1});  // nothing acked yet: the TCP key
  tracker.on_ack({11, 0b1});                                 // 11 and 10 complete
  CHECK(tracker.choose(13, true, held) == StateId{11, 2});
  CHECK(tracker.choose(13, false, held) == StateId{10, 1});  // TCP ignores UDP acks
  tracker.on_ack({40, 0});  // a tick never sent: changes nothing
  CHECK(tracker.choose(13, true, held) == StateId{11, 2});
  // Beyond the baseline window, or gone from the encoder, nothing qualifies: a key is due.
  CHECK(!tracker.choose(11 + ocean::protocol::kMaxBaselineGap + 1, true, held));
  CHECK(!tracker.choose(13, true, [](StateId) { return false; }));
  tracker.reset();
  CHECK(!tracker.choose(13, true, held));
}

TEST_CASE("the token bucket never lets more than rate x time + burst through") {
  TokenBucket bucket(1000.0, 500.0, 0.0);  // 1000 B/s, 500 B burst
  std::size_t sent = 0;
  for (int i = 0; i <= 1000; ++i)          // 1 s in 1 ms steps, trying 300 B each
    if (bucket.try_take(300, i * 0.001)) sent += 300;
  CHECK(sent <= 1000 + 500);
  CHECK(sent >= 1000);
  CHECK(bucket.wait_s(300, 1.0) > 0.0);
  CHECK(TokenBucket(0.0, 0.0, 0.0).try_take(1 << 30, 0.0));  // 0 = unlimited
}

TEST_CASE("baselines prefer the grid, so sessions acking different ticks share one") {
  // Two sessions keyed at 8 on a grid of 4: their newest acks differ, their baseline does not.
  BaselineTracker a(4), b(4);
  for (BaselineTracker* t : {&a, &b}) {
    t->record_sent(8, StateId{8, 1}, true, true);
    for (ocean::Tick tick = 9; tick <= 14; ++tick) t->record_sent(tick, StateId{tick, static_cast<std::uint32_t>(tick)}, false);
  }
  a.on_ack({13, 0b11111});  // 8..13
  b.on_ack({14, 0b110111});  // 14, 13, 12, 10, 9, 8 (11 lost)
  CHECK(a.choose(15, true, held) == StateId{12, 12});
  CHECK(b.choose(15, true, held) == StateId{12, 12});
  CHECK(a.is_acked(StateId{12, 12}));
  CHECK(a.is_acked(StateId{13, 13}));   // the newest acked stays usable
  CHECK(!a.is_acked(StateId{11, 11}));
  // Off the gap limit the grid state gives way to the newest acked one.
  CHECK(a.choose(13 + ocean::protocol::kMaxBaselineGap + 1, true, held) == std::nullopt);
  CHECK(a.choose(15, true, [](StateId s) { return s.tick != 12; }) == StateId{13, 13});
  CHECK(a.root_tick() == 8u);
}

TEST_CASE("a key with nothing sent after it stays a baseline however late it is acked") {
  BaselineTracker t(4);
  t.record_sent(100, StateId{100, 1}, true, true);
  // A thin link: the ack of the key arrives long after, nothing else was sent meanwhile.
  constexpr ocean::Tick late = 100 + ocean::protocol::kMaxBaselineGap + 20;
  t.on_ack({100, 0});
  CHECK(t.choose(late, true, held) == StateId{100, 1});
  CHECK(t.choose(100 + ocean::protocol::kMaxFrameLag + 4, true, held) == std::nullopt);
  // Once later frames went out the client may have dropped the key: the baseline window applies.
  t.record_sent(late + 1, StateId{late + 1, 2}, false);
  CHECK(t.choose(late + 4, true, held) == std::nullopt);
}

TEST_CASE("a key starts a new root: nothing from before it is chosen again") {
  BaselineTracker t(4);
  t.record_sent(8, StateId{8, 1}, true, true);
  t.record_sent(12, StateId{12, 2}, false);
  t.on_ack({12, 0b1111});
  CHECK(t.choose(13, true, held) == StateId{12, 2});
  t.record_sent(16, StateId{16, 3}, true, true);  // keyed again (e.g. merged into a newer root)
  CHECK(t.root_tick() == 16u);
  CHECK(!t.is_acked(StateId{12, 2}));
  CHECK(t.choose(17, true, held) == StateId{16, 3});  // the key, on TCP until acked
  CHECK(t.choose(17, false, held) == StateId{16, 3});
}

TEST_CASE("under load a session takes an older acked grid state that is already encoded") {
  BaselineTracker t(4);
  t.record_sent(8, StateId{8, 1}, true, true);
  for (ocean::Tick tick = 9; tick <= 21; ++tick) t.record_sent(tick, StateId{tick, static_cast<std::uint32_t>(tick)}, false);
  t.on_ack({21, 0b1111111111111});  // 8..21: grid states 20, 16, 12 and 8 (the key)
  CHECK(t.choose(22, true, held) == StateId{20, 20});
  // Only 12 and 8 have an encode this tick: the newest of them.
  CHECK(t.choose_encoded(22, [](StateId s) { return s.tick == 12 || s.tick == 8; }) == StateId{12, 12});
  CHECK(t.choose_encoded(22, [](StateId s) { return s.tick == 8; }) == StateId{8, 1});
  CHECK(!t.choose_encoded(22, [](StateId s) { return s.tick == 21; }));  // not a grid state
  CHECK(!t.choose_encoded(8 + ocean::protocol::kMaxBaselineGap + 1, [](StateId s) { return s.tick == 8; }));
  // A later ack with fewer grid states in its window forgets the older ones.
  t.on_ack({21, 0b1});  // 21 and 20
  CHECK(!t.choose_encoded(22, [](StateId s) { return s.tick == 12; }));
  CHECK(t.choose_encoded(22, [](StateId s) { return s.tick == 20; }) == StateId{20, 20});
  t.reset();
  CHECK(!t.choose_encoded(22, held));
}
