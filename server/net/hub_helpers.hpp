// Small helpers the SessionHub's translation units share (session_hub.cpp, hub_datagrams.cpp,
// hub_ticks.cpp): wall-clock milliseconds, endpoint text for logs, the cookie's endpoint, and
// the session id a client message names.
#pragma once

#include <asio/ip/udp.hpp>

#include "ocean_generated.h"

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

// The session a client message names (UdpHello, Ack, KeyframeRequest, Ping); 0 for other types.
inline std::uint64_t named_session(const wire::Message& message) {
  switch (message.body_type()) {
    case wire::Body::UdpHello: return message.body_as_UdpHello()->session_id();
    case wire::Body::Ack: return message.body_as_Ack()->session_id();
    case wire::Body::KeyframeRequest: return message.body_as_KeyframeRequest()->session_id();
    case wire::Body::Ping: return message.body_as_Ping()->session_id();
    default: return 0;
  }
}

}  // namespace ocean::server::hub
