#include "tick_clock.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace ocean::server;

namespace {

constexpr std::int64_t kMs = 1'000'000;  // ns per ms
constexpr std::int64_t kEpochMs = 1795280400000;  // 2026-11-21T17:00:00Z

}  // namespace

TEST_CASE("deadlines do not drift over a million ticks", "[tick_clock]") {
  for (const int rate : {1, 7, 30, 60, 240}) {
    INFO("rate " << rate);
    const TickClock clock(rate, kEpochMs);
    const std::int64_t start = clock.deadline_ns(0);
    CHECK(start == kEpochMs * kMs);
    std::int64_t previous = start;
    bool all_exact = true;
    for (std::int64_t k = 1; k <= 1'000'000; ++k) {
      const std::int64_t deadline = clock.deadline_ns(k);
      // Ideal start k/rate seconds after the epoch, to within the 1 ns rounding of each deadline.
      const long double ideal = static_cast<long double>(k) * 1e9L / rate;
      const std::int64_t interval = deadline - previous;
      all_exact &= std::fabs(static_cast<long double>(deadline - start) - ideal) < 1.0L;
      all_exact &= interval >= 1'000'000'000 / rate && interval <= 1'000'000'000 / rate + 1;
      all_exact &= clock.tick_at(deadline) == k && clock.tick_at(deadline - 1) == k - 1;
      previous = deadline;
    }
    CHECK(all_exact);
  }
}

