// WebSocketLink: one browser's (or any WebSocket client's) connection as a StreamLink. Each binary
// WebSocket message is one protocol message, byte for byte as on TCP (PROTOCOL.md 4.1). The same
// limits as TcpLink (SocketStreamLink: a bounded, paced send queue, one message written at a time,
// a reason for every close) and a size cap on what the client sends. The protocol itself
// (handshake, Origin check, framing) is websocketpp's, behind WebSocketProtocol.
#pragma once

#include "socket_stream_link.hpp"
#include "websocket_protocol.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <optional>
#include <vector>

namespace ocean::server {

struct TransportContext;  // transport_context.hpp

// Which browser pages may connect: a handshake's Origin must be one of these exactly
// ("https://ocean.example:8443"), or anything with "*". A client that sends no Origin header (not
// a browser: a native tool or a test) is always let in, as over plain TCP; one that sends an empty
// Origin only with "*" (browsers always name the page; an empty one hides where it comes from).
// Which pages may open a WebSocket. Besides the allow-list, the server's own page (--web-listen,
// page_port) is let in under whatever name the browser reached this host by: its Origin is
// http(s)://HOST:page_port where HOST is the handshake's own Host header, so another site's page
// (another host, or this host's other ports) is still refused.
struct OriginPolicy {
  std::vector<std::string> allowed;
  std::uint16_t page_port = 0;  // 0: no page is served
  // origin: the Origin header's value, nullopt when the handshake had none.
  bool accepts(const std::optional<std::string>& origin, const std::string& host = "") const;
};

class WebSocketLink final : public SocketStreamLink {
 public:
  static constexpr double kEndGraceS = 1.0;  // to write a 403 or a close frame once the protocol ended

  // on_refused: called once if the handshake is refused or fails ("origin_refused",
  // "handshake_failed"): the connection never became a WebSocket, and no session saw it.
  // tls: the wss listener's context (--tls-cert), null in the clear.
  WebSocketLink(asio::ip::tcp::socket socket, std::size_t max_queue_bytes, OriginPolicy origins,
                std::function<void(const std::string& reason, const std::string& peer)> on_refused = {},
                const std::shared_ptr<asio::ssl::context>& tls = nullptr);
  // Its row's factory (config/stream_transports.hpp): the Origin policy is --ws-origins and the
  // server's own page.
  static std::shared_ptr<StreamLink> open(asio::ip::tcp::socket socket, const TransportContext& context);

  std::string_view transport() const override { return "ws"; }
  void set_max_message_bytes(std::size_t bytes) override { protocol_.set_max_message_bytes(bytes); }

 private:
  WebSocketProtocol::Handlers protocol_handlers();
  void do_read() override;
  void do_write() override;
  void on_refused(const std::string& reason) override {
    if (on_refused_) on_refused_(reason, peer_text_);
  }
  void on_ended(const std::string& reason);

  OriginPolicy origins_;
  std::function<void(const std::string&, const std::string&)> on_refused_;
  WebSocketProtocol protocol_;
  std::array<std::uint8_t, 16 * 1024> read_buffer_{};
  std::vector<char> output_;          // the protocol's bytes not yet handed to the socket
  std::vector<char> writing_bytes_;   // ... and those being written now
  bool message_in_flight_ = false;    // the queue's front is among them
  std::string ended_reason_;          // the protocol ended: close once its last bytes are written
};

}  // namespace ocean::server
