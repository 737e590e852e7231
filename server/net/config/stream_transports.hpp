// The stream transports, one row each: the one place a transport is registered. A row names the
// transport (the metrics' and logs' label), its listen option and the link class that serves an
// accepted socket. The configuration reads the rows for the listen options (--ws-listen: flag,
// config key, --help, --help-json); the Server opens a listener per enabled row, SessionHub opens
// its links, the session core seeds its ocean_clients gauge. A new stream transport is its link,
// links/<name>_link.hpp/.cpp, and its row here.
//
// The rows live in the config room because ocean_server_config reads them, and that library must
// not reference link code (its fuzzer links it alone): the config layer copies the rows' text at
// compile time (stream_listen_options.cpp) and never touches `open` at run time; only the links room
// (links/stream_transports.cpp) reads the whole table.
#pragma once

#include <asio/ip/tcp.hpp>

#include <memory>
#include <string_view>

namespace ocean::server {

class StreamLink;
struct TransportContext;  // links/stream_transport.hpp

// How an accepted socket becomes a Link: Link::open. Only declared here, so that a row can name a
// link class the table need not see; defined in links/open_link.hpp, and instantiated by the
// link's own .cpp for its class.
template <class Link>
std::shared_ptr<StreamLink> open_link(asio::ip::tcp::socket socket, const TransportContext& context);

struct StreamTransport {
  std::string_view name;  // equals the transport() of the links it opens; keys ServerConfig::stream_listen
  std::string_view role;  // for the bind error: "clients", "WebSocket clients"
  // Its listen option, ADDR:PORT|off and off by default, and that option's help. Empty for the
  // primary transport, whose --listen (which UDP shares) is an ordinary row of kOptions.
  std::string_view option;
  std::string_view help;
  std::shared_ptr<StreamLink> (*open)(asio::ip::tcp::socket socket, const TransportContext& context);
};

// In listening order; the first is the primary one (always on). `class X` in open_link<class X>
// declares the link class, so a row needs no line of its own elsewhere in this file.
inline constexpr StreamTransport kStreamTransports[] = {
    {"tcp", "clients", {}, {}, open_link<class TcpLink>},
    {"ws", "WebSocket clients", "ws-listen",
     "WebSocket address for browser clients (binary messages, no UDP); 'off' (default) disables it",
     open_link<class WebSocketLink>},
};

}  // namespace ocean::server
