#include "config_loader.hpp"
#include "config_options.hpp"
#include "profile.hpp"
#include "temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

using namespace ocean::server;
namespace model = ocean::model;
using ocean::test_support::TempFile;
using Outcome = ConfigLoadResult::Outcome;

namespace {

ConfigLoadResult load(std::vector<std::string> args) {
  args.insert(args.begin(), "ocean-server");
  return load_config(args);
}

}  // namespace

TEST_CASE("no flags gives the documented defaults", "[config]") {
  const ConfigLoadResult r = load({});
  REQUIRE(r.outcome == Outcome::run);
  CHECK(r.config.listen == ListenAddress{"0.0.0.0", 7700});
  CHECK_FALSE(r.config.udp_listen);
  REQUIRE(r.config.metrics_listen);
  CHECK(*r.config.metrics_listen == ListenAddress{"127.0.0.1", 9464});
  CHECK(r.config.scene.size_x == 256);
  CHECK(r.config.tick_rate_hz == 30);
  CHECK(r.config.epoch_unix_ms == 1767225600000);  // 2026-01-01T00:00:00Z, per Python's datetime
  CHECK(r.config.profiles == std::vector<std::string>{"mobile", "desktop"});
  CHECK(r.config.stream_listen.empty());  // no WebSocket port unless asked for
  CHECK(r.config.ws_origins.empty());
  CHECK(r.config.admission_target == 0.85);  // AdmissionBudget's target
}

TEST_CASE("flags set every kind of option", "[config]") {
  TempFile token("  s3cret\n");
  const ConfigLoadResult r =
      load({"--listen", "127.0.0.1:9000", "--udp-listen", "[::1]:9001", "--metrics-listen", "off", "--size", "512",
            "--patch", "300", "--spectrum", "jonswap", "--spreading", "cos2s", "--wind-speed", "12.5", "--wind-dir",
            "45", "--fetch", "50000", "--amplitude", "2", "--depth", "40", "--choppiness", "1.5", "--small-wave",
            "0.1", "--seed", "18446744073709551615", "--tick-rate", "60", "--epoch", "2026-11-21T17:00:00Z",
            "--profiles", "lite, desktop-choppy", "--max-clients", "3", "--admission-target", "1.5", "--admin-token-file", token.path(),
            "--idle-timeout", "2.5", "--log-level", "debug", "--ws-listen", "0.0.0.0:7701", "--ws-origins",
            "https://ocean.example:8443, http://localhost:8080"});
  REQUIRE(r.message == "");
  REQUIRE(r.outcome == Outcome::run);
  const ServerConfig& c = r.config;
  CHECK(c.listen == ListenAddress{"127.0.0.1", 9000});
  CHECK(*c.udp_listen == ListenAddress{"::1", 9001});
  CHECK_FALSE(c.metrics_listen);
  CHECK(c.scene.size_x == 512);
  CHECK(c.scene.size_z == 512);
  CHECK(c.scene.patch_x_m == 300.0);
  CHECK(c.scene.patch_z_m == 300.0);
  CHECK(c.scene.spectrum == ocean::model::SpectrumKind::jonswap);
  CHECK(c.scene.spreading == ocean::model::SpreadingKind::cos2s);
  CHECK(c.scene.wind_speed_mps == 12.5);
  CHECK(c.scene.wind_dir_deg == 45.0);
  CHECK(c.scene.fetch_m == 50000.0);
  CHECK(c.scene.amplitude == 2.0);
  CHECK(c.scene.depth_m == 40.0);
  CHECK(c.scene.choppiness == 1.5);
  CHECK(c.scene.small_wave_m == 0.1);
  CHECK(c.scene.seed == 18446744073709551615ull);
  CHECK(c.tick_rate_hz == 60);
  CHECK(c.epoch_unix_ms == 1795280400000);  // from Python's datetime
  CHECK(c.profiles == std::vector<std::string>{"lite", "desktop-choppy"});
  CHECK(c.max_clients == 3);
  CHECK(c.admission_target == 1.5);
  CHECK_FALSE(load({"--admission-target", "off"}).config.admission_target);
  CHECK(c.admin_token == "s3cret");
  CHECK(c.idle_timeout_s == 2.5);
  CHECK(c.log_level == "debug");
  CHECK(c.stream_listen.at("ws") == ListenAddress{"0.0.0.0", 7701});
  CHECK(c.ws_origins == std::vector<std::string>{"https://ocean.example:8443", "http://localhost:8080"});
}

