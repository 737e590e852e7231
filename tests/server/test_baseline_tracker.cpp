// BaselineTracker (Quake 3 baselines) and TokenBucket: pure session policy, no sockets.
#include "baseline_tracker.hpp"
#include "token_bucket.hpp"

#include <catch2/catch.hpp>

using namespace ocean::server;
using ocean::codec::StateId;

namespace {
const auto held = [](StateId) { return true; };
}

TEST_CASE("UDP baselines are the newest acked state; TCP ones the last queued") {
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
  // Beyond the 32-tick gap, or gone from the encoder, nothing qualifies: a key is due.
  CHECK(!tracker.choose(11 + 33, true, held));
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
