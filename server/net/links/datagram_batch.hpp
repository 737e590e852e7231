// DatagramBatch: the datagrams of one burst (a tick's frames to every UDP session), sent with one
// sendmmsg per up to kMaxBatch instead of one sendto each: the kernel entry was 28 % of the
// server's time with one sendto per datagram. Holds the shared bytes, so nothing is copied.
#pragma once

#include "shared_bytes.hpp"

#include <asio/ip/udp.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ocean::server {

class DatagramBatch {
 public:
  static constexpr std::size_t kMaxBatch = 64;

  // Queues one datagram; sends the batch once it is full.
  void add(SharedBytes bytes, const asio::ip::udp::endpoint& to, int fd);
  // Sends everything queued on socket `fd` without blocking. Datagrams the kernel refuses (a full
  // socket buffer, an unreachable peer) are dropped and counted.
  void flush(int fd);

  std::uint64_t sent() const { return sent_; }
  std::uint64_t dropped() const { return dropped_; }
  std::uint64_t calls() const { return calls_; }

 private:
  struct Pending {
    SharedBytes bytes;
    asio::ip::udp::endpoint to;
  };
  std::vector<Pending> pending_;
  std::uint64_t sent_ = 0, dropped_ = 0, calls_ = 0;
};

}  // namespace ocean::server
