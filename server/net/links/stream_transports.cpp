// The stream transports' table as the server reads it at run time: the links room is the one that
// may reference the rows' factories, which the links' own .cpp files define (open_link.hpp).
#include "stream_transport.hpp"

namespace ocean::server {

std::span<const StreamTransport> stream_transports() { return kStreamTransports; }

const ListenAddress* listen_address(const StreamTransport& transport, const ServerConfig& config) {
  if (transport.option.empty()) return &config.listen;  // the primary: --listen, an ordinary option
  return config.stream_address(transport.name);
}

}  // namespace ocean::server
