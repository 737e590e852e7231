// Issue 33, what operators and the machine do to a running server: a SIGHUP, a log reader that
// goes away, a stall of the whole process (SIGSTOP, a phone in a tunnel on the client side looks
// the same), and scenes at the corners of the documented ranges sent by an admin - the server
// serves on through each, and its UDP viewers come back to UDP. Figures: "[operator]" lines.
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "fault_scenario.hpp"
#include "http_probe.hpp"
#include "message_builders.hpp"
#include "raw_peers.hpp"
#include "server_process.hpp"
#include "temp_file.hpp"

extern char** environ;

using namespace ocean::faults;
using ocean::test_support::ServerProcess;
using ocean::test_support::TempFile;
namespace proto = ocean::protocol;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

namespace {

proto::Hello hello(std::uint8_t profile = 1) { return proto::Hello{profile, 0, ocean::wire::Transport::tcp, "operator"}; }

// ocean-server with its stdout and stderr on a pipe this test reads, as `ocean-server | head`.
struct PipedServer {
  explicit PipedServer(std::vector<std::string> args) {
    REQUIRE(::pipe(fds) == 0);
    args.insert(args.begin(), ocean::test_support::server_binary());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 2);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    REQUIRE(::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
  }
  ~PipedServer() {
    if (fds[0] >= 0) ::close(fds[0]);
    if (pid > 0) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
  }
  // Reads the pipe until the "listening" line; the ports it names.
  std::optional<ocean::test_support::ListeningPorts> read_ports(double timeout_s) {
    std::string text;
    const auto start = Clock::now();
    char buffer[4096];
    while (seconds_since(start) < timeout_s) {
      const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
      if (n <= 0) return std::nullopt;
      text.append(buffer, static_cast<std::size_t>(n));
      if (auto ports = ocean::test_support::parse_listening_line(text)) return ports;
    }
    return std::nullopt;
  }
  void close_reader() {
    ::close(fds[0]);
    fds[0] = -1;
  }
  bool alive() { return ::waitpid(pid, &status, WNOHANG) == 0; }
  int fds[2] = {-1, -1};
  pid_t pid = -1;
  int status = 0;
};

}  // namespace

TEST_CASE("SIGHUP is logged and counted, and the server serves on", "[operator]") {
  FaultScenario s({"--size", "64", "--profiles", "mobile,lite"});
  start_population(s);
  const FaultMeasure m = s.measure("3 SIGHUPs", [&] {
    for (int i = 0; i < 3; ++i) {
      s.server().signal(SIGHUP);
      std::this_thread::sleep_for(milliseconds(700));
    }
  });
  const double counted = scrape(s.server().metrics_port(), "ocean_sighups_total");
  std::printf("[operator] 3 SIGHUPs: alive %d, %.0f counted\n", s.server().alive(), counted);
  check_population(s, m);  // main: killed by the first, nothing logged
  CHECK(counted == 3.0);
  CHECK(s.server().log().find("SIGHUP received: nothing to reload") != std::string::npos);
}

TEST_CASE("a log reader that goes away costs the lines, counted, never the server", "[operator]") {
  PipedServer server({"--listen", "127.0.0.1:0", "--metrics-listen", "127.0.0.1:0", "--size", "64", "--profiles", "mobile"});
  const auto ports = server.read_ports(20.0);
  REQUIRE(ports);
  server.close_reader();  // `| head -c 300` is done
  // Lines to write: sessions connect and leave, a SIGHUP.
  int welcomed = 0;
  for (int i = 0; i < 5; ++i) {
    RawTcp viewer(ports->tcp);
    welcomed += viewer.handshake(hello(), 3.0).has_value();
  }
  ::kill(server.pid, SIGHUP);
  std::this_thread::sleep_for(milliseconds(500));
  RawTcp after(ports->tcp);
  const bool streams = after.handshake(hello(), 3.0).has_value() && after.read_message(2.0).has_value();
  const auto health = http_get(ports->metrics, "/healthz");
  const double failed = scrape(ports->metrics, "ocean_log_write_failures_total");
  std::printf("[operator] log pipe closed: alive %d, %d of 5 welcomed, streams after %d, %.0f log lines lost (counted)\n",
              server.alive(), welcomed, streams, failed);
  CHECK(server.alive());  // main: SIGPIPE at the next line
  CHECK(welcomed == 5);
  CHECK(streams);
  CHECK((health && health->status == 200));
  CHECK(failed > 0.0);
}

