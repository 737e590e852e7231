// Small helpers the SessionCore's translation units share (session_core.cpp, core_datagrams.cpp,
// core_ticks.cpp): the cookie's endpoint and the session id a client message names.
#pragma once

#include <asio/ip/udp.hpp>

#include "ocean_generated.h"

#include <cstdint>

namespace ocean::server::core {

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

}  // namespace ocean::server::core
