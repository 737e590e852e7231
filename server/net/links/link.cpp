#include "link.hpp"

#include <chrono>

namespace ocean::server {

Instant now_instant() {
  using namespace std::chrono;
  return Instant{duration<double>(steady_clock::now().time_since_epoch()).count(),
                 duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count()};
}

std::string endpoint_text(const asio::ip::address& address, std::uint16_t port) {
  std::string text = address.to_string();
  text += ':';
  text += std::to_string(port);
  return text;
}

std::string endpoint_text(const asio::ip::udp::endpoint& endpoint) {
  return endpoint_text(endpoint.address(), endpoint.port());
}

UdpLink::UdpLink(DatagramSocket& socket, const asio::ip::udp::endpoint& to)
    : socket_(&socket), to_(to), peer_(endpoint_text(to)) {}

}  // namespace ocean::server