TEST_CASE("the --help text documents every option", "[config]") {
  const ConfigLoadResult r = load({"--help"});
  REQUIRE(r.outcome == Outcome::show_help);
  for (const ConfigOption& option : config_options()) {
    INFO(option.name);
    CHECK(r.message.find("--" + std::string(option.name) + " ") != std::string::npos);
    CHECK(r.message.find(std::string(option.help)) != std::string::npos);
  }
  CHECK(r.message.find("--config") != std::string::npos);
  CHECK(r.message.find("[[schedule]]") != std::string::npos);
}

TEST_CASE("the --help-json output lists every option with its default and every profile, and --profiles' help names them",
          "[config]") {
  const ConfigLoadResult r = load({"--help-json"});
  REQUIRE(r.outcome == Outcome::show_json);
  const ServerConfig defaults;
  for (const ConfigOption& option : config_options()) {
    INFO(option.name);
    CHECK(r.message.find("{\"name\": \"" + std::string(option.name) + "\", \"value_name\"") != std::string::npos);
  }
  const std::string profiles_help(find_config_option("profiles")->help);
  for (const ocean::Profile& profile : ocean::all_profiles()) {
    INFO(profile.name);
    CHECK(r.message.find("{\"id\": " + std::to_string(profile.id) + ", \"name\": \"" + std::string(profile.name) + "\"") !=
          std::string::npos);
    CHECK(profiles_help.find(profile.name) != std::string::npos);
  }
  CHECK(r.message.find("\"default\": \"" + std::to_string(defaults.max_clients) + "\"") != std::string::npos);
}

TEST_CASE("a TOML file sets options and flags override it", "[config]") {
  TempFile file(R"(
listen = "127.0.0.1:7001"
wind-speed = 5
spectrum = "jonswap"
depth = "deep"
profiles = ["mobile", "lite"]
epoch = 2026-11-21T18:00:00.250+01:00
tick-rate = 60
ws-listen = "127.0.0.1:7002"
tls-cert = "/etc/ocean/fullchain.pem"
tls-key = "/etc/ocean/privkey.pem"
)");
  const ConfigLoadResult from_file = load({"--config", file.path()});
  REQUIRE(from_file.message == "");
  CHECK(from_file.config.listen.port == 7001);
  CHECK(from_file.config.scene.wind_speed_mps == 5.0);
  CHECK(from_file.config.scene.spectrum == ocean::model::SpectrumKind::jonswap);
  CHECK(from_file.config.tls_cert == "/etc/ocean/fullchain.pem");
  CHECK(from_file.config.tls_key == "/etc/ocean/privkey.pem");
  CHECK(std::isinf(from_file.config.scene.depth_m));
  CHECK(from_file.config.profiles == std::vector<std::string>{"mobile", "lite"});
  CHECK(from_file.config.epoch_unix_ms == 1795280400250);  // same instant as 17:00:00.250Z
  CHECK(from_file.config.tick_rate_hz == 60);
  CHECK(from_file.config.stream_listen.at("ws") == ListenAddress{"127.0.0.1", 7002});

  const ConfigLoadResult overridden = load({"--wind-speed", "7", "--config", file.path(), "--depth", "30"});
  REQUIRE(overridden.message == "");
  CHECK(overridden.config.scene.wind_speed_mps == 7.0);
  CHECK(overridden.config.scene.depth_m == 30.0);
  CHECK(overridden.config.listen.port == 7001);  // untouched by flags

  // A transport's listen option turned off over an address takes the transport out.
  ServerConfig config;
  config.stream_listen["ws"] = ListenAddress{"127.0.0.1", 7002};
  CHECK(apply_config_toml(config, "ws-listen = \"off\"\n", "off.toml") == "");
  CHECK(config.stream_listen.empty());
}

