// Scenario parsing, explicit flags over a scenario, and errors that name the flag.
#include <catch2/catch.hpp>

#include "loadtest_options.hpp"
#include "scenario.hpp"

using namespace ocean::loadtest;

TEST_CASE("options: a scenario fills profile, transport and link") {
  const OptionsResult r = parse_options({"--scenario", "mobile-3g", "--clients", "4"});
  REQUIRE(r.error.empty());
  CHECK(r.options.profile == "mobile");
  CHECK(r.options.transport == "udp");
  CHECK(r.options.link.rate_bps == Approx(256000));
  CHECK(r.options.link.delay_ms == Approx(80));
  CHECK(r.options.link.loss == Approx(0.05));
  CHECK(r.options.clients == 4);
}

TEST_CASE("options: explicit flags override the scenario, in any order") {
  const OptionsResult r = parse_options({"--link", "delay=5ms", "--scenario", "tcp-fallback", "--profile", "lite"});
  REQUIRE(r.error.empty());
  CHECK(r.options.transport == "tcp");  // from the scenario
  CHECK(r.options.profile == "lite");
  CHECK(r.options.link.delay_ms == Approx(5));
  CHECK(r.options.link.rate_bps == 0.0);  // the scenario's rate is not merged in
}

TEST_CASE("options: every scenario parses") {
  for (const Scenario& s : all_scenarios()) {
    const OptionsResult r = parse_options({"--scenario", std::string(s.name)});
    INFO(s.name);
    CHECK(r.error.empty());
    CHECK(r.options.link.impaired() == !s.link.empty());
  }
}

TEST_CASE("options: bad values name their flag") {
  auto error_of = [](std::vector<std::string> args) { return parse_options(args).error; };
  CHECK_THAT(error_of({"--clients", "0"}), Catch::Contains("--clients"));
  CHECK_THAT(error_of({"--server", "localhost"}), Catch::Contains("--server"));
  CHECK_THAT(error_of({"--server", "localhost:99999"}), Catch::Contains("--server"));
  CHECK_THAT(error_of({"--transport", "sctp"}), Catch::Contains("--transport") && Catch::Contains("udp, tcp or ws"));
  CHECK(error_of({"--transport", "ws"}).empty());
  const OptionsResult browsers = parse_options({"--scenario", "browser-3g"});
  REQUIRE(browsers.error.empty());
  CHECK(browsers.options.transport == "ws");  // the scenario's own transport
  CHECK_THAT(error_of({"--profile", "phone"}), Catch::Contains("--profile"));
  CHECK_THAT(error_of({"--scenario", "moon"}), Catch::Contains("--scenario"));
  CHECK_THAT(error_of({"--link", "loss=150%"}), Catch::Contains("--link"));
  CHECK_THAT(error_of({"--duration", "0"}), Catch::Contains("--duration"));
  CHECK_FALSE(error_of({"--bogus"}).empty());
  const OptionsResult ok = parse_options({"--server", "10.0.0.2:7100"});
  REQUIRE(ok.error.empty());
  CHECK(ok.options.host == "10.0.0.2");
  CHECK(ok.options.port == "7100");
}

TEST_CASE("options: --server takes a comma list and repeats, in order, a bad entry is named") {
  using ocean::client::ServerEndpoint;
  const OptionsResult list = parse_options({"--server", "10.0.0.1:7100,[::1]:7200", "--server", "b.example:7300"});
  REQUIRE(list.error.empty());
  CHECK(list.options.servers ==
        std::vector<ServerEndpoint>{{"10.0.0.1", "7100"}, {"::1", "7200"}, {"b.example", "7300"}});
  CHECK(list.options.host == "10.0.0.1");
  CHECK(parse_options({}).options.servers == std::vector<ServerEndpoint>{{"127.0.0.1", "7700"}});
  CHECK_THAT(parse_options({"--server", "a:1,,b:2"}).error, Catch::Contains("empty entry"));
  CHECK_THAT(parse_options({"--server", "a:1,b:0"}).error, Catch::Contains("'b:0'"));
  CHECK_THAT(parse_options({"--server", "a:1,b"}).error, Catch::Contains("'b' is not HOST:PORT"));
  CHECK_THAT(parse_options({"--server", "::1:7100"}).error, Catch::Contains("brackets"));
}

TEST_CASE("options: the announced bandwidth is --bandwidth, else the scenario's, else the link's rate") {
  CHECK(parse_options({"--scenario", "mobile-3g"}).options.bandwidth_bps == 256000);
  CHECK(parse_options({"--scenario", "desktop-lan"}).options.bandwidth_bps == 0);
  CHECK(parse_options({"--scenario", "mobile-3g", "--link", "delay=5ms"}).options.bandwidth_bps == 0);
  CHECK(parse_options({"--link", "rate=1mbit"}).options.bandwidth_bps == 1000000);
  CHECK(parse_options({"--scenario", "mobile-3g", "--bandwidth", "32kbit"}).options.bandwidth_bps == 32000);
  CHECK(parse_options({"--bandwidth", "16000"}).options.bandwidth_bps == 16000);
  CHECK(parse_options({"--bandwidth", "4kbps"}).options.bandwidth_bps == 32000);
  CHECK(parse_options({"--scenario", "mobile-3g", "--bandwidth", "0"}).options.bandwidth_bps == 0);
  CHECK_THAT(parse_options({"--bandwidth", "fast"}).error, Catch::Contains("--bandwidth"));
  CHECK_THAT(parse_options({"--bandwidth", "-5kbit"}).error, Catch::Contains("--bandwidth"));
}

TEST_CASE("scenarios: server needs are described, and a Welcome that differs is named") {
  const Scenario* old = find_scenario("old-epoch");
  REQUIRE(old);
  CHECK(describe(old->server) == "tick-rate=240 epoch=now-4018d");
  CHECK(describe(find_scenario("mobile-3g")->server).empty());
  CHECK(describe(find_scenario("weather-front")->server) == "schedule=weather-front");
  const double now = 1.8e9;
  const std::int64_t epoch_ok = static_cast<std::int64_t>((now - 4018 * 86400.0) * 1000);
  CHECK(server_mismatch(old->server, 240, epoch_ok, now).empty());
  CHECK_THAT(server_mismatch(old->server, 30, epoch_ok, now), Catch::Contains("30 Hz"));
  CHECK_THAT(server_mismatch(old->server, 240, 1767225600000, now), Catch::Contains("epoch"));
  CHECK(server_mismatch(find_scenario("mobile-3g")->server, 30, 0, now).empty());
}

TEST_CASE("scenarios: the thin links announce their rate") {
  CHECK(announced_bandwidth_bps(*find_scenario("edge-2g")) == 32000);
  CHECK(announced_bandwidth_bps(*find_scenario("gprs")) == 16000);
  CHECK(announced_bandwidth_bps(*find_scenario("old-epoch")) == 0);
  CHECK(parse_options({"--scenario", "edge-2g"}).options.bandwidth_bps == 32000);
}
