#include "listen_address.hpp"

#include "quoted.hpp"

#include <asio/ip/address.hpp>

#include <charconv>

namespace ocean::server {

std::string ListenAddress::to_string() const {
  const bool v6 = host.find(':') != std::string::npos;
  return (v6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

std::optional<ListenAddress> parse_listen_address(std::string_view text, std::string& error) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string_view::npos || colon + 1 == text.size()) {
    error = quoted(text) + " is not ADDR:PORT (e.g. 0.0.0.0:7700 or [::]:7700)";
    return std::nullopt;
  }
  std::string_view host = text.substr(0, colon);
  const std::string_view port_text = text.substr(colon + 1);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
  if (host == "*") host = "0.0.0.0";

  unsigned long port = 0;
  const auto [end, ec] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (ec != std::errc() || end != port_text.data() + port_text.size() || port > 65535) {
    error = "port '" + std::string(port_text) + "' in '" + std::string(text) +
            "' must be an integer in 0..65535 (0 = any free port)";
    return std::nullopt;
  }
  std::error_code address_error;
  const asio::ip::address address = asio::ip::make_address(std::string(host), address_error);
  if (address_error) {
    error = "address '" + std::string(host) + "' in '" + std::string(text) +
            "' is not an IPv4 or IPv6 literal (host names are not resolved)";
    return std::nullopt;
  }
  return ListenAddress{address.to_string(), static_cast<std::uint16_t>(port)};
}

}  // namespace ocean::server
