#include "tcp_link.hpp"

#include "wire_limits.hpp"

#include <asio/write.hpp>

#include <algorithm>
#include <chrono>

namespace ocean::server {

double monotonic_s() { return now_instant().monotonic_s; }

TcpLink::TcpLink(asio::ip::tcp::socket socket, std::size_t max_queue_bytes)
    : socket_(std::move(socket)),
      pace_timer_(socket_.get_executor()),
      close_timer_(socket_.get_executor()),
      max_queue_bytes_(max_queue_bytes) {
  std::error_code ignored;
  peer_ = socket_.remote_endpoint(ignored);
  peer_text_ = endpoint_text(peer_.address(), peer_.port());
  socket_.set_option(asio::ip::tcp::no_delay(true), ignored);
}

void TcpLink::start(MessageHandler on_message, CloseHandler on_close) {
  on_message_ = std::move(on_message);
  on_close_ = std::move(on_close);
  do_read();
}

void TcpLink::do_read() {
  socket_.async_read_some(asio::buffer(read_buffer_), [self = shared_from_this()](std::error_code error, std::size_t n) {
    if (self->closed_) return;
    if (error) return self->close(error == asio::error::eof ? "peer_closed" : "read_error");
    std::span<const std::uint8_t> bytes(self->read_buffer_.data(), n);
    while (!bytes.empty() && !self->closed_ && !self->closing_) {
      const protocol::TcpFramer::Result result = self->framer_.feed(bytes);
      bytes = bytes.subspan(result.consumed);
      if (result.status == protocol::TcpFramer::Status::bad) {
        // Hand the refusal on as an empty message; the session answers Error and closes.
        self->framing_failure_ = result.reason;
        self->on_message_(std::span<const std::uint8_t>(), now_instant());
        return;
      }
      if (result.status == protocol::TcpFramer::Status::good) self->on_message_(self->framer_.message(), now_instant());
    }
    if (!self->closed_ && !self->closing_) self->do_read();
  });
}

void TcpLink::send(SharedBytes message) {
  if (closed_) return;
  queued_bytes_ += message->size();
  enqueued_total_ += message->size();
  peak_queued_bytes_ = std::max(peak_queued_bytes_, queued_bytes_);
  queue_.push_back(std::move(message));
  do_write();
}

void TcpLink::set_rate(double bytes_per_s) {
  // A burst of two datagram-sized messages: frames go out at the announced rate, never in bursts.
  bucket_ = TokenBucket(bytes_per_s, 2.0 * protocol::kMaxDatagram, monotonic_s());
}

void TcpLink::do_write() {
  if (writing_ || closed_) return;
  if (queue_.empty()) {
    if (closing_) close("closed_after_flush");
    return;
  }
  const SharedBytes& front = queue_.front();
  const double now = monotonic_s();
  const double wait = bucket_.wait_s(front->size(), now);
  writing_ = true;
  if (wait > 0.0) {
    pace_timer_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(wait)));
    pace_timer_.async_wait([self = shared_from_this()](std::error_code) {
      self->writing_ = false;
      self->do_write();
    });
    return;
  }
  bucket_.take(front->size(), now);
  asio::async_write(socket_, asio::buffer(*front), [self = shared_from_this()](std::error_code error, std::size_t) {
    self->writing_ = false;
    if (self->closed_) return;
    if (error) return self->close("write_error");
    self->queued_bytes_ -= self->queue_.front()->size();
    self->queue_.pop_front();
    self->do_write();
  });
}

void TcpLink::close_after_flush(double grace_s) {
  if (closed_ || closing_) return;
  closing_ = true;
  close_timer_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(grace_s)));
  close_timer_.async_wait([self = shared_from_this()](std::error_code error) {
    if (!error) self->close("flush_timeout");
  });
  do_write();
}

void TcpLink::close(const std::string& reason) {
  if (closed_) return;
  closed_ = true;
  std::error_code ignored;
  pace_timer_.cancel();
  close_timer_.cancel();
  socket_.shutdown(asio::ip::tcp::socket::shutdown_both, ignored);
  socket_.close(ignored);
  queue_.clear();
  queued_bytes_ = 0;
  if (on_close_) {
    CloseHandler handler = std::move(on_close_);
    on_close_ = nullptr;
    on_message_ = nullptr;
    handler(reason);
  }
}

}  // namespace ocean::server
