// KeyingPolicy on its own: key ticks, root budgets, the key budget and which roots a key tick
// merges, from counts and times (test_key_roots.cpp drives the same policy through the core).
#include "keying_policy.hpp"

#include <catch2/catch.hpp>

using namespace ocean::server;
using ocean::Tick;

namespace {

constexpr int kTickRate = 60;
const KeyedStream kMobile{64, 2, 30};      // 64 x 64 at 30 Hz on a 60 Hz server
const KeyedStream kDesktop{512, 1, 60};    // 512 x 512 every tick

// A key's size, asked for only when a merge is weighed.
std::function<double()> bytes(double b) {
  return [b] { return b; };
}

KeyingPolicy policy(double key_bytes_per_s = 2'000'000.0) {
  KeyingOptions o;
  o.key_bytes_per_s = key_bytes_per_s;
  return KeyingPolicy(o, kTickRate, 0.0);
}

}  // namespace

TEST_CASE("keys fall on a grid of the key period, in frames of the stream") {
  const KeyingPolicy p = policy();
  // 0.5 s at 30 frames per second: every 15th frame, every 30th tick.
  for (Tick tick = 0; tick < 200; ++tick) CHECK(p.is_key_tick(kMobile, tick) == (tick % 30 == 0));
  CHECK(p.is_key_tick(kDesktop, 60));
  CHECK_FALSE(p.is_key_tick(kDesktop, 31));
}

TEST_CASE("a profile keeps as many roots as its synthesis budget pays for, at least 2, at most max_roots") {
  const KeyingPolicy p = policy();
  CHECK(p.root_budget(kMobile) == 64);  // 2048 samples a tick each: 131072 / 2048
  CHECK(p.root_cap(kMobile) == 4);
  CHECK(p.root_budget(KeyedStream{256, 2, 30}) == 4);
  CHECK(p.root_budget(kDesktop) == 2);  // one root alone is over budget: never fewer than 2
  CHECK(p.root_cap(kDesktop) == 2);
}

TEST_CASE("within the cap nothing is merged and joiners enter") {
  KeyingPolicy p = policy();
  const RootPlan plan = p.plan_roots(kMobile, {{0, 10}, {300, 2}}, 1, 1200, bytes(40.0), 20.0);
  CHECK(plan.merge.empty());
  CHECK(plan.enter);
}

TEST_CASE("beyond the cap the smallest old roots are merged, never the largest nor a young one") {
  KeyingPolicy p = policy();
  // Four roots and a joiner: five, one over the cap of 4; the merge age is 120 ticks.
  RootPlan plan = p.plan_roots(kMobile, {{0, 10}, {100, 3}, {200, 2}, {900, 1}}, 1, 1000, bytes(40.0), 20.0);
  REQUIRE(plan.merge.size() == 1);
  CHECK(plan.merge.front() == 200);  // root 900 (1 session) is 100 ticks old: too young
  CHECK(plan.enter);
  // The largest root is old and small roots are young: nothing to merge, the joiner still enters
  // (a mobile root is cheap; the merges catch up).
  plan = p.plan_roots(kMobile, {{0, 10}, {950, 1}, {960, 1}, {970, 1}}, 1, 1000, bytes(40.0), 20.0);
  CHECK(plan.merge.empty());
  CHECK(plan.enter);
}

TEST_CASE("between joins the roots are consolidated to two") {
  KeyingPolicy p = policy();
  const RootPlan plan = p.plan_roots(kMobile, {{0, 10}, {100, 1}, {200, 1}}, 0, 1000, bytes(40.0), 20.0);
  CHECK(plan.merge == std::vector<Tick>{100, 200});
  // Two roots and nobody waiting: merging one would lower nothing.
  CHECK(p.plan_roots(kMobile, {{0, 10}, {100, 1}}, 0, 1000, bytes(40.0), 20.0).merge.empty());
}

TEST_CASE("merges are paid from the key budget after the joiners' keys; desktop joiners wait for room") {
  // 1000 bytes a second, a burst of 500: room for one 400-byte key, not for a merge besides.
  KeyingPolicy p = policy(1000.0);
  RootPlan plan = p.plan_roots(kDesktop, {{0, 5}, {100, 1}}, 1, 1000, bytes(400.0), 20.0);
  CHECK(plan.merge.empty());
  CHECK_FALSE(plan.enter);  // a third desktop root is over the budget of 2: the joiner waits
  // With the budget paying, the small root is merged and the joiner enters onto this key.
  KeyingPolicy rich = policy();
  plan = rich.plan_roots(kDesktop, {{0, 5}, {100, 1}}, 1, 1000, bytes(400.0), 20.0);
  CHECK(plan.merge == std::vector<Tick>{100});
  CHECK(plan.enter);
  // Keys the burst can never hold cannot be merged: the joiner starts a root rather than wait for good.
  KeyingPolicy poor = policy(100.0);
  plan = poor.plan_roots(kDesktop, {{0, 5}, {100, 1}}, 1, 1000, bytes(400.0), 20.0);
  CHECK(plan.merge.empty());
  CHECK(plan.enter);
}

TEST_CASE("the key budget paces keys and lets a key larger than its burst through a full bucket") {
  KeyingPolicy p = policy(1000.0);  // burst 500 bytes
  CHECK(p.take_key(300.0, 0.0));
  CHECK_FALSE(p.take_key(300.0, 0.0));  // 200 left
  CHECK(p.take_key(300.0, 0.1));        // 100 more
  CHECK_FALSE(p.take_key(5000.0, 0.2));  // capped at the burst, which is not full yet
  CHECK(p.take_key(5000.0, 1.0));
}
