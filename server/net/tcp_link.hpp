// TcpLink: one client's TCP connection. Reads size-prefixed messages through a TcpFramer and
// hands each whole message on; writes shared message bytes from a queue bounded in bytes, paced by
// the session's token bucket, so a slow or silent reader never grows server memory.
#pragma once

#include "profile_stream.hpp"
#include "tcp_framer.hpp"
#include "token_bucket.hpp"

#include <asio/ip/tcp.hpp>
#include <asio/steady_timer.hpp>

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <span>
#include <string>

namespace ocean::server {

class TcpLink : public std::enable_shared_from_this<TcpLink> {
 public:
  using MessageHandler = std::function<void(std::span<const std::uint8_t>)>;
  using CloseHandler = std::function<void(const std::string& reason)>;

  // max_queue_bytes bounds the frames waiting to be written; control messages (Pong, Error,
  // SceneUpdate, Bye) may use kControlHeadroomBytes more, and nothing ever goes beyond that.
  TcpLink(asio::ip::tcp::socket socket, std::size_t max_queue_bytes);
  void start(MessageHandler on_message, CloseHandler on_close);

  static constexpr std::size_t kControlHeadroomBytes = 64 * 1024;
  // A frame message: queued only if the bound leaves room for `frame_bytes` in all (check first).
  bool has_room(std::size_t frame_bytes) const { return queued_bytes_ + frame_bytes <= max_queue_bytes_; }
  // A control message: room within the bound plus the headroom. A client that asks for answers
  // (Pings) but does not read them runs out of it.
  bool has_control_room(std::size_t bytes) const {
    return queued_bytes_ + bytes <= max_queue_bytes_ + kControlHeadroomBytes;
  }
  void send(SharedBytes message);
  // Pacing for everything written from now on (bytes per second, 0 = unlimited).
  void set_rate(double bytes_per_s);
  void set_max_message_bytes(std::size_t bytes) { framer_.set_max_message_bytes(bytes); }
  // Writes what is queued, then closes; closes anyway after `grace_s` (a reader that stopped).
  void close_after_flush(double grace_s);
  void close(const std::string& reason);

  std::size_t queued_bytes() const { return queued_bytes_; }
  // Bytes ever queued; a message queued when this was `mark` has been written once
  // written_through(mark) holds.
  std::uint64_t enqueued_total() const { return enqueued_total_; }
  bool written_through(std::uint64_t mark) const { return enqueued_total_ - queued_bytes_ >= mark; }
  std::size_t max_queue_bytes() const { return max_queue_bytes_; }
  std::size_t peak_queued_bytes() const { return peak_queued_bytes_; }
  std::size_t framer_buffered_bytes() const { return framer_.buffered_bytes(); }
  const asio::ip::tcp::endpoint& peer() const { return peer_; }
  protocol::Reason framing_failure() const { return framing_failure_; }  // set when a message was empty
  bool open() const { return !closed_; }

 private:
  void do_read();
  void do_write();

  asio::ip::tcp::socket socket_;
  asio::ip::tcp::endpoint peer_;
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