TEST_CASE("every kind of bad value is refused with a message naming it", "[config]") {
  TempFile empty_token("\n  \n");
  TempFile bad_key("not-hex");
  struct Case {
    std::vector<std::string> args;
    std::vector<std::string> mentions;
  };
  const Case cases[] = {
      {{"--size", "100"}, {"--size", "power of two"}},
      {{"--size", "abc"}, {"--size", "not an integer"}},
      {{"--patch", "0"}, {"--patch", "patch_x_m"}},
      {{"--spectrum", "pierson"}, {"--spectrum", "pierson", "phillips, jonswap"}},
      {{"--spreading", "flat"}, {"--spreading", "cos2s"}},
      {{"--wind-speed", "-1"}, {"--wind-speed", "[0, 100]"}},
      {{"--wind-speed", "nan"}, {"--wind-speed", "finite"}},
      {{"--wind-speed", "12knots"}, {"--wind-speed", "not a number"}},
      {{"--wind-dir", "east"}, {"--wind-dir", "not a number"}},
      {{"--fetch", "0"}, {"--fetch", "fetch_m"}},
      {{"--amplitude", "-2"}, {"--amplitude"}},
      {{"--depth", "shallow"}, {"--depth", "deep"}},
      {{"--depth", "-3"}, {"--depth", "depth_m"}},
      {{"--choppiness", "-1"}, {"--choppiness"}},
      {{"--small-wave", "-1"}, {"--small-wave"}},
      {{"--seed", "-1"}, {"--seed", "not an unsigned 64-bit integer"}},
      {{"--listen", "1.2.3.4:70000"}, {"--listen", "0..65535"}},
      {{"--listen", "localhost:80"}, {"--listen", "not an IPv4 or IPv6 literal"}},
      {{"--listen", "1.2.3.4"}, {"--listen", "ADDR:PORT"}},
      {{"--udp-listen", "1.2.3.4:x"}, {"--udp-listen", "port"}},
      {{"--udp-public-port", "70000"}, {"--udp-public-port", "0..65535"}},
      {{"--udp-public-port", "-1"}, {"--udp-public-port", "0..65535"}},
      {{"--metrics-listen", "on"}, {"--metrics-listen", "ADDR:PORT"}},
      {{"--ws-listen", "7701"}, {"--ws-listen", "ADDR:PORT"}},
      {{"--ws-origins", "ocean.example"}, {"--ws-origins", "'ocean.example'", "scheme://host[:port]"}},
      {{"--ws-origins", "https://ocean.example/viewer"}, {"--ws-origins", "no path"}},
      {{"--ws-origins", "ftp://ocean.example"}, {"--ws-origins", "http or https"}},
      {{"--web-listen", "8080"}, {"--web-listen", "ADDR:PORT"}},
      {{"--web-listen", "127.0.0.1:8080"}, {"--web-listen", "--ws-listen"}},  // the page needs a WebSocket
      // TLS: both files or neither, for a browser listener, each a file name (their contents are
      // read when the server is built: tests/server/tls_reload_test.py).
      {{"--ws-listen", "127.0.0.1:0", "--tls-cert", "c.pem"}, {"--tls-cert needs --tls-key"}},
      {{"--ws-listen", "127.0.0.1:0", "--tls-key", "k.pem"}, {"--tls-key needs --tls-cert"}},
      {{"--tls-cert", "c.pem", "--tls-key", "k.pem"}, {"--tls-cert", "give --ws-listen"}},
      {{"--web-listen", "127.0.0.1:0", "--tls-cert", "c.pem", "--tls-key", "k.pem"}, {"--web-listen", "--ws-listen"}},
      {{"--ws-listen", "127.0.0.1:0", "--tls-cert", "", "--tls-key", "k.pem"}, {"--tls-cert", "must name a file"}},
      {{"--ws-listen", "127.0.0.1:0", "--tls-cert", "c.pem", "--tls-key", ""}, {"--tls-key", "must name a file"}},
      {{"--tick-rate", "0"}, {"--tick-rate", "1..240"}},
      {{"--tick-rate", "241"}, {"--tick-rate", "1..240"}},
      {{"--tick-rate", "20"}, {"--tick-rate", "mobile", "multiple"}},
      {{"--epoch", "yesterday"}, {"--epoch", "RFC 3339"}},
      {{"--epoch", "2026-02-30T00:00:00Z"}, {"--epoch", "RFC 3339"}},
      {{"--profiles", "mobile,tablet"}, {"--profiles", "tablet", "known: mobile"}},
      {{"--profiles", "mobile,mobile"}, {"--profiles", "twice"}},
      {{"--profiles", ","}, {"--profiles", "at least one"}},
      {{"--profiles", "mobile", "--size", "32"}, {"--profiles", "mobile", "--size 32"}},
      // desktop's 2048 m cascade is 8 patches: 8 x 200 km is beyond the sim's 1e6 m.
      {{"--profiles", "desktop", "--patch", "200000"}, {"--profiles", "desktop", "cascade 1", "--patch"}},
      {{"--max-clients", "0"}, {"--max-clients", "1.."}},
      {{"--admission-target", "0"}, {"--admission-target", "(0, 3]", "or off"}},
      {{"--admission-target", "4"}, {"--admission-target", "(0, 3]"}},
      {{"--admission-target", "none"}, {"--admission-target", "'off'"}},
      {{"--admin-token-file", "/nonexistent/token"}, {"--admin-token-file", "cannot be read"}},
      {{"--admin-token-file", empty_token.path()}, {"--admin-token-file", "empty"}},
      {{"--cookie-key-file", bad_key.path()}, {"--cookie-key-file", "64 hex digits"}},
      {{"--idle-timeout", "0"}, {"--idle-timeout", "(0, 3600]"}},
      {{"--log-level", "loud"}, {"--log-level", "trace"}},
      {{"--config", "/nonexistent/ocean.toml"}, {"--config", "cannot be read"}},
      {{"--bogus", "1"}, {"--bogus"}},
  };
  for (const Case& c : cases) {
    const ConfigLoadResult r = load(c.args);
    INFO(c.args.front() << " -> " << r.message);
    CHECK(r.outcome == Outcome::error);
    for (const std::string& mention : c.mentions) CHECK(r.message.find(mention) != std::string::npos);
  }
}

