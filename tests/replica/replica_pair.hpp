// ReplicaPair: two ocean-server processes started from one TOML config file (the production
// path: --config), each on its own free loopback port, in a temporary directory removed at the
// end. The config fixes the epoch, seed, scene, profiles and vessels, so the two are replicas.
#pragma once

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include <asio/ip/tcp.hpp>

#include "server_process.hpp"

namespace ocean::replica_test {

using test_support::ServerProcess;

// 2026-01-01T00:00:00Z, written in the file as a TOML date-time.
inline constexpr std::int64_t kEpochUnixMs = 1767225600000;
inline constexpr int kTickRateHz = 30;

// With `vessels`, two vessels sail: the wake is the server's own sea (CODEC.md 7.9), and replicas
// must author it alike. With `metrics`, each replica serves /metrics and /readyz on a port of its own.
inline std::string replica_config_toml(bool vessels, bool metrics = false) {
  return R"(# Written by tests/replica: every replica of this test reads this one file.
listen = "127.0.0.1:0"
metrics-listen = ")" + std::string(metrics ? "127.0.0.1:0" : "off") + R"("
size = 64
patch = 64.0
spectrum = "jonswap"
wind-speed = 12.0
wind-dir = 30.0
seed = 20261121
tick-rate = 30
epoch = 2026-01-01T00:00:00Z
profiles = ["mobile", "lite"]
idle-timeout = 60
log-level = "info"
)" + std::string(vessels ? R"(
[[vessel]]
id = 1
length = 24
beam = 6
draft = 1.5
repeat = true
waypoints = [[0, -100, -100], [30, 100, -100], [60, 100, 100], [90, -100, 100], [120, -100, -100]]

[[vessel]]
id = 2
length = 10
beam = 3
draft = 0.6
repeat = true
waypoints = [[0, -200, 40], [50, 200, 40], [100, -200, 40]]
)" : "");
}

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("ocean-replica-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

class ReplicaPair {
 public:
  // stagger_s: the second replica starts this long after the first is listening, so the two
  // begin at different ticks (frames must not depend on when a server started). vessels: the
  // config runs two (replica_config_toml).
  explicit ReplicaPair(double stagger_s = 0.0, bool vessels = false) {
    std::ofstream(dir_.file("ocean.toml")) << replica_config_toml(vessels);
    for (int i = 0; i < 2; ++i) {
      if (i == 1 && stagger_s > 0.0) {
        REQUIRE(servers_[0]->wait_listening(30.0));
        std::this_thread::sleep_for(std::chrono::duration<double>(stagger_s));
      }
      // Both start before either is waited for, so they come up side by side.
      test_support::ServerOptions options;
      options.args = {"--config", dir_.file("ocean.toml")};
      options.log_path = dir_.file("server-" + std::to_string(i) + ".log");
      options.wait_listening = false;
      servers_[i] = std::make_unique<ServerProcess>(std::move(options));
    }
    for (int i = 0; i < 2; ++i) {
      const bool listening = servers_[i]->wait_listening(30.0);
      INFO("replica " << i << " log:\n" << servers_[i]->log());
      REQUIRE(listening);
      ports_[i] = servers_[i]->tcp_port();
    }
  }

  ServerProcess& server(int i) { return *servers_[i]; }
  std::uint16_t port(int i) const { return ports_[i]; }
  std::vector<asio::ip::tcp::endpoint> endpoints() const {
    return {{asio::ip::address_v4::loopback(), ports_[0]}, {asio::ip::address_v4::loopback(), ports_[1]}};
  }
  std::string logs() const { return "replica 0:\n" + servers_[0]->log() + "replica 1:\n" + servers_[1]->log(); }

 private:
  TempDir dir_;
  std::unique_ptr<ServerProcess> servers_[2];
  std::uint16_t ports_[2] = {0, 0};
};

}  // namespace ocean::replica_test
