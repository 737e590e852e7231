#include "server.hpp"
#include "server_log.hpp"
#include "raw_http_get.hpp"

#include <asio/connect.hpp>
#include <asio/read.hpp>
#include <asio/write.hpp>
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <future>
#include <thread>

using namespace ocean::server;
using ocean::server::test::raw_http_get;
using namespace std::chrono_literals;

namespace {

ServerConfig test_config() {
  ServerConfig config;
  config.listen = {"127.0.0.1", 0};
  config.metrics_listen = ListenAddress{"127.0.0.1", 0};
  config.scene.size_x = config.scene.size_z = 64;
  config.scene.patch_x_m = config.scene.patch_z_m = 64.0;
  config.profiles = {"lite", "mobile"};
  config.tick_rate_hz = 60;
  config.log_level = "warn";
  set_log_level(config.log_level);  // main() does this for ocean-server
  REQUIRE(validate_server_config(config) == "");
  return config;
}

// Runs server.run() on a thread; the future is ready when run() has returned.
std::future<void> run_async(Server& server) {
  return std::async(std::launch::async, [&server] { server.run(); });
}

bool wait_until(const std::function<bool()>& condition, std::chrono::milliseconds limit = 5s) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(5ms);
  }
  return true;
}

}  // namespace

TEST_CASE("stop() ends a running server cleanly", "[server]") {
  Server server(test_config());
  CHECK(server.tcp_port() != 0);
  CHECK(server.udp_port() == server.tcp_port());  // UDP follows the TCP port unless told otherwise
  auto done = run_async(server);
  REQUIRE(wait_until([&] { return server.ready(); }));
  server.stop();
  REQUIRE(done.wait_for(5s) == std::future_status::ready);
  done.get();
  CHECK(server.metrics().ticks.value() >= 1);
}

TEST_CASE("SIGTERM ends a running server cleanly", "[server]") {
  Server server(test_config());
  auto done = run_async(server);
  REQUIRE(wait_until([&] { return server.ready(); }));
  std::raise(SIGTERM);  // handled by the server's signal_set, not the default action
  REQUIRE(done.wait_for(5s) == std::future_status::ready);
  done.get();
  // The listeners are closed: a new connection to the old port is refused.
  asio::io_context context;
  asio::ip::tcp::socket socket(context);
  std::error_code error;
  socket.connect({asio::ip::make_address("127.0.0.1"), server.tcp_port()}, error);
  CHECK(error);
}

TEST_CASE("a signal that arrives before run() still stops the server", "[server]") {
  Server server(test_config());
  std::raise(SIGINT);
  auto done = run_async(server);
  REQUIRE(done.wait_for(5s) == std::future_status::ready);
  done.get();
}

TEST_CASE("/metrics, /healthz and /readyz are served over loopback", "[server][metrics]") {
  Server server(test_config());
  REQUIRE(server.metrics_port());
  const std::uint16_t port = *server.metrics_port();
  auto done = run_async(server);
  REQUIRE(wait_until([&] { return server.ready() && server.metrics().ticks.value() >= 3; }));

  const std::string metrics = raw_http_get(port, "/metrics");
  CHECK(metrics.rfind("HTTP/1.1 200 OK\r\n", 0) == 0);
  CHECK(metrics.find("Content-Type: text/plain; version=0.0.4") != std::string::npos);
  CHECK(metrics.find("\nocean_ticks_total ") != std::string::npos);
  CHECK(metrics.find("\nocean_frames_computed_total{profile=\"mobile\"} ") != std::string::npos);
  CHECK(metrics.find("\nocean_clients{profile=\"lite\",transport=\"udp\"} 0") != std::string::npos);
  CHECK(metrics.find("\nocean_tick_seconds{quantile=\"0.5\"} ") != std::string::npos);
  const std::size_t body = metrics.find("\r\n\r\n") + 4;
  const std::size_t length_at = metrics.find("Content-Length: ") + 16;
  CHECK(std::stoul(metrics.substr(length_at)) == metrics.size() - body);

  CHECK(raw_http_get(port, "/healthz").find("\r\n\r\nok\n") != std::string::npos);
  CHECK(raw_http_get(port, "/readyz").rfind("HTTP/1.1 200", 0) == 0);
  CHECK(raw_http_get(port, "/nope").rfind("HTTP/1.1 404", 0) == 0);

  server.stop();
  REQUIRE(done.wait_for(5s) == std::future_status::ready);
}