TEST_CASE("a readable cookie key file sets the key", "[config]") {
  TempFile key("00112233445566778899aabbccddeeff00112233445566778899AABBCCDDEEFF\n");
  const ConfigLoadResult r = load({"--cookie-key-file", key.path()});
  REQUIRE(r.message == "");
  REQUIRE(r.config.cookie_key.size() == 32);
  CHECK(r.config.cookie_key[0] == 0x00);
  CHECK(r.config.cookie_key[15] == 0xff);
  CHECK(r.config.cookie_key[31] == 0xff);
}

TEST_CASE("config file errors name the key and line", "[config]") {
  struct Case {
    std::string toml;
    std::vector<std::string> mentions;
  };
  const Case cases[] = {
      {"wind-speed = 5\nwindspeed = 6\n", {"unknown key 'windspeed'", ":2"}},
      {"wind-speed = \"fast\"\n", {"wind-speed", "must be a number", "a string"}},
      {"size = 12.5\n", {"size", "must be an integer"}},
      {"profiles = [\"mobile\", 3]\n", {"profiles", "array of strings"}},
      {"listen = 7700\n", {"listen", "must be a string"}},
      {"wind-speed = 5\nwind-speed = 6\n", {":2"}},  // TOML forbids redefinition
      {"[scene]\nwind-speed = 5\n", {"unknown key 'scene'"}},
      {"tick-rate = 7\n", {"--tick-rate 7", "mobile"}},
      {"config = \"other.toml\"\n", {"unknown key 'config'"}},
  };
  for (const Case& c : cases) {
    TempFile file(c.toml);
    const ConfigLoadResult r = load({"--config", file.path()});
    INFO(c.toml << " -> " << r.message);
    CHECK(r.outcome == Outcome::error);
    for (const std::string& mention : c.mentions) CHECK(r.message.find(mention) != std::string::npos);
  }
}

TEST_CASE("scheduled scene changes build on each other and on the flags", "[config][schedule]") {
  TempFile file(R"(
wind-speed = 10
[[schedule]]
tick = 100
wind-speed = 20
[[schedule]]
tick = 200
wind-dir = 90
spectrum = "jonswap"
)");
  const ConfigLoadResult r = load({"--config", file.path(), "--amplitude", "2"});
  REQUIRE(r.message == "");
  REQUIRE(r.config.schedule.size() == 2);
  std::string error;
  const SceneSchedule schedule = make_schedule(r.config, error);
  REQUIRE(error == "");
  CHECK(schedule.scene_at(99).wind_speed_mps == 10.0);
  CHECK(schedule.scene_at(-5).wind_speed_mps == 10.0);
  CHECK(schedule.scene_at(100).wind_speed_mps == 20.0);
  CHECK(schedule.scene_at(100).amplitude == 2.0);  // the flag reaches scheduled scenes too
  CHECK(schedule.scene_at(100).wind_dir_deg == 0.0);
  CHECK(schedule.scene_at(199).spectrum == ocean::model::SpectrumKind::phillips);
  CHECK(schedule.scene_at(200).wind_speed_mps == 20.0);
  CHECK(schedule.scene_at(200).wind_dir_deg == 90.0);
  CHECK(schedule.scene_at(200).spectrum == ocean::model::SpectrumKind::jonswap);
  CHECK(schedule.scene_at(1'000'000'000'000).amplitude == 2.0);
}

