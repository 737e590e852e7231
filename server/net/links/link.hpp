// Link: a path for one client's messages, as the session core sees it. The core is pure (bytes and
// time in, bytes and events out); links are its edges to the network:
// - a StreamLink carries ordered, reliable messages both ways and owns its send queue (TcpLink
//   today; a WebSocket link implements the same interface);
// - a UdpLink sends datagrams to one proven address on the server's UDP socket (what arrives on
//   that socket reaches the core through the server, whatever the session).
// Adding a transport: implement StreamLink and hand each accepted connection to
// SessionCore::open (CONTRIBUTING.md "Adding a transport").
#pragma once

#include "shared_bytes.hpp"
#include "wire_reason.hpp"

#include <asio/ip/address.hpp>
#include <asio/ip/udp.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace ocean::server {

// When something happened, as the edge that saw it read its clocks: monotonic seconds for timers
// and pacing, wall-clock milliseconds for cookies and Pongs.
struct Instant {
  double monotonic_s = 0.0;
  std::int64_t unix_ms = 0;
};
Instant now_instant();  // the edges' clock (tcp_link.cpp)

class Link {
 public:
  virtual ~Link() = default;
  virtual std::string_view transport() const = 0;  // metrics and log label: "tcp", "udp", ...
  virtual const std::string& peer() const = 0;      // address text for logs
  virtual bool open() const = 0;
  virtual void send(SharedBytes message) = 0;
};

class StreamLink : public Link {
 public:
  // Every whole message, in order, with the instant it was read. An empty message means the
  // framing failed (framing_failure() says why); nothing follows it.
  using MessageHandler = std::function<void(std::span<const std::uint8_t> message, const Instant& now)>;
  using CloseHandler = std::function<void(const std::string& reason)>;

  // Space reserved beyond the frame bound for control messages (Pong, Error, SceneUpdate, Bye).
  static constexpr std::size_t kControlHeadroomBytes = 64 * 1024;

  virtual void start(MessageHandler on_message, CloseHandler on_close) = 0;
  virtual asio::ip::address address() const = 0;  // the client's IP (the UDP cookie binds it)
  // A frame is queued only if has_room(bytes) (check first); a control message may use the headroom.
  virtual bool has_room(std::size_t bytes) const = 0;
  virtual bool has_control_room(std::size_t bytes) const = 0;
  virtual void set_rate(double bytes_per_s) = 0;  // pacing of all later writes; 0 = unlimited
  virtual void set_max_message_bytes(std::size_t bytes) = 0;
  virtual void close_after_flush(double grace_s) = 0;  // writes what is queued, then closes
  virtual void close(const std::string& reason) = 0;   // now; the close handler runs before it returns
  virtual std::size_t queued_bytes() const = 0;
  virtual std::size_t peak_queued_bytes() const = 0;
  // Bytes ever queued; a message queued when this was `mark` is written once written_through(mark).
  virtual std::uint64_t enqueued_total() const = 0;
  virtual bool written_through(std::uint64_t mark) const = 0;
  virtual protocol::Reason framing_failure() const = 0;
};

// The server's UDP socket as the core uses it: send one datagram, never blocking.
class DatagramSocket {
 public:
  virtual ~DatagramSocket() = default;
  // Now (answers to one datagram: UdpReady).
  virtual bool send_datagram(std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& to) = 0;
  // Shared bytes, possibly queued until flush() so a burst goes out in batches (frames).
  virtual void send_shared(const SharedBytes& bytes, const asio::ip::udp::endpoint& to) { send_datagram(*bytes, to); }
  virtual void flush() {}
};

class UdpLink final : public Link {
 public:
  UdpLink(DatagramSocket& socket, const asio::ip::udp::endpoint& to);
  std::string_view transport() const override { return "udp"; }
  const std::string& peer() const override { return peer_; }
  bool open() const override { return true; }
  void send(SharedBytes datagram) override { socket_->send_shared(datagram, to_); }
  void send(std::span<const std::uint8_t> datagram) { socket_->send_datagram(datagram, to_); }
  const asio::ip::udp::endpoint& endpoint() const { return to_; }

 private:
  DatagramSocket* socket_;
  asio::ip::udp::endpoint to_;
  std::string peer_;
};

// "address:port", for logs.
std::string endpoint_text(const asio::ip::udp::endpoint& endpoint);
std::string endpoint_text(const asio::ip::address& address, std::uint16_t port);

}  // namespace ocean::server
