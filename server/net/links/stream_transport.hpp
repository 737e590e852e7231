// StreamTransport: one way a client reaches the server over a TCP socket - its name (the metrics'
// and logs' transport label), where it listens, and the StreamLink that serves an accepted socket.
// The Server opens a listener per transport the config enables and the hub hands each accepted
// socket to its transport; the session core sees only the link. A new stream transport is its
// link class and its row in stream_transports.cpp.
#pragma once

#include "link.hpp"
#include "listen_address.hpp"
#include "server_config.hpp"

#include <asio/ip/tcp.hpp>
#include <asio/ssl/context.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace ocean::server {

// What a transport may need to open a link, from the server that accepted the socket.
struct TransportContext {
  const ServerConfig& config;
  std::size_t queue_bytes;     // the link's send queue bound
  std::uint16_t web_port = 0;  // the browser viewer's page, 0 when none is served
  std::shared_ptr<asio::ssl::context> tls;  // the browser listeners' TLS (--tls-cert), null in the clear
  // A connection refused before it became a session (a failed handshake): reason, peer.
  std::function<void(const std::string& reason, const std::string& peer)> refused;
};

struct StreamTransport {
  std::string_view name;  // equals the transport() of the links it opens
  std::string_view role;  // for the bind error: "clients", "WebSocket clients"
  // Where it listens, or null when the config leaves it off.
  const ListenAddress* (*address)(const ServerConfig& config);
  std::shared_ptr<StreamLink> (*open)(asio::ip::tcp::socket socket, const TransportContext& context);
};

// In listening order; the first is the primary one (always on: --listen, which UDP shares).
std::span<const StreamTransport> stream_transports();

}  // namespace ocean::server