TEST_CASE("after a 3 s stall of the server its UDP viewers come back to UDP", "[operator]") {
  FaultScenario s({"--size", "64", "--profiles", "mobile,lite", "--max-clients", "200", "--max-connections-per-ip", "0",
                   "--max-handshakes-per-ip", "256", "--connect-rate-per-ip", "0"},
                  100);
  start_population(s);
  REQUIRE(s.population().on_udp(0));
  s.server().signal(SIGSTOP);
  std::this_thread::sleep_for(milliseconds(3000));
  s.server().signal(SIGCONT);
  const auto resumed = Clock::now();
  int on_udp = 0;
  double took = 0.0;
  while (seconds_since(resumed) < 10.0) {
    std::this_thread::sleep_for(milliseconds(250));
    on_udp = 0;
    for (std::size_t i = 0; i < 100; ++i) on_udp += s.population().on_udp(i);
    took = seconds_since(resumed);
    if (on_udp >= 100) break;
  }
  std::uint64_t fallbacks = 0, returns = 0;
  for (std::size_t i = 0; i < 100; ++i) {
    const auto [fell_back, returned] = s.population().transport_changes(i);  // one round trip to its thread
    fallbacks += fell_back;
    returns += returned;
  }
  std::printf("[operator] 3 s SIGSTOP: %d of 100 UDP viewers on UDP %.1f s after SIGCONT (%llu fell back to TCP, %llu "
              "came back)\n",
              on_udp, took, static_cast<unsigned long long>(fallbacks), static_cast<unsigned long long>(returns));
  CHECK(s.server().alive());
  CHECK(on_udp >= 95);  // main: 2 of 200, the rest on TCP for good
  for (const std::uint64_t connects : s.population().connects()) CHECK(connects == 1);
}

