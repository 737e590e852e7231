// TcpLink: one client's TCP connection as a StreamLink. Reads size-prefixed messages through a
// TcpFramer and hands each whole message on; writes shared message bytes from a queue bounded in
// bytes, paced by the session's token bucket, so a slow or silent reader never grows server memory.
#pragma once

#include "link.hpp"
#include "tcp_framer.hpp"
#include "token_bucket.hpp"

#include <asio/ip/tcp.hpp>
#include <asio/steady_timer.hpp>

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <span>
#include <string>

namespace ocean::server {

class TcpLink final : public StreamLink, public std::enable_shared_from_this<TcpLink> {
 public:
  // max_queue_bytes bounds the frames waiting to be written; control messages may use
  // kControlHeadroomBytes more, and nothing ever goes beyond that.
  TcpLink(asio::ip::tcp::socket socket, std::size_t max_queue_bytes);

  std::string_view transport() const override { return "tcp"; }
  const std::string& peer() const override { return peer_text_; }
  bool open() const override { return !closed_; }
  void send(SharedBytes message) override;

  void start(MessageHandler on_message, CloseHandler on_close) override;
  asio::ip::address address() const override { return peer_.address(); }
  bool has_room(std::size_t frame_bytes) const override { return queued_bytes_ + frame_bytes <= max_queue_bytes_; }
  // A client that asks for answers (Pings) but does not read them runs out of the headroom.
  bool has_control_room(std::size_t bytes) const override {
    return queued_bytes_ + bytes <= max_queue_bytes_ + kControlHeadroomBytes;
  }
  void set_rate(double bytes_per_s) override;
  void set_max_message_bytes(std::size_t bytes) override { framer_.set_max_message_bytes(bytes); }
  void close_after_flush(double grace_s) override;  // closes anyway after grace_s (a reader that stopped)
  void close(const std::string& reason) override;
  std::size_t queued_bytes() const override { return queued_bytes_; }
  std::size_t peak_queued_bytes() const override { return peak_queued_bytes_; }
  std::uint64_t enqueued_total() const override { return enqueued_total_; }
  bool written_through(std::uint64_t mark) const override { return enqueued_total_ - queued_bytes_ >= mark; }
  protocol::Reason framing_failure() const override { return framing_failure_; }

  std::size_t max_queue_bytes() const { return max_queue_bytes_; }
  std::size_t framer_buffered_bytes() const { return framer_.buffered_bytes(); }

 private:
  void do_read();
  void do_write();

  asio::ip::tcp::socket socket_;
  asio::ip::tcp::endpoint peer_;
  std::string peer_text_;
  asio::steady_timer pace_timer_;
  asio::steady_timer close_timer_;
  protocol::TcpFramer framer_;
  std::array<std::uint8_t, 16 * 1024> read_buffer_{};
  std::deque<SharedBytes> queue_;
  std::size_t queued_bytes_ = 0;
  std::uint64_t enqueued_total_ = 0;
  std::size_t peak_queued_bytes_ = 0;
  std::size_t max_queue_bytes_;
  TokenBucket bucket_{0.0, 0.0, 0.0};
  protocol::Reason framing_failure_ = protocol::Reason::ok;
  bool writing_ = false;
  bool closing_ = false;
  bool closed_ = false;
  MessageHandler on_message_;
  CloseHandler on_close_;
};

// Seconds on a monotonic clock, the time base of pacing and session timers.
double monotonic_s();

}  // namespace ocean::server
