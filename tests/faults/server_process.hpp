// ServerProcess: the real ocean-server binary of the build tree, spawned on free loopback ports.
// Its log is drained by a thread (a full pipe would stall the server), the ports are read from its
// "listening" line, and its resident memory is read from /proc. Killed when destroyed.
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <sys/types.h>
#include <thread>
#include <vector>

namespace ocean::faults {

class ServerProcess {
 public:
  // extra_args follow --listen/--metrics-listen (127.0.0.1, port 0); throws when it does not start.
  explicit ServerProcess(const std::vector<std::string>& extra_args);
  ~ServerProcess();
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  std::uint16_t tcp_port() const { return tcp_port_; }  // UDP is on the same port
  std::uint16_t metrics_port() const { return metrics_port_; }
  pid_t pid() const { return pid_; }
  bool alive() const;
  // VmRSS in KiB; nullopt when the process is gone.
  std::optional<std::uint64_t> rss_kib() const;
  std::string log() const;

 private:
  void drain_output();
  void shutdown();  // kills the server and stops the drainer; safe to call twice

  pid_t pid_ = -1;
  int read_fd_ = -1;
  std::uint16_t tcp_port_ = 0;
  std::uint16_t metrics_port_ = 0;
  mutable std::mutex mutex_;
  std::string log_;
  std::atomic<bool> stop_{false};
  std::thread drainer_;
};

}  // namespace ocean::faults