TEST_CASE("admin scenes at the corners of the ranges leave a server of every profile serving, and flags it cannot "
          "carry stop it at start with the figures",
          "[operator]") {
  const TempFile token_file("the-operators-token\n");  // removed however the test ends
  FaultScenario s({"--size", "256", "--profiles", "mobile,lite,desktop,desktop-choppy,mobile-choppy", "--admin-token-file",
                   token_file.path()});
  start_population(s);
  // A viewer of each other profile, reading what the server sends (not decoding: a count).
  std::vector<std::unique_ptr<RawTcp>> viewers;
  for (std::uint8_t profile : {2, 3, 4, 5}) {
    viewers.push_back(std::make_unique<RawTcp>(s.port()));
    REQUIRE(viewers.back()->handshake(hello(profile), 5.0));
  }
  struct Change {
    const char* what;
    std::optional<double> wind, amplitude, choppiness;
    std::optional<ocean::wire::Spectrum> spectrum;
    std::optional<double> dir;
  };
  // The cases, which stopped main's server one second after ocean-admin reported success,
  // then every range at its maximum together.
  const std::vector<Change> changes = {
      {"wind 100, amplitude 1e5", 100.0, 1e5, {}, {}, {}},
      {"amplitude 5e5", {}, 5e5, {}, {}, {}},
      {"wind 30, amplitude 1e6", 30.0, 1e6, {}, {}, {}},
      {"wind 50, amplitude 1e6", 50.0, 1e6, {}, {}, {}},
      {"amplitude 1e6, choppiness 100", 10.0, 1e6, 100.0, {}, {}},
      {"amplitude 1e5, choppiness 100", {}, 1e5, 100.0, {}, {}},
      {"jonswap, wind 100, amplitude 1e6", 100.0, 1e6, 0.0, ocean::wire::Spectrum::jonswap, {}},
      {"every range at its maximum", 100.0, 1e6, 100.0, ocean::wire::Spectrum::jonswap, 1e6},
      {"back to a gale", 20.0, 1.0, 1.2, ocean::wire::Spectrum::jonswap, 0.0},
  };
  int applied = 0, refused = 0, unanswered = 0;
  const FaultMeasure m = s.measure("corner scenes by admin", [&] {
    RawTcp admin(s.port());
    REQUIRE(admin.handshake(hello(), 3.0));
    std::uint32_t id = 0;
    for (const Change& c : changes) {
      proto::ParamChange change;
      change.admin_token = "the-operators-token";
      change.request_id = ++id;
      change.wind_speed_mps = c.wind;
      change.amplitude = c.amplitude;
      change.choppiness = c.choppiness;
      change.spectrum = c.spectrum;
      change.wind_dir_deg = c.dir;
      ParamChangeAnswer answer;
      for (int tries = 0; tries < 10; ++tries) {  // past the change rate, if it says so
        answer = send_param_change(admin, change, kTimingMeasurable ? 5.0 : 20.0);  // an ASan server's checks are slow
        if (answer.error != proto::Reason::rate_limited) break;
        std::this_thread::sleep_for(milliseconds(1000));
      }
      std::printf("[operator] %-36s %s\n", c.what,
                  answer.applied ? "applied" : answer.error ? proto::to_string(*answer.error).data() : "no answer");
      applied += answer.applied;
      refused += answer.error == proto::Reason::out_of_range;
      unanswered += !answer.applied && !answer.error;
    }
    std::this_thread::sleep_for(milliseconds(2500));  // past the last change's lead
  });
  int viewers_streaming = 0;
  for (auto& v : viewers) {  // each still gets frames after the changes
    int messages = 0;
    for (int i = 0; i < 200 && v->read_message(0.5); ++i) ++messages;
    viewers_streaming += messages >= 20;
  }
  std::printf("[operator] %zu corner scenes: %d applied, %d refused out_of_range, %d unanswered; %d of 4 other profiles' "
              "viewers streaming\n",
              changes.size(), applied, refused, unanswered, viewers_streaming);
  for (const char* series : {"ocean_serve_seconds{quantile=\"1\"}", "ocean_tick_seconds{quantile=\"1\"}",
                             "ocean_loop_lag_seconds{quantile=\"1\"}", "ocean_ticks_late_total", "ocean_frames_dropped_total"})
    std::printf("[operator] %s %g\n", series, scrape(s.server().metrics_port(), series));
  check_population(s, m);  // main: exit 2 at the first change's tick
  CHECK(unanswered == 0);
  CHECK(refused >= 1);
  CHECK(applied >= 1);
  CHECK(viewers_streaming == 4);
  CHECK(scrape(s.server().metrics_port(), "ocean_samples_saturated_total{profile=\"desktop\"}") == 0.0);

  // The same kind of scene as flags: refused before the server listens, naming the field and profile.
  ocean::test_support::ServerOptions options = fault_server({"--profiles", "desktop", "--wind-speed", "100", "--amplitude",
                                                            "100000"});
  options.wait_listening = false;
  ServerProcess refused_at_start(options);
  const int status = refused_at_start.wait_exit(20.0);
  const std::string log = refused_at_start.log();
  std::printf("[operator] flags wind 100, amplitude 1e5 on desktop: exit %d: %s", status, log.c_str());
  CHECK(status == 2);
  CHECK(log.find("heights") != std::string::npos);
  CHECK(log.find("'desktop'") != std::string::npos);
  CHECK(log.find("listening") == std::string::npos);  // main: listened, then exit 2 at the first tick
}
