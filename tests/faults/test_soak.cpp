// The soak (issue 16): every attack of a peer without a token at once, for two minutes
// (OCEAN_SOAK_SECONDS), against a server streaming to 200 load-test viewers (every frame checked
// against the sim) and six in-process viewers whose cookies an attacker replays from its own
// ports, with a weather change scheduled in the middle. The viewers must keep >= 99 % of their
// frames on time with 0 bad frames, the server's memory at the end must be within 20 % of where
// it started, /healthz must answer and the log must stay small. Figures are printed ("[soak]").
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "client_population.hpp"
#include "fault_scenario.hpp"
#include "http_probe.hpp"
#include "json_value.hpp"
#include "message_builders.hpp"
#include "raw_peers.hpp"
#include "server_process.hpp"
#include "temp_file.hpp"

using namespace ocean::faults;
using ocean::test_support::ServerOptions;
using ocean::test_support::ServerProcess;
using ocean::test_support::TempFile;
namespace proto = ocean::protocol;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

namespace {

constexpr std::int64_t kEpochUnixMs = 1767225600000;  // 2026-01-01T00:00:00Z, the config's epoch
constexpr int kTickRateHz = 30;
constexpr int kLoadClients = 200;
constexpr int kVictimsUdp = 5, kVictimsTcp = 1;


// Two minutes; 30 s under a sanitizer, where only correctness is asserted.
double soak_seconds() {
  const char* text = std::getenv("OCEAN_SOAK_SECONDS");
  return text ? std::atof(text) : kTimingMeasurable ? 120.0 : 30.0;
}

std::int64_t tick_now() {
  const std::int64_t now_ms =
      std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  return (now_ms - kEpochUnixMs) * kTickRateHz / 1000;
}

// Under a sanitizer the server runs several times slower and its measured capacity falls below
// the 200 viewers (99 of them refused server_full in one run, and with them the attackers): the
// door is --max-clients alone there, so that every attack reaches a server serving everyone.
std::string config_text(const std::string& token_file, std::int64_t change_tick) {
  return std::string(kTimingMeasurable ? "" : "admission-target = \"off\"\n") +
         "listen = \"127.0.0.1:0\"\nmetrics-listen = \"127.0.0.1:0\"\nsize = 64\npatch = 64.0\n"
         "spectrum = \"jonswap\"\nwind-speed = 12.0\nseed = 7\ntick-rate = 30\n"
         "epoch = 2026-01-01T00:00:00Z\nprofiles = [\"mobile\", \"lite\"]\nmax-clients = 260\n"
         "max-connections-per-ip = 0\nconnect-rate-per-ip = 0\n"  // every viewer and attacker shares this host's address
         "admin-token-file = \"" + token_file + "\"\n"
         "[[schedule]]\ntick = " + std::to_string(change_tick) + "\nwind-speed = 17.0\nwind-dir = 60.0\n";
}

// Runs `attack` in a loop on its own low-priority thread until `stop`.
class Attackers {
 public:
  explicit Attackers(std::atomic<bool>& stop) : stop_(stop) {}
  ~Attackers() { join(); }
  template <typename F>
  void add(F attack) {
    threads_.emplace_back([this, attack]() mutable {
      lower_thread_priority();
      while (!stop_) attack();
    });
  }
  void join() {
    for (auto& t : threads_)
      if (t.joinable()) t.join();
  }

 private:
  std::atomic<bool>& stop_;
  std::vector<std::thread> threads_;
};

void pause_ms(int ms) { std::this_thread::sleep_for(milliseconds(ms)); }

std::uint64_t counter(const std::string& metrics, const std::string& series) {
  return static_cast<std::uint64_t>(metric_value(metrics, series).value_or(0.0));
}

}  // namespace