TEST_CASE("tick index is floor((now - epoch) * rate / 1000)", "[tick_clock]") {
  const TickClock clock(30, 1000);
  CHECK(clock.tick_at(1000 * kMs) == 0);
  CHECK(clock.tick_at(1000 * kMs - 1) == -1);
  CHECK(clock.tick_at(2000 * kMs) == 30);
  CHECK(clock.tick_at(2000 * kMs + 33 * kMs) == 30);
  CHECK(clock.tick_at(2000 * kMs + 34 * kMs) == 31);
  CHECK(clock.tick_at(1000 * kMs - 1000 * kMs) == -30);

  // Present-day wall clocks with the default epoch 0: the product (now * rate) exceeds 64 bits in
  // nanoseconds, so compare against 128-bit arithmetic.
  const TickClock from_zero(240, 0);
  for (std::int64_t now_ms : {std::int64_t{1795280400000}, std::int64_t{1795280400001}, std::int64_t{4102444800123}}) {
    const std::int64_t now_ns = now_ms * kMs + 123456;
    const auto expected = static_cast<std::int64_t>(static_cast<__int128>(now_ns) * 240 / 1'000'000'000);
    CHECK(from_zero.tick_at(now_ns) == expected);
  }
}

TEST_CASE("simulation time is tick / rate, precise for large tick counts", "[tick_clock]") {
  const TickClock clock(30, 0);
  CHECK(clock.sim_time_s(0) == 0.0);
  CHECK(clock.sim_time_s(45) == 1.5);
  CHECK(clock.sim_time_s(-15) == -0.5);
  const std::int64_t tick = 53'858'412'000 + 7;  // about 2026 with epoch 0
  CHECK(std::fabs(clock.sim_time_s(tick) - (1'795'280'400.0 + 7.0 / 30.0)) < 1e-6);
}

TEST_CASE("two servers with one config number ticks alike", "[tick_clock]") {
  const TickClock a(60, kEpochMs);
  const TickClock b(60, kEpochMs);
  // Different moments of the same tick give the same index and the same simulation time.
  for (std::int64_t k : {0, 1, 59, 60, 123456789}) {
    CHECK(a.tick_at(a.deadline_ns(k)) == b.tick_at(b.deadline_ns(k + 1) - 1));
    CHECK(a.sim_time_s(k) == b.sim_time_s(k));
  }
  // A server started later still lands on the same numbering.
  CHECK(a.decide(kEpochMs * kMs + 5000 * kMs, std::nullopt)->tick == 300);
  CHECK(b.decide(kEpochMs * kMs + 5000 * kMs + 16 * kMs, std::nullopt)->tick == 300);
}

TEST_CASE("catch-up policy: short delays run every tick, long ones skip ahead", "[tick_clock]") {
  const TickClock clock(30, kEpochMs, 2);
  const std::int64_t k = 1000;
  CHECK(clock.decide(clock.deadline_ns(k) + 5, std::nullopt)->tick == k);  // starts at the current tick
  CHECK_FALSE(clock.decide(clock.deadline_ns(k + 1) - 1, k));              // woke early
  CHECK_FALSE(clock.decide(clock.deadline_ns(k), k));                      // tick k is done

  auto on_time = clock.decide(clock.deadline_ns(k + 1), k);
  REQUIRE(on_time);
  CHECK(on_time->tick == k + 1);
  CHECK(on_time->skipped == 0);
  CHECK_FALSE(on_time->late);

  for (int extra : {1, 2}) {  // within max_catch_up: run the next tick, flagged late
    auto behind = clock.decide(clock.deadline_ns(k + 1 + extra), k);
    REQUIRE(behind);
    CHECK(behind->tick == k + 1);
    CHECK(behind->skipped == 0);
    CHECK(behind->late);
  }
  auto far_behind = clock.decide(clock.deadline_ns(k + 4), k);  // 3 more than the next are due
  REQUIRE(far_behind);
  CHECK(far_behind->tick == k + 4);
  CHECK(far_behind->skipped == 3);
  CHECK(far_behind->late);

  const TickClock strict(30, kEpochMs, 0);
  auto jump = strict.decide(strict.deadline_ns(k + 2), k);
  CHECK(jump->tick == k + 2);
  CHECK(jump->skipped == 1);
}

TEST_CASE("a simulated loop accounts for every tick as run or skipped", "[tick_clock]") {
  // Virtual time: the loop sleeps until the next deadline, and each tick costs `cost_ns`, except
  // one stall. No real sleeping.
  const TickClock clock(30, kEpochMs, 2);
  const std::int64_t period = 1'000'000'000 / 30;
  struct Scenario {
    std::int64_t cost_ns;
    std::int64_t stall_ns;
    std::int64_t expect_skipped;
  };
  for (const Scenario s : {Scenario{period / 2, 0, 0}, Scenario{period / 2, 2 * period, 0},
                           // Tick 99 ends 10.5 periods late: ticks 100..108 are skipped, 109 runs.
                           Scenario{period / 2, 10 * period, 9}}) {
    INFO("stall " << s.stall_ns / period << " periods");
    std::int64_t now = clock.deadline_ns(0);
    std::optional<std::int64_t> last;
    std::int64_t run = 0, skipped = 0, late = 0, out_of_order = 0;
    for (int wake = 0; wake < 20000; ++wake) {
      const auto decision = clock.decide(now, last);
      if (!decision) {
        now = clock.deadline_ns(*last + 1);  // sleep until due
        continue;
      }
      if (last && decision->tick != *last + 1 + decision->skipped) ++out_of_order;
      last = decision->tick;
      ++run;
      skipped += decision->skipped;
      late += decision->late;
      now += s.cost_ns + (run == 100 ? s.stall_ns : 0);
    }
    CHECK(out_of_order == 0);
    CHECK(skipped == s.expect_skipped);
    CHECK(run + skipped == *last + 1);  // every tick from 0 to the last either ran or was skipped
    if (s.stall_ns == 0) CHECK(late == 0);
    else CHECK(late > 0);
  }
}

TEST_CASE("TickClock refuses a non-positive rate", "[tick_clock]") {
  CHECK_THROWS_WITH(TickClock(0, 0), Catch::Contains("rate_hz"));
  CHECK_THROWS_WITH(TickClock(30, 0, -1), Catch::Contains("max_catch_up"));
}
