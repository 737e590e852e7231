// Built as C++17 (CMakeLists.txt): websocketpp 0.8.2 declares constructors as template-ids,
// which C++20 refuses.
#include "websocket_protocol.hpp"

#include <websocketpp/config/core.hpp>
#include <websocketpp/server.hpp>

namespace ocean::server {

namespace {

using Endpoint = websocketpp::server<websocketpp::config::core>;
namespace close_code = websocketpp::close::status;

}  // namespace

struct WebSocketProtocol::Impl {
  Handlers handlers;
  Endpoint endpoint;
  Endpoint::connection_ptr connection;
  bool ended = false;
  bool closing_by_us = false;

  // Why the connection closes, from the close frame websocketpp sent itself (or the client's).
  void end_by_code() {
    switch (connection->get_local_close_code()) {
      case close_code::message_too_big: return end("oversized");
      case close_code::protocol_error:
      case close_code::invalid_payload:
      case close_code::unsupported_data: return end("malformed");
      default: return end(closing_by_us ? "closed" : "peer_closed");
    }
  }

  // A close the client started: websocketpp's answer echoes the client's code, which is then no
  // verdict on the client's input.
  bool client_closed() const { return connection->get_remote_close_code() != close_code::abnormal_close; }

  void end(const std::string& reason) {
    if (ended) return;
    ended = true;
    if (handlers.on_ended) handlers.on_ended(reason);
  }
};

WebSocketProtocol::WebSocketProtocol(Handlers handlers, std::size_t max_message_bytes) : impl_(std::make_unique<Impl>()) {
  Impl& impl = *impl_;
  impl.handlers = std::move(handlers);
  impl.endpoint.clear_access_channels(websocketpp::log::alevel::all);
  impl.endpoint.clear_error_channels(websocketpp::log::elevel::all);
  impl.connection = impl.endpoint.get_connection();
  Endpoint::connection_ptr& con = impl.connection;
  Impl* self = impl_.get();
  con->set_max_message_size(max_message_bytes);
  // An upgrade request has no body: without this, websocketpp buffers a Content-Length of up to
  // 32 MB per handshake.
  con->set_max_http_body_size(0);
  con->set_write_handler([self](websocketpp::connection_hdl, const char* data, std::size_t size) {
    if (self->handlers.on_output) self->handlers.on_output(data, size);
    return websocketpp::lib::error_code();
  });
  con->set_validate_handler([self](websocketpp::connection_hdl) {
    const auto& headers = self->connection->get_request().get_headers();
    const bool has_origin = headers.find("Origin") != headers.end();  // the map ignores case
    const std::optional<std::string> origin = has_origin ? std::optional<std::string>(self->connection->get_origin()) : std::nullopt;
    if (self->handlers.accept_origin && self->handlers.accept_origin(origin, self->connection->get_request_header("Host")))
      return true;
    self->connection->set_status(websocketpp::http::status_code::forbidden);
    self->end("origin_refused");
    return false;
  });
  con->set_message_handler([self](websocketpp::connection_hdl, Endpoint::message_ptr message) {
    if (self->ended) return;
    if (message->get_opcode() != websocketpp::frame::opcode::binary) {
      websocketpp::lib::error_code ignored;
      self->connection->close(close_code::unsupported_data, "text messages are not part of the protocol", ignored);
      return self->end("malformed");
    }
    const std::string& payload = message->get_payload();
    if (self->handlers.on_message)
      self->handlers.on_message(reinterpret_cast<const std::uint8_t*>(payload.data()), payload.size());
  });
  con->set_fail_handler([self](websocketpp::connection_hdl) { self->end("handshake_failed"); });
  con->set_close_handler([self](websocketpp::connection_hdl) {
    if (self->client_closed() && !self->closing_by_us) return self->end("peer_closed");
    self->end_by_code();
  });
  con->start();
}

WebSocketProtocol::~WebSocketProtocol() {
  // The connection's handlers point here: no callback may reach the link while it goes away.
  if (impl_ && impl_->connection) {
    impl_->ended = true;
    impl_->handlers = Handlers{};
    // Its pending read holds a shared_ptr to the connection itself (iostream transport): ending
    // the read ends the connection, or a client that left mid-handshake would leak it.
    impl_->connection->eof();
  }
}

void WebSocketProtocol::feed(const std::uint8_t* data, std::size_t size) {
  std::size_t done = 0;
  while (done < size && !impl_->ended) {
    const std::size_t used = impl_->connection->read_some(reinterpret_cast<const char*>(data) + done, size - done);
    if (used == 0) break;
    done += used;
    // Bad input (an oversized or malformed frame) normally ends the connection inside read_some
    // (websocketpp sends its close frame and terminates); should it ever wait for the client's
    // close frame instead, a hostile client never sends one, so the link ends now.
    if (!impl_->ended && !impl_->closing_by_us &&
        impl_->connection->get_state() == websocketpp::session::state::closing)
      impl_->end_by_code();
  }
}

bool WebSocketProtocol::send(const std::uint8_t* data, std::size_t size) {
  if (!is_open()) return false;
  return !impl_->connection->send(data, size, websocketpp::frame::opcode::binary);
}

void WebSocketProtocol::set_max_message_bytes(std::size_t bytes) { impl_->connection->set_max_message_size(bytes); }

void WebSocketProtocol::close(std::uint16_t code, const std::string& reason) {
  if (impl_->connection->get_state() != websocketpp::session::state::open) return;
  impl_->closing_by_us = true;
  websocketpp::lib::error_code ignored;
  impl_->connection->close(code, reason, ignored);
}

bool WebSocketProtocol::is_open() const {
  return !impl_->ended && impl_->connection->get_state() == websocketpp::session::state::open;
}

}  // namespace ocean::server
