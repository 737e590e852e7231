// ThreadSchedule: the kernel's per-thread figures are read as seconds, anything else is refused,
// and a thread that spins shows its running time grow.
#include "thread_schedule.hpp"

#include <catch2/catch.hpp>

#include <chrono>

using ocean::server::parse_schedstat;
using ocean::server::this_thread_schedule;

TEST_CASE("thread schedule: schedstat's three numbers are run and wait nanoseconds", "[admission]") {
  const auto s = parse_schedstat("344573255 58417 18\n");
  REQUIRE(s);
  CHECK(s->ran_s == Approx(0.344573255));
  CHECK(s->waited_s == Approx(0.000058417));
  CHECK(!parse_schedstat(""));
  CHECK(!parse_schedstat("12 34"));
  CHECK(!parse_schedstat("12 x 5"));
  CHECK(!parse_schedstat("1 2 3 4"));
  CHECK(!parse_schedstat("-1 2 3"));
}

TEST_CASE("thread schedule: this thread's running time grows while it spins", "[admission]") {
  const auto before = this_thread_schedule();
  if (!before) {
    WARN("the kernel keeps no per-thread scheduler statistics here");
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  volatile unsigned sink = 0;
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(50)) sink = sink + 1;
  const auto after = this_thread_schedule();
  REQUIRE(after);
  // 50 ms of wall time spinning: most of it on a CPU even on a shared machine.
  CHECK(after->ran_s - before->ran_s > 0.005);
  CHECK(after->waited_s >= before->waited_s);
}