TEST_CASE("bad schedules are refused naming the entry", "[config][schedule]") {
  struct Case {
    std::string toml;
    std::vector<std::string> mentions;
  };
  const Case cases[] = {
      {"[[schedule]]\ntick = 10\nwind-speed = 5\n[[schedule]]\ntick = 10\nwind-speed = 6\n",
       {"schedule entry 2", "strictly"}},
      {"[[schedule]]\ntick = 10\nsize = 512\n", {"schedule entry 1", "'size' cannot be scheduled", "wind-speed"}},
      {"[[schedule]]\nwind-speed = 5\n", {"schedule entry 1", "tick = T"}},
      {"[[schedule]]\ntick = \"soon\"\nwind-speed = 5\n", {"schedule entry 1", "tick = T"}},
      {"[[schedule]]\ntick = 10\nwind-speed = \"gale\"\n", {"schedule entry 1", "wind-speed", "must be a number"}},
      {"[[schedule]]\ntick = 10\nwind-speed = 500\n", {"schedule entry 1", "tick 10", "wind_speed_mps"}},
      {"schedule = 3\n", {"'schedule' must be an array of tables"}},
  };
  for (const Case& c : cases) {
    TempFile file(c.toml);
    const ConfigLoadResult r = load({"--config", file.path()});
    INFO(c.toml << " -> " << r.message);
    CHECK(r.outcome == Outcome::error);
    for (const std::string& mention : c.mentions) CHECK(r.message.find(mention) != std::string::npos);
  }
}

TEST_CASE("describe_config shows options but never the admin token", "[config]") {
  TempFile token("top-secret-token");
  const ConfigLoadResult r = load({"--admin-token-file", token.path(), "--wind-speed", "11"});
  REQUIRE(r.outcome == Outcome::run);
  const std::string text = describe_config(r.config);
  CHECK(text.find("wind-speed=11") != std::string::npos);
  CHECK(text.find("profiles=mobile,desktop") != std::string::npos);
  CHECK(text.find("top-secret-token") == std::string::npos);
}

TEST_CASE("config text that is not ASCII is refused before the TOML parser sees it", "[config]") {
  ServerConfig config;
  // Malformed UTF-8, and valid characters on which toml++ 3.3 reaches TOML_UNREACHABLE (the
  // second is fuzz_config_toml's finding: U+FEEF before a key).
  for (const std::string& bad : {std::string("seed = 1\n\x80"), std::string("seed = 1\n\xEF\xBB\xAFl = 1"),
                                 std::string("seed = 1\n\xC3\xA9 = 2"), std::string("seed = 1\n# vln\xC4\x9B")}) {
    const std::string error = apply_config_toml(config, bad, "bad.toml");
    INFO(error);
    CHECK(error.rfind("bad.toml:2: byte ", 0) == 0);
    CHECK(error.find("not ASCII") != std::string::npos);
  }
  CHECK(apply_config_toml(config, "# plain\nseed = 9\n", "ok.toml").empty());
  CHECK(config.scene.seed == 9u);
}

TEST_CASE("an empty file, a directory, a huge file or a negative tick is an error, not the defaults", "[config]") {
  TempFile empty("");
  CHECK(load({"--config", empty.path()}).message.find("is empty") != std::string::npos);
  const ConfigLoadResult directory = load({"--config", "/tmp"});
  CHECK(directory.outcome == Outcome::error);
  CHECK(directory.message.find("not a regular file") != std::string::npos);
  TempFile huge(std::string(kMaxConfigBytes + 1, '#'));
  CHECK(load({"--config", huge.path()}).message.find("at most") != std::string::npos);
  TempFile negative("[[schedule]]\ntick = -5\nwind-speed = 12.0\n");
  const ConfigLoadResult r = load({"--config", negative.path()});
  CHECK(r.outcome == Outcome::error);
  CHECK(r.message.find("negative") != std::string::npos);
}

