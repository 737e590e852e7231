// AckWindow: the latest complete tick plus a bit for each of the 32 ticks before it (the
// reliable/yojimbo convention), built from whatever set of complete ticks a client holds. Ticks
// are 64-bit: a window works the same across 2^32 and near the top of the range.
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "ack_window.hpp"

using namespace ocean::protocol;
using ocean::Tick;

namespace {

// The window after each tick completes, in this order.
AckWindow complete_in_order(std::initializer_list<Tick> ticks) {
  const std::vector<Tick> all(ticks);
  return *ack_window(all);
}

}  // namespace

TEST_CASE("ack state is the latest tick plus a bit per earlier tick") {
  for (Tick base : {Tick{0}, Tick{0xFFFF'FFF0u}, (Tick{1} << 63) - 20}) {
    INFO("base " << base);
    AckWindow window{base + 10, 0};
    CHECK(window == AckWindow{base + 10, 0});
    window = window.with(base + 12);  // 11 missing
    CHECK(window == AckWindow{base + 12, 0b10u});  // bit 1 = tick 10
    window = window.with(base + 11);  // arrives late
    CHECK(window == AckWindow{base + 12, 0b11u});
    window = window.with(base + 44);  // 32 ticks after 12: tick 12 is bit 31
    CHECK(window == AckWindow{base + 44, 1u << 31});
    CHECK(window.contains(base + 12));
    CHECK_FALSE(window.contains(base + 11));
    CHECK(window.with(base + 11) == window);  // older than the window: nothing changes
    CHECK(window.with(base + 44) == window);  // the latest again
    window = window.with(base + 100);  // far ahead: the field empties
    CHECK(window == AckWindow{base + 100, 0});
    CHECK_FALSE(window.contains(base + 44));
    CHECK_FALSE(window.contains(base + 101));
  }
}

TEST_CASE("a window spans 2^32 and the top of the tick range") {
  const Tick wrap = Tick{1} << 32;
  const AckWindow across = complete_in_order({wrap - 3, wrap - 1, wrap, wrap + 2});
  CHECK(across.latest_tick == wrap + 2);
  CHECK(across.bits == ((1u << 1) | (1u << 2) | (1u << 4)));  // ages 2, 3, 5; wrap + 1 (age 1) is missing
  for (Tick t : {wrap - 3, wrap - 1, wrap, wrap + 2}) CHECK(across.contains(t));
  for (Tick t : {wrap - 4, wrap - 2, wrap + 1, wrap + 3}) CHECK_FALSE(across.contains(t));

  const Tick top = std::numeric_limits<Tick>::max();
  const AckWindow high = complete_in_order({top - 40, top - 32, top});
  CHECK(high == AckWindow{top, 1u << 31});
  CHECK(high.contains(top - 32));
  CHECK_FALSE(high.contains(top - 40));
  CHECK(complete_in_order({0, top}) == AckWindow{top, 0});  // a jump larger than any shift
}

TEST_CASE("ack_window of a tick set does not depend on order and matches contains()") {
  std::mt19937 rng(5);
  for (Tick offset : {Tick{0}, Tick{0xFFFF'FFC0u}}) {
    std::uniform_int_distribution<Tick> tick(offset + 1000, offset + 1080);
    for (int round = 0; round < 200; ++round) {
      std::vector<Tick> ticks(1 + round % 20);
      for (auto& t : ticks) t = tick(rng);
      const auto window = ack_window(ticks);
      REQUIRE(window);
      const Tick newest = *std::max_element(ticks.begin(), ticks.end());
      CHECK(window->latest_tick == newest);
      for (Tick t = offset + 990; t <= offset + 1090; ++t) {
        const bool in_set = std::find(ticks.begin(), ticks.end(), t) != ticks.end();
        CHECK(window->contains(t) == (in_set && t <= newest && newest - t <= kAckWindowTicks));
      }
      std::shuffle(ticks.begin(), ticks.end(), rng);
      CHECK(ack_window(ticks) == window);
    }
  }
  CHECK_FALSE(ack_window({}));
}

TEST_CASE("without(t) is the window of the set without t, except for the latest tick") {
  const std::vector<Tick> ticks = {100, 101, 103, 110, 130, 131, 132};
  const AckWindow window = *ack_window(ticks);
  for (Tick t : ticks) {
    if (t == 132) {
      CHECK(window.without(t) == window);  // the latest stays: it is what the window is relative to
      continue;
    }
    std::vector<Tick> rest;
    for (Tick u : ticks)
      if (u != t) rest.push_back(u);
    CHECK(window.without(t) == *ack_window(rest));
  }
  CHECK(window.without(99) == window);   // beyond the window
  CHECK(window.without(200) == window);  // newer than the latest
}
