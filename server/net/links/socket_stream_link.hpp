// SocketStreamLink: what every StreamLink over one accepted TCP socket shares, whatever its
// framing (TcpLink: size prefixes; WebSocketLink: WebSocket messages): the send queue bounded in
// bytes (frames up to the bound, control messages into the headroom above it), its accounting
// (written_through), the pacing bucket, and closing (now, or once the queue is written, within a
// grace time). A subclass reads and writes: do_read() once started, do_write() whenever there may
// be something to write. Over TLS (a wss listener with --tls-cert) the handshake comes first.
#pragma once

#include "byte_stream.hpp"
#include "link.hpp"
#include "token_bucket.hpp"

#include <asio/ip/tcp.hpp>
#include <asio/steady_timer.hpp>

#include <cstdint>
#include <deque>
#include <memory>
#include <string>

namespace ocean::server {

class SocketStreamLink : public StreamLink, public std::enable_shared_from_this<SocketStreamLink> {
 public:
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
  void close_after_flush(double grace_s) override;  // closes anyway after grace_s (a reader that stopped)
  void close(const std::string& reason) override;
  std::size_t queued_bytes() const override { return queued_bytes_; }
  std::size_t peak_queued_bytes() const override { return peak_queued_bytes_; }
  std::uint64_t enqueued_total() const override { return enqueued_total_; }
  bool written_through(std::uint64_t mark) const override { return enqueued_total_ - queued_bytes_ >= mark; }
  protocol::Reason framing_failure() const override { return framing_failure_; }

  std::size_t max_queue_bytes() const { return max_queue_bytes_; }

 protected:
  // max_queue_bytes bounds the frames waiting to be written; control messages may use
  // kControlHeadroomBytes more, and nothing ever goes beyond that. tls: null in the clear.
  SocketStreamLink(asio::ip::tcp::socket socket, std::size_t max_queue_bytes,
                   const std::shared_ptr<asio::ssl::context>& tls = nullptr);

  virtual void do_read() = 0;
  virtual void do_write() = 0;
  // The connection failed before it could carry a session (a TLS handshake): told, then closed.
  virtual void on_refused(const std::string& /*reason*/) {}
  // Seconds until the front message may go at the session's rate (0: now, and it is taken).
  double pace_wait_s(std::size_t bytes);
  // The front message was written: its bytes leave the queue.
  void pop_written();
  // Nothing queued can be written any more (the connection is ending).
  void drop_queue();
  // Closes with `reason` after grace_s unless closed before (a reader that stopped).
  void close_within(double grace_s, const char* reason = "flush_timeout");
  // do_write() again after `wait_s` (pacing).
  void write_after(double wait_s);
  template <class Self>
  std::shared_ptr<Self> self() {
    return std::static_pointer_cast<Self>(shared_from_this());
  }

  ByteStream stream_;
  asio::ip::tcp::endpoint peer_;
  std::string peer_text_;
  std::deque<SharedBytes> queue_;
  protocol::Reason framing_failure_ = protocol::Reason::ok;
  bool writing_ = false;
  bool closing_ = false;
  bool closed_ = false;
  MessageHandler on_message_;
  CloseHandler on_close_;

 private:
  asio::steady_timer pace_timer_;
  asio::steady_timer close_timer_;
  std::size_t queued_bytes_ = 0;
  std::uint64_t enqueued_total_ = 0;
  std::size_t peak_queued_bytes_ = 0;
  std::size_t max_queue_bytes_;
  TokenBucket bucket_{0.0, 0.0, 0.0};
};

// Seconds on a monotonic clock, the time base of pacing and session timers.
double monotonic_s();

}  // namespace ocean::server