TEST_CASE("a two-minute soak of every attack leaves 200 viewers on time through a weather change", "[soak]") {
  const double soak_s = soak_seconds();
  const TempFile token("soak-admin-token-not-guessable\n");
  // The weather changes halfway through the attacks (the load test starts ~8 s before them).
  const std::int64_t change_tick = tick_now() + static_cast<std::int64_t>((8.0 + soak_s / 2) * kTickRateHz);
  const TempFile config(config_text(token.path(), change_tick));
  ServerOptions server_options;
  server_options.args = {"--config", config.path()};
  ServerProcess server(server_options);
  const std::uint16_t port = server.tcp_port();

  ServerOptions load_options;
  load_options.program = "client/loadtest/ocean-loadtest";
  load_options.wait_listening = false;
  load_options.args = {"--server", "127.0.0.1:" + std::to_string(port), "--clients", std::to_string(kLoadClients),
                       "--profile", "mobile", "--transport", "udp", "--ramp", "4",
                       "--duration", std::to_string(static_cast<int>(soak_s + 15)), "--json", "--quiet"};
  ServerProcess load(load_options);
  ClientPopulation victims(port, kVictimsUdp, kVictimsTcp, kMobile);
  // An unattacked server of the same config with a few clients, measured over the same ticks: if
  // even they are late, the machine was starved (other programs on its cores), and the soak's
  // on-time shares say nothing about the server under attack (FaultScenario does the same).
  ServerProcess control_server(server_options);
  ClientPopulation control(control_server.tcp_port(), kControlClients - 1, 1, kMobile);
  REQUIRE(victims.wait_streaming(30, 20.0));
  REQUIRE(control.wait_streaming(30, 10.0));
  std::this_thread::sleep_for(milliseconds(4000));  // the load test's ramp is over

  const std::string metrics_before = http_get(server.metrics_port(), "/metrics").value_or(HttpReply{}).body;
  const std::uint64_t rss_start = server.rss_kib().value_or(0);
  const std::size_t log_start = server.log().size();
  std::vector<proto::Welcome> victim_welcomes;
  for (std::size_t i = 0; i < victims.size(); ++i)
    if (const auto w = victims.welcome(i); w && victims.on_udp(i)) victim_welcomes.push_back(*w);

  std::atomic<bool> stop{false};
  std::atomic<std::uint64_t> guesses{0}, hellos{0}, hijack_bytes_in{0}, refused_joins{0}, garbage{0}, silent{0}, pings{0};
  const std::uint32_t first_tick = victims.tick_now() + 1;
  const auto start = Clock::now();
  {
    Attackers attackers(stop);
    // 1. Token guessing: wrong-token ParamChanges as fast as the server reads them, reconnecting
    //    whenever it closes the guesser.
    attackers.add([&] {
      RawTcp guesser(port);
      if (!guesser.handshake(proto::Hello{kMobile, 0, ocean::wire::Transport::tcp, "guesser"})) return pause_ms(50);
      proto::ParamChange change;
      change.admin_token = "guess-" + std::to_string(guesses.load());
      change.wind_speed_mps = 30.0;
      const proto::Bytes bytes = proto::encode(change);
      for (int i = 0; i < 500 && !stop && guesser.send(bytes); ++i) ++guesses;
    });
    // 2. Its own UdpHello, replayed from two ports in turn (once a "udp proven" line each).
    attackers.add([&] {
      RawTcp session(port);
      const auto welcome = session.handshake(proto::Hello{kMobile, 0, ocean::wire::Transport::udp, "rebinder"});
      if (!welcome) return pause_ms(50);
      RawUdp a, b;
      const proto::Bytes hello = proto::encode(proto::UdpHello{welcome->session_id, welcome->udp_cookie});
      for (int i = 0; i < 4000 && !stop && session.connected(); ++i, ++hellos) {
        (i % 2 ? a : b).send_to(port, hello);
        if (i % 40 == 39) {
          a.drain();
          b.drain();
          pause_ms(10);
        }
      }
    });
    // 3. The victims' UdpHellos (seen on the path), replayed from another port of their address.
    attackers.add([&] {
      RawUdp thief;
      for (int round = 0; round < 100 && !stop; ++round) {
        for (const proto::Welcome& w : victim_welcomes) thief.send_to(port, proto::encode(proto::UdpHello{w.session_id, w.udp_cookie}));
        pause_ms(10);
        thief.drain();
      }
      hijack_bytes_in += thief.bytes_in();
    });
    // 4. Joins the server must refuse (a profile it does not offer), in a tight loop.
    attackers.add([&] {
      RawTcp joiner(port);
      if (joiner.send(proto::encode(proto::Hello{2, 0, ocean::wire::Transport::tcp, "refused"})) &&
          joiner.wait_closed(1.0).error)
        ++refused_joins;
    });
    // 5. Silent sockets from one address, renewed as the server times them out.
    attackers.add([&] {
      std::vector<RawTcp> sockets;
      for (int i = 0; i < 40 && !stop; ++i, ++silent) sockets.emplace_back(port);
      for (int i = 0; i < 40 && !stop; ++i) pause_ms(100);
    });
    // 6. UDP garbage and oversized datagrams from a second address.
    attackers.add([&] {
      RawUdp udp("127.0.0.2");
      std::mt19937 random(16);
      for (int burst = 0; burst < 20; ++burst, ++garbage) {
        proto::Bytes d(1 + random() % 1500);
        for (auto& byte : d) byte = static_cast<std::uint8_t>(random());
        udp.send_to(port, d);
      }
      pause_ms(10);
      udp.drain();
    });
    // 7. A session that never reads and floods Pings and KeyframeRequests.
    attackers.add([&] {
      RawTcp flooder(port, 4096);
      if (!flooder.handshake(proto::Hello{kMobile, 0, ocean::wire::Transport::tcp, "flooder"})) return pause_ms(50);
      for (std::uint32_t i = 0; i < 20000 && !stop; ++i, ++pings) {
        const bool sent = i % 2 ? flooder.send(proto::encode(proto::Ping{0, {}, i, 0}))
                                : flooder.send(proto::encode(proto::KeyframeRequest{0, {}, ocean::wire::KeyframeReason::decode_error}));
        if (!sent) break;
        if (i % 100 == 99) pause_ms(10);
      }
    });

    // Meanwhile: /healthz, and the server's memory.
    double slowest_health = 0.0;
    int health_failures = 0;
    while (seconds_since(start) < soak_s) {
      const auto probe = Clock::now();
      const auto reply = http_get(server.metrics_port(), "/healthz", 2.0);
      if (!reply || reply->status != 200) ++health_failures;
      slowest_health = std::max(slowest_health, seconds_since(probe));
      std::this_thread::sleep_for(milliseconds(500));
    }
    stop = true;
    attackers.join();
    const double attack_s = seconds_since(start);
    const std::uint32_t last_tick = victims.tick_now();
    std::this_thread::sleep_for(milliseconds(2000));  // let the servers' idle sweeps settle

    const std::uint64_t rss_end = server.rss_kib().value_or(0);
    const double log_rate = static_cast<double>(server.log().size() - log_start) / attack_s;
    const std::string metrics = http_get(server.metrics_port(), "/metrics").value_or(HttpReply{}).body;
    const PopulationWindow window = victims.window(first_tick, last_tick);
    const PopulationWindow control_window = control.window(first_tick, last_tick);
    const bool control_on_time = control_window.on_time_share() >= kOnTimeShare;

    // The load test ends by itself; its last line is the JSON summary.
    const int load_status = load.wait_exit(soak_s + 60.0);
    const std::string load_log = load.log();
    const std::size_t brace = load_log.rfind("\n{");
    std::string error;
    const auto summary = ocean::loadtest::parse_json(brace == std::string::npos ? load_log : load_log.substr(brace + 1), error);
    INFO("load test output:\n" << load_log);
    REQUIRE(summary);
    const auto number = [&](const char* key) {
      const auto* v = summary->find(key);
      return v ? v->number : -1.0;
    };
    std::printf("[soak] %.0f s of attacks: %llu guesses, %llu replayed UdpHellos, %llu refused joins, %llu silent sockets, "
                "%llu garbage datagrams, %llu Pings/KeyframeRequests unread\n",
                attack_s, static_cast<unsigned long long>(guesses.load()), static_cast<unsigned long long>(hellos.load()),
                static_cast<unsigned long long>(refused_joins.load()), static_cast<unsigned long long>(silent.load()),
                static_cast<unsigned long long>(garbage.load()), static_cast<unsigned long long>(pings.load()));
    std::printf("[soak] load test: %d clients, %.2f %% on time, %.0f bad, %.0f reconnects, %.0f scenes; victims %s; "
                "unattacked server's clients %.2f %% on time; replayed-cookie port got %llu bytes\n",
                kLoadClients, number("frames_ok_pct"), number("frames_bad"), number("reconnects"), number("scenes"),
                window.describe().c_str(), 100.0 * control_window.on_time_share(),
                static_cast<unsigned long long>(hijack_bytes_in.load()));
    std::printf("[soak] server: RSS %llu -> %llu KiB, log %.0f B/s, slowest /healthz %.1f ms (%d failed), rejects "
                "unauthorized %llu token_guessing %llu profile_unavailable %llu\n",
                static_cast<unsigned long long>(rss_start), static_cast<unsigned long long>(rss_end), log_rate,
                slowest_health * 1000.0, health_failures,
                static_cast<unsigned long long>(counter(metrics, "ocean_rejects_total{reason=\"unauthorized\"}")),
                static_cast<unsigned long long>(counter(metrics, "ocean_rejects_total{reason=\"token_guessing\"}")),
                static_cast<unsigned long long>(counter(metrics, "ocean_rejects_total{reason=\"profile_unavailable\"}")));
    std::fflush(stdout);

    CHECK(server.alive());
    CHECK(load_status == 0);
    CHECK(number("clients_welcomed") == kLoadClients);
    CHECK(number("frames_bad") == 0);
    CHECK(number("scenes") >= 2);  // the scheduled weather change reached the viewers
    CHECK(health_failures == 0);
    CHECK(hijack_bytes_in.load() < 64 * 1024);  // no victim's stream went to the thief's port
    for (std::size_t i = 0; i < victims.size(); ++i) CHECK(victims.connects()[i] == 1);
    CHECK(guesses.load() > 0);
    CHECK(counter(metrics, "ocean_rejects_total{reason=\"profile_unavailable\"}") >
          counter(metrics_before, "ocean_rejects_total{reason=\"profile_unavailable\"}"));
    CHECK(log_rate < 4096.0);
    if (kTimingMeasurable) {
      CHECK(static_cast<double>(rss_end) <= 1.2 * static_cast<double>(rss_start));
      // Only a miss is excused, and only when even the unattacked server's clients were late.
      const bool on_time = number("frames_ok_pct") >= 99.0 && window.on_time_share() >= kOnTimeShare && slowest_health < 0.1;
      if (on_time || control_on_time) {
        CHECK(number("frames_ok_pct") >= 99.0);
        CHECK(window.on_time_share() >= kOnTimeShare);
        CHECK(slowest_health < 0.1);
      } else {
        std::printf("[soak] NOT ASSERTED on a starved machine: on time %.2f %% (load test) and %.2f %% (victims); the "
                    "unattacked server's clients kept only %.2f %%, slowest /healthz %.1f ms\n",
                    number("frames_ok_pct"), 100.0 * window.on_time_share(), 100.0 * control_window.on_time_share(),
                    slowest_health * 1000.0);
      }
    }
  }
}
