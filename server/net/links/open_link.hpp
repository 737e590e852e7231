// open_link's definition, for the links' own .cpp files: each instantiates it for its class, the one
// its row in kStreamTransports (config/stream_transports.hpp) names, e.g.
//   template std::shared_ptr<StreamLink> open_link<TcpLink>(asio::ip::tcp::socket, const TransportContext&);
// A file that includes this must not see the table (stream_transports.hpp, stream_transport.hpp):
// the rows' initializers would instantiate every row's link there, and need every link class.
// A link's .cpp reads its context from transport_context.hpp.
#pragma once

#include <asio/ip/tcp.hpp>

#include <memory>

namespace ocean::server {

class StreamLink;
struct TransportContext;

template <class Link>
std::shared_ptr<StreamLink> open_link(asio::ip::tcp::socket socket, const TransportContext& context) {
  return Link::open(std::move(socket), context);
}

}  // namespace ocean::server
