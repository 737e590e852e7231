#include "socket_stream_link.hpp"

#include "wire_limits.hpp"

#include <algorithm>
#include <chrono>

namespace ocean::server {

double monotonic_s() { return now_instant().monotonic_s; }

SocketStreamLink::SocketStreamLink(asio::ip::tcp::socket socket, std::size_t max_queue_bytes,
                                   const std::shared_ptr<asio::ssl::context>& tls)
    : stream_(std::move(socket), tls),
      pace_timer_(stream_.socket().get_executor()),
      close_timer_(stream_.socket().get_executor()),
      max_queue_bytes_(max_queue_bytes) {
  std::error_code ignored;
  peer_ = stream_.socket().remote_endpoint(ignored);
  peer_text_ = endpoint_text(peer_.address(), peer_.port());
  stream_.socket().set_option(asio::ip::tcp::no_delay(true), ignored);
}

void SocketStreamLink::start(MessageHandler on_message, CloseHandler on_close) {
  on_message_ = std::move(on_message);
  on_close_ = std::move(on_close);
  if (!stream_.is_tls()) return do_read();
  // Writes wait for the handshake too: do_write() sees writing_ until it is done. A client that
  // never finishes it is closed by the session's Hello deadline (--handshake-timeout).
  writing_ = true;
  stream_.handshake([self = shared_from_this()](std::error_code error) {
    if (self->closed_) return;
    if (error) {
      self->on_refused("tls_handshake_failed");
      return self->close("tls_handshake_failed");
    }
    self->writing_ = false;
    self->do_read();
    self->do_write();
  });
}

void SocketStreamLink::send(SharedBytes message) {
  if (closed_) return;
  queued_bytes_ += message->size();
  enqueued_total_ += message->size();
  peak_queued_bytes_ = std::max(peak_queued_bytes_, queued_bytes_);
  queue_.push_back(std::move(message));
  do_write();
}

void SocketStreamLink::set_rate(double bytes_per_s) {
  // A burst of two datagram-sized messages: frames go out at the announced rate, never in bursts.
  bucket_ = TokenBucket(bytes_per_s, 2.0 * protocol::kMaxDatagram, monotonic_s());
}

double SocketStreamLink::pace_wait_s(std::size_t bytes) {
  const double now = monotonic_s();
  const double wait = bucket_.wait_s(bytes, now);
  if (wait <= 0.0) bucket_.take(bytes, now);
  return std::max(0.0, wait);
}

void SocketStreamLink::pop_written() {
  if (queue_.empty()) return;
  queued_bytes_ -= std::min(queued_bytes_, queue_.front()->size());
  queue_.pop_front();
}

void SocketStreamLink::drop_queue() {
  queue_.clear();
  queued_bytes_ = 0;
}

void SocketStreamLink::write_after(double wait_s) {
  writing_ = true;
  pace_timer_.expires_after(
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(wait_s)));
  pace_timer_.async_wait([self = shared_from_this()](std::error_code) {
    self->writing_ = false;
    self->do_write();
  });
}

void SocketStreamLink::close_after_flush(double grace_s) {
  if (closed_ || closing_) return;
  closing_ = true;
  close_within(grace_s);
  do_write();
}

void SocketStreamLink::close_within(double grace_s, const char* reason) {
  close_timer_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(grace_s)));
  close_timer_.async_wait([self = shared_from_this(), reason](std::error_code error) {
    if (!error) self->close(reason);
  });
}

void SocketStreamLink::close(const std::string& reason) {
  if (closed_) return;
  closed_ = true;
  std::error_code ignored;
  pace_timer_.cancel();
  close_timer_.cancel();
  stream_.socket().shutdown(asio::ip::tcp::socket::shutdown_both, ignored);
  stream_.socket().close(ignored);
  drop_queue();
  if (on_close_) {
    CloseHandler handler = std::move(on_close_);
    on_close_ = nullptr;
    on_message_ = nullptr;
    handler(reason);
  }
}

}  // namespace ocean::server
