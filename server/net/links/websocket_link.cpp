#include "websocket_link.hpp"

#include "open_link.hpp"
#include "transport_context.hpp"
#include "wire_limits.hpp"

#include <asio/write.hpp>

#include <algorithm>

namespace ocean::server {

bool OriginPolicy::accepts(const std::optional<std::string>& header, const std::string& host) const {
  if (!header) return true;
  const std::string& origin = *header;
  if (std::any_of(allowed.begin(), allowed.end(), [&](const std::string& a) { return a == "*" || (a == origin && !a.empty()); }))
    return true;
  if (origin.empty()) return false;
  if (page_port == 0 || host.empty()) return false;
  // Host is "name:port", "[v6]:port" or a bare name; the page's Origin has the same name.
  const std::size_t bracket = host.rfind(']');
  const std::size_t colon = host.rfind(':');
  const std::string name = colon != std::string::npos && (bracket == std::string::npos || colon > bracket) ? host.substr(0, colon) : host;
  if (name.empty() || name.find_first_of("/@ ") != std::string::npos) return false;
  const std::size_t scheme_end = origin.find("://");
  if (scheme_end == std::string::npos) return false;
  const std::string scheme = origin.substr(0, scheme_end);
  if (scheme != "http" && scheme != "https") return false;
  const std::string rest = origin.substr(scheme_end + 3);
  if (rest == name + ":" + std::to_string(page_port)) return true;
  return rest == name && page_port == (scheme == "https" ? 443 : 80);  // the default port is not written
}

WebSocketLink::WebSocketLink(asio::ip::tcp::socket socket, std::size_t max_queue_bytes, OriginPolicy origins,
                             std::function<void(const std::string&, const std::string&)> on_refused,
                             const std::shared_ptr<asio::ssl::context>& tls)
    : SocketStreamLink(std::move(socket), max_queue_bytes, tls),
      origins_(std::move(origins)),
      on_refused_(std::move(on_refused)),
      protocol_(protocol_handlers(), protocol::kDefaultMaxMessageBytes) {}

std::shared_ptr<StreamLink> WebSocketLink::open(asio::ip::tcp::socket socket, const TransportContext& context) {
  return std::make_shared<WebSocketLink>(std::move(socket), context.queue_bytes,
                                         OriginPolicy{context.config.ws_origins, context.web_port}, context.refused,
                                         context.tls);
}
template std::shared_ptr<StreamLink> open_link<WebSocketLink>(asio::ip::tcp::socket, const TransportContext&);

WebSocketProtocol::Handlers WebSocketLink::protocol_handlers() {
  WebSocketProtocol::Handlers handlers;
  handlers.accept_origin = [this](const std::optional<std::string>& origin, const std::string& host) {
    return origins_.accepts(origin, host);
  };
  handlers.on_message = [this](const std::uint8_t* data, std::size_t size) {
    if (!closed_ && !closing_ && on_message_) on_message_(std::span<const std::uint8_t>(data, size), now_instant());
  };
  handlers.on_output = [this](const char* data, std::size_t size) { output_.insert(output_.end(), data, data + size); };
  handlers.on_ended = [this](const std::string& reason) { on_ended(reason); };
  return handlers;
}

// The protocol carries nothing more. Bad framing is a refusal the core answers (an empty message,
// as for TcpLink's framer); the rest closes once the protocol's last bytes (a 403, a close frame)
// are written. Called inside feed(), before the protocol has emitted those bytes (websocketpp
// writes a 403 after asking about the Origin): do_read writes them.
void WebSocketLink::on_ended(const std::string& reason) {
  ended_reason_ = reason;
  if (!closing_) close_within(kEndGraceS);  // a client that reads nothing cannot hold the last bytes forever
  if ((reason == "origin_refused" || reason == "handshake_failed") && on_refused_) on_refused_(reason, peer_text_);
  if ((reason == "oversized" || reason == "malformed") && on_message_ && !closing_) {
    framing_failure_ = reason == "oversized" ? protocol::Reason::oversized : protocol::Reason::unexpected_message;
    on_message_(std::span<const std::uint8_t>(), now_instant());
  }
  if (!message_in_flight_) drop_queue();  // nothing more can be framed
}

void WebSocketLink::do_read() {
  stream_.read_some(asio::buffer(read_buffer_), [self = self<WebSocketLink>()](std::error_code error, std::size_t n) {
    if (self->closed_) return;
    if (error) return self->close(error == asio::error::eof ? "peer_closed" : "read_error");
    self->protocol_.feed(self->read_buffer_.data(), n);
    if (self->closed_) return;
    // What the protocol answers by itself (Pongs to WebSocket Pings) is bounded like the queue:
    // a client that sends Pings and reads nothing is closed, not buffered for.
    if (self->output_.size() + self->writing_bytes_.size() > self->max_queue_bytes() + kControlHeadroomBytes)
      return self->close("send_queue_full");
    self->do_write();  // a handshake answer, a Pong, a close frame
    if (self->ended_reason_.empty()) self->do_read();
  });
}

// One write at a time: the protocol's pending bytes first, then the next queued message once the
// handshake is done and the pace allows it; after the queue, on close_after_flush, a close frame.
void WebSocketLink::do_write() {
  if (writing_ || closed_) return;
  if (closing_ && !protocol_.is_open() && ended_reason_.empty() && !message_in_flight_)
    drop_queue();  // refused in its handshake, or closing: nothing more can be framed
  if (output_.empty() && !queue_.empty() && protocol_.is_open()) {
    const SharedBytes& front = queue_.front();
    if (const double wait = pace_wait_s(front->size()); wait > 0.0) return write_after(wait);
    message_in_flight_ = protocol_.send(front->data(), front->size());
    if (!message_in_flight_) pop_written();  // cannot be framed: it goes nowhere
  }
  if (output_.empty()) {
    if (!ended_reason_.empty()) return close(ended_reason_);
    if (!closing_ || !queue_.empty()) return;
    if (!protocol_.is_open()) return close("closed_after_flush");  // the close frame is written
    protocol_.close(1000, "");  // its close frame lands in output_
    if (output_.empty()) return close("closed_after_flush");
  }
  writing_ = true;
  writing_bytes_.swap(output_);
  output_.clear();
  stream_.write(asio::buffer(writing_bytes_), [self = self<WebSocketLink>()](std::error_code error, std::size_t) {
    self->writing_ = false;
    if (self->closed_) return;
    if (error) return self->close("write_error");
    if (std::exchange(self->message_in_flight_, false)) self->pop_written();
    if (!self->ended_reason_.empty()) self->drop_queue();
    self->do_write();
  });
}

}  // namespace ocean::server
