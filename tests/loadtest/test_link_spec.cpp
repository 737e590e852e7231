#include "link_spec.hpp"

#include <catch2/catch.hpp>

using ocean::loadtest::parse_link_spec;
using ocean::loadtest::parse_rate_bps;

TEST_CASE("link spec: the issue's example parses with units") {
  auto r = parse_link_spec("rate=256kbit,delay=80ms,jitter=20ms,loss=5%,reorder=1%,dup=0.5%");
  REQUIRE(r.error.empty());
  CHECK(r.spec.rate_bps == Approx(256000));
  CHECK(r.spec.delay_ms == Approx(80));
  CHECK(r.spec.jitter_ms == Approx(20));
  CHECK(r.spec.loss == Approx(0.05));
  CHECK(r.spec.reorder == Approx(0.01));
  CHECK(r.spec.duplicate == Approx(0.005));
  CHECK(r.spec.impaired());
}

TEST_CASE("link spec: empty and 'none' mean an unimpaired link") {
  CHECK_FALSE(parse_link_spec("").spec.impaired());
  CHECK_FALSE(parse_link_spec("none").spec.impaired());
}

TEST_CASE("link spec: other units") {
  auto r = parse_link_spec("rate=2mbit, delay=0.1s, queue=16kB");
  REQUIRE(r.error.empty());
  CHECK(r.spec.rate_bps == Approx(2e6));
  CHECK(r.spec.delay_ms == Approx(100));
  CHECK(r.spec.queue_bytes == 16 * 1024);
}

TEST_CASE("link spec: each bad field is named") {
  CHECK_THAT(parse_link_spec("rate=fast").error, Catch::Contains("rate='fast'"));
  CHECK_THAT(parse_link_spec("delay=-5ms").error, Catch::Contains("delay"));
  CHECK_THAT(parse_link_spec("loss=150%").error, Catch::Contains("loss"));
  CHECK_THAT(parse_link_spec("bogus=1").error, Catch::Contains("unknown key 'bogus'"));
  CHECK_THAT(parse_link_spec("loss").error, Catch::Contains("not key=value"));
  CHECK_THAT(parse_link_spec("delay=10ms,jitter=20ms").error, Catch::Contains("jitter"));
  CHECK_THAT(parse_link_spec("queue=10").error, Catch::Contains("queue"));
}

TEST_CASE("link spec: a rate alone, as --bandwidth takes it") {
  CHECK(parse_rate_bps("32kbit") == 32000.0);
  CHECK(parse_rate_bps("2mbit") == 2e6);
  CHECK(parse_rate_bps("4kbps") == 32000.0);
  CHECK(parse_rate_bps(" 16000 ") == 16000.0);
  CHECK_FALSE(parse_rate_bps("32 kbit/s"));
  CHECK_FALSE(parse_rate_bps("-1"));
  CHECK_FALSE(parse_rate_bps(""));
}
