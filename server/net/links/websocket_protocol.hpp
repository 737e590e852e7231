// WebSocketProtocol: RFC 6455 for one server-side connection, bytes in and bytes out: the opening
// handshake (with the Origin check), framing, unmasking, Ping/Pong and the closing handshake,
// done by websocketpp on its iostream transport. It owns no socket: WebSocketLink feeds it what
// it reads and writes what it emits. Its interface is plain C++17 because websocketpp 0.8.2 (the
// Debian 12 package) does not compile as C++20, so websocket_protocol.cpp alone is built as C++17.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace ocean::server {

class WebSocketProtocol {
 public:
  struct Handlers {
    // The handshake's Origin header (nullopt when it sent none, "" when it sent an empty one) and
    // Host header ("" when none): false refuses it with 403.
    std::function<bool(const std::optional<std::string>& origin, const std::string& host)> accept_origin;
    // One whole binary message.
    std::function<void(const std::uint8_t* data, std::size_t size)> on_message;
    // Bytes to write to the socket, in order.
    std::function<void(const char* data, std::size_t size)> on_output;
    // The connection will carry nothing more: "origin_refused", "handshake_failed",
    // "oversized" (a message beyond the limit), "malformed" (bad framing, a text message),
    // "peer_closed" (the client's close frame). Called once; what on_output got before it
    // (a 403, a close frame) should still be written.
    std::function<void(const std::string& reason)> on_ended;
  };

  WebSocketProtocol(Handlers handlers, std::size_t max_message_bytes);
  ~WebSocketProtocol();
  WebSocketProtocol(const WebSocketProtocol&) = delete;
  WebSocketProtocol& operator=(const WebSocketProtocol&) = delete;

  void feed(const std::uint8_t* data, std::size_t size);  // bytes read from the socket
  // One binary message; false unless the handshake is done and the connection not closing.
  bool send(const std::uint8_t* data, std::size_t size);
  void set_max_message_bytes(std::size_t bytes);
  // Starts the closing handshake (a close frame with this code and reason).
  void close(std::uint16_t code, const std::string& reason);
  bool is_open() const;  // handshake done, not closing

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ocean::server
