// TransportContext: what a stream transport may need to open a link, from the server that accepted
// the socket. Apart from the transports' table (stream_transport.hpp) so that a link's .cpp can read
// it beside open_link.hpp without seeing the table.
#pragma once

#include "server_config.hpp"

#include <asio/ssl/context.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace ocean::server {

struct TransportContext {
  const ServerConfig& config;
  std::size_t queue_bytes;     // the link's send queue bound
  std::uint16_t web_port = 0;  // the browser viewer's page, 0 when none is served
  std::shared_ptr<asio::ssl::context> tls;  // the browser listeners' TLS (--tls-cert), null in the clear
  // A connection refused before it became a session (a failed handshake): reason, peer.
  std::function<void(const std::string& reason, const std::string& peer)> refused;
};

}  // namespace ocean::server
