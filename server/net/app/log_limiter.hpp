// LogLimiter: which lines of a repeated event reach the log. A peer that can make the server log
// (a wrong token, a replayed datagram, a connection loop) must not be able to fill the disk or
// drown other lines, yet the operator must still see that it happens: each (reason, peer address)
// gets a few lines per window, each reason a few more over all peers, and at the end of a window
// one summary per reason says how many lines were left out. Single-threaded; server_log locks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ocean::server {

class LogLimiter {
 public:
  struct Limits {
    double window_s = 10.0;
    int per_peer = 5;          // lines per reason and peer address per window
    int per_reason = 50;       // lines per reason over all peers per window
    std::size_t max_peers = 4096;  // distinct (reason, address) keys kept; beyond, only per_reason applies
  };

  LogLimiter() : LogLimiter(Limits{}) {}
  explicit LogLimiter(Limits limits) : limits_(limits) {}

  // True when a line about `reason` from `peer` ("ip:port", "[v6]:port" or "") may be written at
  // now_s. The port is ignored: a connection loop gets a new one each time.
  bool allow(std::string_view reason, std::string_view peer, double now_s);
  // When the window holding now_s has ended: the lines left out in it, per reason (then reset).
  std::vector<std::pair<std::string, std::uint64_t>> take_summary(double now_s);
  std::uint64_t suppressed_total() const { return suppressed_total_; }

 private:
  void roll(double now_s);

  Limits limits_;
  double window_start_s_ = -1.0;
  std::map<std::string, int, std::less<>> per_peer_;      // "reason address" -> lines this window
  std::map<std::string, int, std::less<>> per_reason_;    // lines this window
  std::map<std::string, std::uint64_t, std::less<>> suppressed_;  // this window
  std::vector<std::pair<std::string, std::uint64_t>> ended_;      // of windows that ended, not taken
  std::uint64_t suppressed_total_ = 0;
};

// The address part of "ip:port" or "[v6]:port" (the text itself when it has no port).
std::string_view peer_address(std::string_view peer);

}  // namespace ocean::server
