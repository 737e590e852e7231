// Small helpers the SessionHub's translation units share (session_hub.cpp, hub_datagrams.cpp,
// hub_ticks.cpp): wall-clock milliseconds, endpoint text for logs, the cookie's endpoint.
#pragma once

#include <asio/ip/udp.hpp>

#include <chrono>
#include <cstdint>
#include <string>

namespace ocean::server::hub {

inline std::int64_t unix_ms_now() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

inline std::string endpoint_text(const auto& endpoint) {
  std::string text = endpoint.address().to_string();
  text += ':';
  text += std::to_string(endpoint.port());
  return text;
}

// The cookie binds the client's IP only: its UDP port is not known when the Welcome is sent.
inline asio::ip::udp::endpoint cookie_endpoint(const asio::ip::address& address) { return {address, 0}; }

}  // namespace ocean::server::hub