TEST_CASE("a long schedule loads in linear time, and one over the limit is refused", "[config][schedule]") {
  auto schedule_text = [](std::size_t entries) {
    std::string text;
    for (std::size_t i = 0; i < entries; ++i)
      text += "[[schedule]]\ntick = " + std::to_string(100 + i) + "\nwind-speed = " + std::to_string(5 + i % 10) + ".0\n";
    return text;
  };
  // Linear against quadratic by the ratio of 8x the entries (8x linear, 64x quadratic), the best
  // of three runs each, so a slow machine or a sanitizer (TSan: 0.56 s for 8000) scales both.
  auto best_load_s = [&](std::size_t entries) {
    const std::string text = schedule_text(entries);
    double best = 1e9;
    for (int run = 0; run < 3; ++run) {
      ServerConfig config;
      const auto start = std::chrono::steady_clock::now();
      REQUIRE(apply_config_toml(config, text, "long.toml").empty());
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      REQUIRE(config.schedule.size() == entries);
    }
    return best;
  };
  const double small = best_load_s(1000), large = best_load_s(8000);
  INFO("1000 entries " << small << " s, 8000 entries " << large << " s");
  CHECK(large < 20.0 * small + 0.02);  // main: 1.43 s for 8000 (a copy of the growing schedule per entry)
  ServerConfig over;
  CHECK(apply_config_toml(over, schedule_text(kMaxScheduleEntries + 1), "over.toml").find("at most") != std::string::npos);
}

TEST_CASE("any 64-bit seed can be given, in TOML as a string, a bad one says what is allowed", "[config]") {
  CHECK(load({"--seed", "18446744073709551615"}).config.scene.seed == 18446744073709551615ull);
  CHECK(load({"--seed", "0xfedcba9876543210"}).config.scene.seed == 0xfedcba9876543210ull);
  TempFile file("seed = \"0xffffffffffffffff\"\n");
  CHECK(load({"--config", file.path()}).config.scene.seed == 0xffffffffffffffffull);
  const ConfigLoadResult bad = load({"--seed", "-1"});
  CHECK(bad.outcome == Outcome::error);
  CHECK(bad.message.find("unsigned 64-bit") != std::string::npos);
}

// Vessels ([[vessel]] tables) and the wake's square (CODEC.md 7.9): a fleet loads, and every bad
// vessel is refused with a message that names the vessel and what is wrong.
TEST_CASE("a config file's vessels load, and bad ones are refused by name", "[config]") {
  TempFile fleet(R"(
wake-size = 400
wake-origin-x = -200
wake-origin-z = -200
[[vessel]]
id = 3
length = 24
beam = 6
draft = 1.5
repeat = true
waypoints = [[0, -100, -100], [20, 100, -100], [40, -100, -100]]
[[vessel]]
id = 4
length = 12.5
beam = 4
draft = 1
waypoints = [[0, 50, 50]]
)");
  const ConfigLoadResult ok = load({"--config", fleet.path()});
  REQUIRE(ok.message == "");
  REQUIRE(ok.config.vessels.size() == 2);
  CHECK(ok.config.vessels[0].id == 3);
  CHECK(ok.config.vessels[0].repeat);
  CHECK(ok.config.vessels[0].points.size() == 3);
  CHECK(ok.config.vessels[0].points[1].x_m == 100.0);
  CHECK(ok.config.vessels[1].hull.length_m == 12.5);
  CHECK(ok.config.wake_size_m == 400.0);

  const auto refused = [&](const std::string& vessel, const std::vector<std::string>& mentions) {
    TempFile file("wake-size = 400\nwake-origin-x = -200\nwake-origin-z = -200\n[[vessel]]\n" + vessel);
    const ConfigLoadResult r = load({"--config", file.path()});
    INFO(vessel << " -> " << r.message);
    CHECK(r.outcome == Outcome::error);
    for (const std::string& m : mentions) CHECK_THAT(r.message, Catch::Contains(m));
  };
  refused("id = 1\nlength = 24\nbeam = 6\ndraft = 1.5\nwaypoints = [[0, 0, 0], [1, 100, 0]]\n", {"vessel 1", "m/s"});
  refused("id = 1\nlength = 24\nbeam = 6\ndraft = 1.5\nwaypoints = [[0, 500, 0]]\n", {"vessel 1", "outside"});
  refused("id = 1\nlength = 24\nbeam = 60\ndraft = 1.5\nwaypoints = [[0, 0, 0]]\n", {"beam_m"});
  refused("id = 1\nlength = 24\nbeam = 6\ndraft = 1.5\nwaypoints = [[0, 0]]\n", {"[t, x, z]"});
  refused("id = 1\nlength = 24\nbeam = 6\nwaypoints = [[0, 0, 0]]\n", {"length, beam and draft"});
  refused("id = 1\nlength = 24\nbeam = 6\ndraft = 1\nspeed = 3\nwaypoints = [[0, 0, 0]]\n", {"unknown key 'speed'"});
  refused("id = 1\nlength = 24\nbeam = 6\ndraft = 1\nrepeat = true\nwaypoints = [[0, 0, 0], [10, 10, 0]]\n", {"circuit"});
  CHECK_THAT(load({"--wake-size", "10"}).message, Catch::Contains("--wake-size"));
  CHECK_THAT(load({"--wake-decay", "0"}).message, Catch::Contains("--wake-decay"));
  CHECK_THAT(load({"--wake", "maybe"}).message, Catch::Contains("must be auto or on"));
  CHECK(load({"--wake", "on"}).config.has_wake());
  CHECK_FALSE(load({"--wake", "auto"}).config.has_wake());
}

