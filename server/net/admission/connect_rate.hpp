// ConnectRate: how fast one address range may open connections. Every connection costs the
// network thread an accept, a session and a close before it says anything, and churned ones (open,
// close, never a byte: 13 400 a second from one local process) are all cost. Beyond a range's
// rate the socket is closed at once, before any of that. A range is an IPv4 /24 or an IPv6 /64:
// what one host or one customer's allocation can cycle through. Pure: times are arguments.
#pragma once

#include "token_bucket.hpp"

#include <asio/ip/address.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>

namespace ocean::server {

class ConnectRate {
 public:
  // per_s 0: no limit. A range may open `burst` connections at once, then per_s a second.
  ConnectRate(double per_s, double burst, std::size_t max_ranges = 4096)
      : per_s_(per_s), burst_(burst), max_ranges_(max_ranges) {}

  // True when `address` may open a connection now (and counts it).
  bool allow(const asio::ip::address& address, double now_s);
  std::size_t tracked_ranges() const { return ranges_.size(); }

  using Range = std::array<std::uint8_t, 9>;  // family, then the prefix's bytes
  static Range range_of(const asio::ip::address& address);

 private:
  struct Entry {
    TokenBucket bucket;
    double last_s;
  };
  void make_room(double now_s);

  double per_s_;
  double burst_;
  std::size_t max_ranges_;
  std::map<Range, Entry> ranges_;
};

}  // namespace ocean::server
