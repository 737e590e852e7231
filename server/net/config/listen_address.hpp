// ListenAddress: an "ADDR:PORT" the server binds to, parsed strictly (IP literals only, no DNS),
// so a typo fails at startup with a message instead of binding somewhere unexpected.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ocean::server {

struct ListenAddress {
  std::string host;        // an IPv4 or IPv6 literal, without brackets
  std::uint16_t port = 0;  // 0 = any free port (tests)

  std::string to_string() const;  // "[::1]:7700" or "0.0.0.0:7700"
  bool operator==(const ListenAddress&) const = default;
};

// Accepts "1.2.3.4:7700", "[::]:7700" and "*:7700" (= 0.0.0.0). On failure returns nullopt and
// sets `error` to what was wrong (without the option name; the caller adds it).
std::optional<ListenAddress> parse_listen_address(std::string_view text, std::string& error);

}  // namespace ocean::server
