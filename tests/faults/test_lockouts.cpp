// Issue 33, the real server: nobody locks others out. Connections churned from one address range
// 400 times faster than its connect rate, slow and idle page connections from many addresses, one
// address holding every slot, an empty WebSocket Origin, token guessing from many addresses and the
// operator behind the guessers' NAT, and a flood of admin changes - each beside viewers who must
// keep streaming. Figures are printed ("[lockouts]" lines).
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "fault_scenario.hpp"
#include "http_probe.hpp"
#include "message_builders.hpp"
#include "raw_peers.hpp"
#include "server_process.hpp"
#include "temp_file.hpp"

using namespace ocean::faults;
using ocean::test_support::ServerProcess;
using ocean::test_support::TempFile;
namespace proto = ocean::protocol;
using Clock = std::chrono::steady_clock;
using std::chrono::microseconds;
using std::chrono::milliseconds;

namespace {

proto::Hello hello(const char* name) { return proto::Hello{1, 0, ocean::wire::Transport::tcp, name}; }

// A loopback address of its own /24 (ConnectRate's range), so that it is not this host's 127.0.0.1.
std::string loopback(int range, int host) { return "127.0." + std::to_string(range) + "." + std::to_string(host); }

// Opens `n` connections from `from` without waiting for any (non-blocking connects), then closes
// them: as many as the kernel completes, the churn one process can make. Returns how many it
// started.
int churn(std::uint16_t port, const char* from, int n) {
  sockaddr_in local{}, remote{};
  local.sin_family = remote.sin_family = AF_INET;
  ::inet_pton(AF_INET, from, &local.sin_addr);
  ::inet_pton(AF_INET, "127.0.0.1", &remote.sin_addr);
  remote.sin_port = htons(port);
  std::vector<int> fds;
  for (int i = 0; i < n; ++i) {
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
    if (fd < 0) break;
    if (::bind(fd, reinterpret_cast<const sockaddr*>(&local), sizeof local) == 0)
      (void)::connect(fd, reinterpret_cast<const sockaddr*>(&remote), sizeof remote);
    fds.push_back(fd);
  }
  std::this_thread::sleep_for(std::chrono::microseconds(200));  // the handshakes complete
  const linger reset{1, 0};  // closed with RST: no TIME_WAIT on either side holds the churn back
  for (const int fd : fds) {
    ::setsockopt(fd, SOL_SOCKET, SO_LINGER, &reset, sizeof reset);
    ::close(fd);
  }
  return static_cast<int>(fds.size());
}

// A web root with the four files --web-listen serves (small: the page, not the viewer, is tested).
struct WebRoot {
  WebRoot() : path(std::filesystem::temp_directory_path() / ("ocean-lockouts-web-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
    for (const char* name : {"index.html", "viewer.js", "ocean-web.js", "ocean-web.wasm"})
      std::ofstream(path / name) << "<!-- " << name << " -->\n";
  }
  ~WebRoot() { std::filesystem::remove_all(path); }
  std::filesystem::path path;
};

// Page loads from 127.0.0.1, each answered 200 within 2 s.
int page_loads(std::uint16_t web_port, int n) {
  int ok = 0;
  for (int i = 0; i < n; ++i) {
    const auto reply = http_get(web_port, "/", 2.0);
    ok += reply && reply->status == 200;
    std::this_thread::sleep_for(milliseconds(100));
  }
  return ok;
}

}  // namespace

TEST_CASE("connections churned from one address range at 20 000 a second let every probing newcomer in",
          "[lockouts]") {
  // 100 viewers (97 on UDP, 3 on TCP) share 127.0.0.1 with the newcomers: no per-address
  // connection limit, and room for them all to say Hello at once (they join within the default
  // burst of 100 connections of one range).
  // Under a sanitizer the server cannot serve 100 viewers in time at all, and its measured
  // capacity refuses newcomers whatever the churn: the door is --max-clients alone there, and what
  // is tested is that every connection path stays sound under the churn.
  std::vector<std::string> args = {"--size", "64", "--profiles", "mobile,lite", "--max-clients", "200",
                                   "--max-connections-per-ip", "0", "--max-handshakes-per-ip", "256"};
  if (!kTimingMeasurable) args.insert(args.end(), {"--admission-target", "off"});
  FaultScenario s(args, 97);
  start_population(s);
  std::atomic<bool> stop{false};
  std::atomic<std::uint64_t> churned{0};
  std::vector<std::thread> churners;
  // Four threads at 5 000 connections a second each: 400 times the range's connect rate, and more
  // than the 13 400 a second that let 1 of 11 newcomers in before the door was built. Not faster:
  // "as fast as they go" was 50 000-75 000 a second on the 2-core machines this test was written
  // on and 150 000 on a later kernel, and there, and at 66 000 on a CI machine, the churner's own
  // handshakes (loopback: both ends' kernel work on the server's two cores) starved every
  // process, the viewers' included (7 % on time): the test measured the kernel. A sanitizer's
  // server is several times slower at everything, accepting included: one thread at 6400 a
  // second there.
  const int threads = kTimingMeasurable ? 4 : 1;
  const auto batch_interval = kTimingMeasurable ? microseconds(128'000'000 / 5'000) : milliseconds(20);
  for (int t = 0; t < threads; ++t)
    churners.emplace_back([&, t] {
      const std::string from = loopback(1, 2 + t);
      auto next = std::chrono::steady_clock::now();
      while (!stop) {
        churned += churn(s.port(), from.c_str(), 128);  // open, close, never a byte
        next += batch_interval;
        std::this_thread::sleep_until(next);
      }
    });
  int welcomed = 0;
  const FaultMeasure m = s.measure("churn + 10 newcomers", [&] {
    std::this_thread::sleep_for(milliseconds(1500));  // the admission budget has seen the churn
    for (int i = 0; i < 10; ++i) {
      RawTcp newcomer(s.port());
      welcomed += newcomer.handshake(hello("newcomer"), kTimingMeasurable ? 2.0 : 10.0).has_value();
      std::this_thread::sleep_for(milliseconds(300));
    }
  });
  stop = true;
  for (auto& t : churners) t.join();
  const double closed_at_accept = rejects(s.server().metrics_port(), "connect_rate");
  std::printf("[lockouts] %llu connections churned in %.1f s (%.0f a second) from one /24: %d of 10 newcomers welcomed, "
              "%.0f closed at accept (connect_rate), %.0f refused server_full; network thread busy %.2f, waiting %.2f, "
              "admission capacity %.0f (0: none)\n",
              static_cast<unsigned long long>(churned.load()), m.seconds, static_cast<double>(churned.load()) / m.seconds,
              welcomed, closed_at_accept, rejects(s.server().metrics_port(), "server_full"),
              scrape(s.server().metrics_port(), "ocean_network_busy_ratio"),
              scrape(s.server().metrics_port(), "ocean_network_cpu_wait_ratio"),
              scrape(s.server().metrics_port(), "ocean_admission_capacity"));
  check_population(s, m);
  CHECK(welcomed == 10);  // main: 1 of 11 at 13 400 a second ("overload ... admitting at most 68")
  CHECK(closed_at_accept > 0.0);
}

TEST_CASE("slow and idle connections from many addresses never keep the page from anyone", "[lockouts]") {
  const WebRoot root;
  ServerProcess server(fault_server({"--size", "64", "--profiles", "mobile", "--ws-listen", "127.0.0.1:0",
                                     "--web-listen", "127.0.0.1:0", "--web-root", root.path.string()}));
  const std::uint16_t web = server.web_port();
  REQUIRE(web != 0);
  const std::string request = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: ";
  // 64 slowloris connections from 8 addresses: a byte every 200 ms, never the end of the headers;
  // each one the server times out is opened again.
  std::atomic<bool> stop{false};
  std::atomic<int> reopened{0};
  std::vector<std::thread> slow;
  for (int a = 0; a < 8; ++a)
    slow.emplace_back([&, a] {
      const std::string from = loopback(2, 1 + a);
      std::vector<std::unique_ptr<RawTcp>> held;
      for (int i = 0; i < 8; ++i) held.push_back(std::make_unique<RawTcp>(web, 0, from.c_str()));
      for (std::size_t byte = 0; !stop; ++byte) {
        for (auto& c : held)
          if (!c->send(proto::Bytes{static_cast<std::uint8_t>(request[byte % request.size()])})) {
            c = std::make_unique<RawTcp>(web, 0, from.c_str());
            ++reopened;
          }
        std::this_thread::sleep_for(milliseconds(200));
      }
    });
  std::this_thread::sleep_for(milliseconds(1000));
  const int under_slowloris = page_loads(web, 10);
  stop = true;
  for (auto& t : slow) t.join();
  // Idle connections from 100 addresses, one each, and then 300 from 30 (ten each): more than
  // the listener holds, so the oldest silent ones make room.
  std::vector<std::unique_ptr<RawTcp>> idle;
  for (int a = 0; a < 100; ++a) idle.push_back(std::make_unique<RawTcp>(web, 0, loopback(3, 1 + a).c_str()));
  std::this_thread::sleep_for(milliseconds(300));
  const int beside_idle = page_loads(web, 10);
  for (int a = 0; a < 30; ++a)
    for (int i = 0; i < 10; ++i) idle.push_back(std::make_unique<RawTcp>(web, 0, loopback(4, 1 + a).c_str()));
  std::this_thread::sleep_for(milliseconds(300));
  const int beside_flood = page_loads(web, 10);
  const double evicted = rejects(server.metrics_port(), "http_evicted");
  std::printf("[lockouts] page loads: %d of 10 beside 64 slowloris connections from 8 addresses (%d reopened), %d of 10 "
              "beside 100 idle ones from 100 addresses, %d of 10 beside 400 (%.0f evicted)\n",
              under_slowloris, reopened.load(), beside_idle, beside_flood, evicted);
  CHECK(server.alive());
  CHECK(under_slowloris == 10);  // main: 0 of 11
  CHECK(beside_idle == 10);      // main: 0 of 10
  CHECK(beside_flood == 10);
  CHECK(evicted > 0.0);
}

TEST_CASE("one address holds at most 64 connections by default, and an empty WebSocket Origin is refused",
          "[lockouts]") {
  ServerProcess server(fault_server({"--size", "64", "--profiles", "mobile", "--max-clients", "300", "--ws-listen",
                                     "127.0.0.1:0"}));  // 100 connections: within one range's burst
  std::vector<std::unique_ptr<RawTcp>> hoard;
  int held = 0;
  for (int i = 0; i < 100; ++i) {
    hoard.push_back(std::make_unique<RawTcp>(server.tcp_port()));
    held += hoard.back()->handshake(hello("hoarder"), 2.0).has_value();
  }
  RawTcp other(server.tcp_port(), 0, loopback(5, 1).c_str());
  const bool other_welcomed = other.handshake(hello("other"), 2.0).has_value();
  // A WebSocket upgrade whose Origin header is there but empty (from another address: 127.0.0.1
  // holds its 64).
  RawTcp ws(server.ws_port(), 0, loopback(5, 2).c_str());
  const std::string upgrade = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                              "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\nOrigin: \r\n\r\n";
  ws.send(proto::Bytes(upgrade.begin(), upgrade.end()));
  const std::vector<std::uint8_t> answer = ws.read_raw(2.0);
  const std::string status(answer.begin(), answer.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(answer.size(), 12)));
  std::printf("[lockouts] 100 sessions from one address: %d welcomed, another address welcomed: %d; an empty Origin: '%s'\n",
              held, other_welcomed, status.c_str());
  CHECK(held == 64);  // main: 100 (no limit by default; 300 WebSocket sessions held every slot)
  CHECK(other_welcomed);
  CHECK(rejects(server.metrics_port(), "address_connections_full") >= 36.0);
  CHECK(status == "HTTP/1.1 403");  // main: 101, as if no Origin had been sent
}

TEST_CASE("guessing from 50 addresses is as slow as from one, and the operator behind a guesser's address gets in",
          "[lockouts]") {
  const TempFile token_file("the-operators-token\n");  // removed however the test ends
  // Viewer slots for every guesser: one refused server_full that reconnected at once would churn
  // its /24 past --connect-rate-per-ip, which closes the range (the operator's too) at accept.
  FaultScenario s({"--size", "64", "--profiles", "mobile,lite", "--max-clients", "200", "--admin-token-file", token_file.path()});
  start_population(s);
  std::atomic<bool> stop{false};
  std::atomic<std::uint64_t> guesses{0};
  std::vector<std::thread> guessers;
  // 50 addresses, the first (the operator's NAT) with four guessers: on main it spent its budget
  // of 10 wrong tokens a minute within seconds, and the operator's right token was refused.
  for (int g = 0; g < 53; ++g)
    guessers.emplace_back([&, g] {
      lower_thread_priority();
      const int a = g < 50 ? g : 0;
      const std::string from = loopback(6, 1 + a);
      std::uint32_t id = 0;
      while (!stop) {  // guess, read the answer, guess again; reconnect when closed
        RawTcp guesser(s.port(), 0, from.c_str());
        if (!guesser.handshake(hello("guesser"), 2.0)) {
          std::this_thread::sleep_for(milliseconds(1000));  // refused: try later, as a client does
          continue;
        }
        proto::ParamChange change;
        change.wind_speed_mps = 15.0;
        while (!stop && guesser.connected()) {
          change.admin_token = "guess-" + std::to_string(a) + "-" + std::to_string(++id);
          change.request_id = id;
          if (send_param_change(guesser, change, 5.0).error) ++guesses;
          else break;
        }
      }
    });
  const double looked_before = rejects(s.server().metrics_port(), "unauthorized") + rejects(s.server().metrics_port(), "token_guessing");
  const auto counting = Clock::now();
  double took = -1.0;
  const FaultMeasure m = s.measure("50 addresses guessing", [&] {
    std::this_thread::sleep_for(milliseconds(8000));
    // The operator, from the first guesser's address (a shared NAT), with the right token.
    RawTcp admin(s.port(), 0, loopback(6, 1).c_str());
    REQUIRE(admin.handshake(hello("operator"), 2.0));
    proto::ParamChange change;
    change.admin_token = "the-operators-token";
    change.request_id = 4242;
    change.wind_speed_mps = 12.0;
    const auto start = Clock::now();
    if (send_param_change(admin, change, 20.0).applied) took = seconds_since(start);
  });
  stop = true;
  for (auto& t : guessers) t.join();
  const double looked = rejects(s.server().metrics_port(), "unauthorized") + rejects(s.server().metrics_port(), "token_guessing") -
                        looked_before;
  const double counted_s = seconds_since(counting);
  std::printf("[lockouts] 53 guessers from 50 addresses for %.1f s: %.0f tokens looked at (%llu answered), the operator's change "
              "applied after %.1f s\n",
              counted_s, looked, static_cast<unsigned long long>(guesses.load()), took);
  check_population(s, m);
  CHECK(looked <= 10.0 + 5.0 * counted_s + 1.0);  // main: 500 in 8 s from 50 addresses (10 each)
  CHECK(took >= 0.0);                              // main: refused "try later" from the guessers' address
  CHECK(took <= 15.0);
}

TEST_CASE("admin changes as fast as they are answered apply a few, refuse the rest with a reason, and skip no tick",
          "[lockouts]") {
  const TempFile token_file("the-operators-token\n");
  FaultScenario s({"--size", "64", "--profiles", "mobile,lite,desktop", "--admin-token-file", token_file.path()});
  start_population(s);
  const double skipped_before = scrape(s.server().metrics_port(), "ocean_ticks_skipped_total");
  int applied = 0, rate_limited = 0;
  const FaultMeasure m = s.measure("30 changes, no pause", [&] {
    RawTcp admin(s.port());
    REQUIRE(admin.handshake(hello("operator"), 2.0));
    for (int i = 0; i < 30; ++i) {
      proto::ParamChange change;
      change.admin_token = "the-operators-token";
      change.request_id = static_cast<std::uint32_t>(1 + i);
      change.wind_speed_mps = 8.0 + (i % 10);
      const ParamChangeAnswer answer = send_param_change(admin, change, 2.0);
      applied += answer.applied;
      rate_limited += answer.error == proto::Reason::rate_limited;
    }
    std::this_thread::sleep_for(milliseconds(1500));  // the last ones' lead
  });
  const double skipped = scrape(s.server().metrics_port(), "ocean_ticks_skipped_total") - skipped_before;
  std::printf("[lockouts] 30 admin changes in %.1f s: %d applied, %d rate_limited, %.0f ticks skipped; slowest tick "
              "simulated in %.1f ms, served in %.1f ms\n",
              m.seconds, applied, rate_limited, skipped, 1e3 * scrape(s.server().metrics_port(), "ocean_tick_seconds{quantile=\"1\"}"),
              1e3 * scrape(s.server().metrics_port(), "ocean_serve_seconds{quantile=\"1\"}"));
  check_population(s, m);
  CHECK(applied + rate_limited == 30);  // every one answered
  CHECK(applied <= 4 + static_cast<int>(m.seconds) + 1);  // main: 31 of 100 sent in a second applied
  CHECK(applied >= 4);
  if (kTimingMeasurable) CHECK(skipped == 0.0);  // main: 13 on desktop
}
