#include "tcp_link.hpp"

#include "open_link.hpp"
#include "transport_context.hpp"

#include <asio/write.hpp>

namespace ocean::server {

std::shared_ptr<StreamLink> TcpLink::open(asio::ip::tcp::socket socket, const TransportContext& context) {
  return std::make_shared<TcpLink>(std::move(socket), context.queue_bytes);
}
template std::shared_ptr<StreamLink> open_link<TcpLink>(asio::ip::tcp::socket, const TransportContext&);

void TcpLink::do_read() {
  stream_.read_some(asio::buffer(read_buffer_), [self = self<TcpLink>()](std::error_code error, std::size_t n) {
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

void TcpLink::do_write() {
  if (writing_ || closed_) return;
  if (queue_.empty()) {
    if (closing_) close("closed_after_flush");
    return;
  }
  const SharedBytes& front = queue_.front();
  if (const double wait = pace_wait_s(front->size()); wait > 0.0) return write_after(wait);
  writing_ = true;
  stream_.write(asio::buffer(*front), [self = self<TcpLink>()](std::error_code error, std::size_t) {
    self->writing_ = false;
    if (self->closed_) return;
    if (error) return self->close("write_error");
    self->pop_written();
    self->do_write();
  });
}

}  // namespace ocean::server
