// The stream transports, one row each: size-prefixed messages on TCP (--listen), and WebSocket
// binary messages for browsers (--ws-listen; wss with --tls-cert).
#include "stream_transport.hpp"

#include "tcp_link.hpp"
#include "websocket_link.hpp"

namespace ocean::server {
namespace {

const StreamTransport kStreamTransports[] = {
    {"tcp", "clients", [](const ServerConfig& c) -> const ListenAddress* { return &c.listen; },
     [](asio::ip::tcp::socket socket, const TransportContext& context) -> std::shared_ptr<StreamLink> {
       return std::make_shared<TcpLink>(std::move(socket), context.queue_bytes);
     }},
    {"ws", "WebSocket clients",
     [](const ServerConfig& c) -> const ListenAddress* { return c.ws_listen ? &*c.ws_listen : nullptr; },
     [](asio::ip::tcp::socket socket, const TransportContext& context) -> std::shared_ptr<StreamLink> {
       return std::make_shared<WebSocketLink>(std::move(socket), context.queue_bytes,
                                              OriginPolicy{context.config.ws_origins, context.web_port}, context.refused,
                                              context.tls);
     }},
};

}  // namespace

std::span<const StreamTransport> stream_transports() { return kStreamTransports; }

}  // namespace ocean::server
