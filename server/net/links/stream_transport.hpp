// StreamTransport: one way a client reaches the server over a TCP socket; the rows are
// kStreamTransports (config/stream_transports.hpp). The Server opens a listener per transport the
// config enables and the hub hands each accepted socket to its transport; the session core sees
// only the link. A new stream transport is its link class and its row in that table.
#pragma once

#include "link.hpp"
#include "listen_address.hpp"
#include "server_config.hpp"
#include "stream_transports.hpp"
#include "transport_context.hpp"

#include <span>

namespace ocean::server {

// kStreamTransports, in listening order; the first is the primary one (always on: --listen, which
// UDP shares).
std::span<const StreamTransport> stream_transports();

// Where `transport` listens, or null when the config leaves it off.
const ListenAddress* listen_address(const StreamTransport& transport, const ServerConfig& config);

}  // namespace ocean::server
