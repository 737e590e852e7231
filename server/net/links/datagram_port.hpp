// DatagramPort: the server's UDP socket, kept out of asio's reactor. asio registers every socket
// edge-triggered for good, so each arriving datagram woke the network thread: a thousand viewers
// acking ten times a second cost about 7000 wakes a second, and the wakes, not the acks, were the
// cost. Here the socket waits in an epoll set of its own, one-shot: a wake drains it in batches
// (recvmmsg), and only after a pause of a millisecond is it armed again, so a steady stream of
// datagrams costs at most one wake per pause. An ack or a Ping waits at most that long, far below
// a tick and any round trip it measures. Sending goes through fd() (sendmmsg, sendto).
#pragma once

#include <asio/io_context.hpp>
#include <asio/ip/udp.hpp>
#include <asio/posix/stream_descriptor.hpp>
#include <asio/steady_timer.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace ocean::server {

class DatagramPort {
 public:
  using Handler = std::function<void(std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& from)>;
  static constexpr std::size_t kBatch = 32;           // datagrams per recvmmsg
  static constexpr std::size_t kMaxPerWake = 256;     // then ticks and TCP get their turn
  static constexpr std::size_t kBufferBytes = 1500;   // larger datagrams arrive truncated (and are refused)
  static constexpr std::chrono::microseconds kPause{1000};

  // Takes the bound socket over (it leaves asio's reactor). Throws std::system_error.
  DatagramPort(asio::io_context& context, asio::ip::udp::socket socket, Handler handler);
  ~DatagramPort();
  DatagramPort(const DatagramPort&) = delete;
  DatagramPort& operator=(const DatagramPort&) = delete;

  void start();  // reads until close()
  void close();
  bool is_open() const { return fd_ >= 0; }
  int fd() const { return fd_; }

  std::uint64_t wakes() const { return wakes_; }

 private:
  void arm();
  std::size_t drain();

  int fd_ = -1;
  asio::posix::stream_descriptor ready_;  // the epoll set holding fd_, readable when fd_ is
  asio::steady_timer pause_;
  Handler handler_;
  std::vector<std::array<std::uint8_t, kBufferBytes>> buffers_;
  std::array<asio::ip::udp::endpoint, kBatch> senders_;
  std::uint64_t wakes_ = 0;
};

}  // namespace ocean::server