TEST_CASE("frames reach the network side in tick order at tick / rate", "[server]") {
  Server server(test_config());
  std::vector<std::pair<std::int64_t, double>> seen;  // network thread only, read after run() ends
  std::vector<int> grids;
  server.set_frame_sink([&](const std::shared_ptr<const TickFrames>& frames) {
    seen.emplace_back(frames->tick, frames->time_s);
    if (grids.empty())
      for (const ProfileFrame& f : frames->frames) grids.push_back(f.frame.n_x);
  });
  auto done = run_async(server);
  REQUIRE(wait_until([&] { return server.metrics().ticks.value() >= 10; }));
  server.stop();
  REQUIRE(done.wait_for(5s) == std::future_status::ready);

  REQUIRE(seen.size() >= 5);
  CHECK(grids == std::vector<int>{32, 64});
  bool increasing = true, timed = true;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    timed &= std::abs(seen[i].second - static_cast<double>(seen[i].first) / 60.0) < 1e-6;
    if (i > 0) increasing &= seen[i].first > seen[i - 1].first;
  }
  CHECK(increasing);
  CHECK(timed);
  // The first tick is the current wall-clock tick counted from the epoch, not tick 0.
  const auto now_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                          std::chrono::system_clock::now().time_since_epoch()).count();
  const auto now_tick = (now_ms - server.config().epoch_unix_ms) * 60 / 1000;
  CHECK(std::abs(seen.back().first - now_tick) < 60 * 5);
}

TEST_CASE("a network side slower than the ticks still answers stop() and SIGTERM", "[server]") {
  // Each tick takes the network thread 5 periods: a new tick always waits when one is served.
  // Served back to back in one handler, they would keep stop's handler waiting for ever.
  Server server(test_config());
  std::atomic<int> served{0};
  std::atomic<bool> slow{true};  // cleared after the verdict, so a failing server still ends
  server.set_frame_sink([&](const std::shared_ptr<const TickFrames>&) {
    ++served;
    if (slow) std::this_thread::sleep_for(std::chrono::milliseconds(5 * 1000 / 60));
  });
  auto done = run_async(server);
  REQUIRE(wait_until([&] { return served >= 3; }));
  const auto asked = std::chrono::steady_clock::now();
  std::raise(SIGTERM);
  const bool stopped = done.wait_for(5s) == std::future_status::ready;
  slow = false;
  REQUIRE(stopped);
  done.get();
  // The signal waits for at most the tick being served, then the goodbyes' grace.
  CHECK(std::chrono::steady_clock::now() - asked < std::chrono::duration<double>(kStopGraceS + 1.0));
  CHECK(server.metrics().frames_dropped.value() > 0);  // the queue kept the newest ticks
}

TEST_CASE("until sessions exist, TCP clients are refused with a counted reason", "[server]") {
  Server server(test_config());
  auto done = run_async(server);
  asio::io_context context;
  asio::ip::tcp::socket socket(context);
  socket.connect({asio::ip::make_address("127.0.0.1"), server.tcp_port()});
  char byte;
  std::error_code error;
  asio::read(socket, asio::buffer(&byte, 1), error);
  CHECK(error == asio::error::eof);  // closed by the server
  CHECK(wait_until([&] { return server.metrics().rejects("sessions_unavailable").value() == 1; }));
  server.stop();
  REQUIRE(done.wait_for(5s) == std::future_status::ready);
}

TEST_CASE("an epoch too far from now fails construction naming --epoch", "[server]") {
  ServerConfig config = test_config();
  config.epoch_unix_ms = 0;  // now is ~1.8e9 s later, beyond what the simulation accepts
  CHECK_THROWS_WITH(Server(config), Catch::Contains("--epoch 0"));
}

TEST_CASE("a port already in use fails construction naming the address", "[server]") {
  Server first(test_config());
  ServerConfig clash = test_config();
  clash.listen.port = first.tcp_port();
  CHECK_THROWS_WITH(Server(clash), Catch::Contains("127.0.0.1:" + std::to_string(first.tcp_port())));
}
