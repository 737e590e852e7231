// EtcdProcess: one etcd member (Debian's etcd-server) on free loopback ports, its data in a
// folder of its own, for tests of the fleet's timeline; SIGKILLed with the test (ServerProcess).
#pragma once

#include "etcd_gateway.hpp"
#include "server_process.hpp"

#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <unistd.h>

namespace ocean::test_support {

inline std::uint16_t free_port() {
  asio::io_context io;
  asio::ip::tcp::acceptor acceptor(io, {asio::ip::make_address("127.0.0.1"), 0});
  return acceptor.local_endpoint().port();
}

class EtcdProcess {
 public:
  EtcdProcess() {
    if (::access("/usr/bin/etcd", X_OK) != 0) FAIL("/usr/bin/etcd is missing: deploy/install-deps.sh installs etcd-server");
    std::string folder = (std::filesystem::temp_directory_path() / "ocean-etcd-XXXXXX").string();
    REQUIRE(::mkdtemp(folder.data()));
    home_ = folder;
    data_ = home_ / "data";
    // A port probed free may be taken before etcd binds it (parallel tests): then new ports.
    for (int attempt = 0; attempt < 3 && !process_; ++attempt) {
      std::filesystem::remove_all(data_);  // a member bootstrapped on other ports would refuse new ones
      client_port_ = free_port();
      peer_port_ = free_port();
      start(attempt == 2);
    }
  }
  ~EtcdProcess() {
    stop();
    std::error_code ignored;
    std::filesystem::remove_all(home_, ignored);
  }
  // Starts etcd and waits until it answers; when it exits first, false (or, `must`, a failure).
  bool start(bool must = true) {
    const std::string client = "http://127.0.0.1:" + std::to_string(client_port_);
    const std::string peer = "http://127.0.0.1:" + std::to_string(peer_port_);
    const std::string log = (home_ / "etcd.log").string();
    ServerOptions options;
    options.program = "/usr/bin/etcd";
    options.args = {"--data-dir", data_.string(), "--listen-client-urls", client, "--advertise-client-urls", client,
                    "--listen-peer-urls", peer, "--initial-advertise-peer-urls", peer, "--initial-cluster", "default=" + peer};
    options.log_path = log;
    options.wait_listening = false;
    process_.emplace(options);
    const server::EtcdGateway probe({"127.0.0.1", client_port_}, 0.5);
    for (int i = 0; i < 200; ++i) {
      if (probe.range("a", "b", 1).error.empty()) return true;
      if (!must && !process_->alive()) {
        process_.reset();
        return false;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    FAIL("etcd did not answer on port " << client_port_ << " within 10 s (is etcd-server installed? see " << log << ")");
    return false;
  }
  void stop() { process_.reset(); }  // SIGKILL
  std::uint16_t client_port() const { return client_port_; }
  std::string url(const std::string& prefix) const { return "etcd://127.0.0.1:" + std::to_string(client_port_) + prefix; }

 private:
  std::filesystem::path home_, data_;  // a folder of its own: its data and its log
  std::uint16_t client_port_ = 0, peer_port_ = 0;
  std::optional<ServerProcess> process_;  // killed with the test process too
};

}  // namespace ocean::test_support