// Dropped objects ([[drop]] tables): round hulls pressing for a splash, once or again and again,
// after the vessels in the list the Welcome carries; every bad one refused by name.
TEST_CASE("a config file's dropped objects load as hulls present for a splash, and bad ones are refused", "[config]") {
  TempFile scenario(R"(
wake-size = 400
wake-origin-x = -200
wake-origin-z = -200
[[drop]]
id = 10
x = 20
z = -30
size = 1.5
at = 5
splash = 0.5
every = 20
[[drop]]
id = 11
x = -50
z = 60
[[vessel]]
id = 1
length = 12
beam = 4
draft = 1
waypoints = [[0, 0, 0]]
)");
  const ConfigLoadResult ok = load({"--config", scenario.path()});
  REQUIRE(ok.message == "");
  REQUIRE(ok.config.vessels.size() == 3);
  CHECK(ok.config.vessels[0].id == 1);  // the vessels, then the objects
  const auto& d = ok.config.vessels[1];
  CHECK(d.id == 10);
  CHECK(d.hull == ocean::model::Hull{1.5, 1.5, 0.75});
  CHECK(d.points == std::vector<ocean::model::Waypoint>{{0.0, 20.0, -30.0}});
  CHECK(d.presence == ocean::model::Presence{5.0, 0.5, 20.0});
  CHECK(ok.config.vessels[2].hull == ocean::model::Hull{2.0, 2.0, 1.0});  // the defaults: 2 m, once at 0 for 1 s
  CHECK(ok.config.vessels[2].presence == ocean::model::Presence{0.0, 1.0, 0.0});

  const auto refused = [&](const std::string& drop, const std::vector<std::string>& mentions) {
    TempFile file("wake-size = 400\nwake-origin-x = -200\nwake-origin-z = -200\n[[vessel]]\nid = 1\nlength = 12\n"
                  "beam = 4\ndraft = 1\nwaypoints = [[0, 0, 0]]\n[[drop]]\n" + drop);
    const ConfigLoadResult r = load({"--config", file.path()});
    INFO(drop << " -> " << r.message);
    CHECK(r.outcome == Outcome::error);
    for (const std::string& m : mentions) CHECK_THAT(r.message, Catch::Contains(m));
  };
  refused("id = 2\nx = 500\nz = 0\n", {"[[drop]]", "vessel 2", "outside"});
  refused("id = 1\nx = 0\nz = 0\n", {"share this id"});
  refused("id = 2\nz = 0\n", {"needs x and z"});
  refused("id = 2\nx = 0\nz = 0\nsize = 80\n", {"size 80", "(0, 50]"});
  refused("id = 2\nx = 0\nz = 0\nsize = 0\n", {"size 0"});
  refused("id = 2\nx = 0\nz = 0\nsplash = 0\n", {"present_for_s"});
  refused("id = 2\nx = 0\nz = 0\nsplash = 3\nevery = 2\n", {"lasts at most that long"});
  refused("id = 2\nx = 0\nz = 0\nevery = -1\n", {"present_every_s"});
  refused("id = 2\nx = 0\nz = 0\nat = \"soon\"\n", {"numbers"});
  refused("id = 2\nx = 0\nz = 0\nmass = 80\n", {"unknown key 'mass'"});
}
