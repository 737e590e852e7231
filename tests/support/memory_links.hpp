// In-memory links for driving a SessionCore without sockets: MemoryLink is a StreamLink whose
// writes complete at once (or, with a queue bound, pile up until the test drains them), and
// MemoryDatagrams is the server's UDP socket as a list of what was sent where.
#pragma once

#include "link.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace ocean::test {

class MemoryLink final : public server::StreamLink {
 public:
  explicit MemoryLink(std::string peer = "127.0.0.1:40000", std::size_t max_queue_bytes = 1u << 20,
                      asio::ip::address address = asio::ip::make_address("127.0.0.1"))
      : peer_(std::move(peer)), max_queue_bytes_(max_queue_bytes), address_(std::move(address)) {}

  std::string_view transport() const override { return "tcp"; }
  const std::string& peer() const override { return peer_; }
  bool open() const override { return !closed_; }
  void send(server::SharedBytes message) override {
    if (closed_) return;
    enqueued_total_ += message->size();
    sent_.push_back(*message);
  }
  void start(MessageHandler on_message, CloseHandler on_close) override {
    on_message_ = std::move(on_message);
    on_close_ = std::move(on_close);
  }
  asio::ip::address address() const override { return address_; }
  bool has_room(std::size_t bytes) const override { return bytes <= max_queue_bytes_; }
  bool has_control_room(std::size_t bytes) const override { return bytes <= max_queue_bytes_ + kControlHeadroomBytes; }
  void set_rate(double) override {}
  void set_max_message_bytes(std::size_t) override {}
  void close_after_flush(double) override {
    if (!linger) close("closed_after_flush");
  }
  void close(const std::string& reason) override {
    if (closed_) return;
    closed_ = true;
    close_reason = reason;
    if (on_close_) std::exchange(on_close_, nullptr)(reason);
  }
  std::size_t queued_bytes() const override { return 0; }
  std::size_t peak_queued_bytes() const override { return 0; }
  std::uint64_t enqueued_total() const override { return enqueued_total_; }
  bool written_through(std::uint64_t mark) const override { return enqueued_total_ >= mark; }
  protocol::Reason framing_failure() const override { return protocol::Reason::ok; }

  // Client -> server: one whole message, as a TcpFramer would hand it on.
  void deliver(std::span<const std::uint8_t> message, const server::Instant& now) {
    if (!closed_ && on_message_) on_message_(message, now);
  }
  // Server -> client: what was written since the last take.
  std::vector<protocol::Bytes> take() { return std::exchange(sent_, {}); }

  std::string close_reason;
  bool linger = false;  // close_after_flush leaves it open, like a client that stops reading

 private:
  std::string peer_;
  std::size_t max_queue_bytes_;
  asio::ip::address address_;
  std::uint64_t enqueued_total_ = 0;
  std::vector<protocol::Bytes> sent_;
  bool closed_ = false;
  MessageHandler on_message_;
  CloseHandler on_close_;
};

class MemoryDatagrams final : public server::DatagramSocket {
 public:
  struct Sent {
    protocol::Bytes bytes;
    asio::ip::udp::endpoint to;
  };
  bool send_datagram(std::span<const std::uint8_t> bytes, const asio::ip::udp::endpoint& to) override {
    sent_.push_back(Sent{protocol::Bytes(bytes.begin(), bytes.end()), to});
    return true;
  }
  std::vector<Sent> take() { return std::exchange(sent_, {}); }

 private:
  std::vector<Sent> sent_;
};

}  // namespace ocean::test
