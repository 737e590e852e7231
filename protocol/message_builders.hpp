// encode(): one message value -> the bytes to send (size-prefixed FlatBuffer, identical on TCP
// and UDP), so nobody hand-rolls FlatBuffers. Encoding does not check meaning: the receiver's
// verify_message() does; tests/protocol proves every encoded valid value passes it.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "message_types.hpp"

namespace ocean::protocol {

Bytes encode(const Hello& message);
Bytes encode(const Welcome& message);
Bytes encode(const UdpHello& message);  // padded to kUdpHelloMinBytes
Bytes encode(const UdpReady& message);
Bytes encode(const Ack& message);
Bytes encode(const KeyframeRequest& message);
Bytes encode(const SetTransport& message);
Bytes encode(const ParamChange& message);
Bytes encode(const SceneUpdate& message);
Bytes encode(const Error& message);
Bytes encode(const Bye& message);
Bytes encode(const Ping& message);
Bytes encode(const Pong& message);
Bytes encode(const HeightQuery& message);
Bytes encode(const HeightAnswer& message);
Bytes encode(const FrameData& message);  // frames: a block of frame_records.hpp
Bytes encode(const AnyMessage& message);

// True when bytes may be sent as one UDP datagram (size <= kMaxDatagram); check before sending.
bool fits_datagram(std::span<const std::uint8_t> bytes);

}  // namespace ocean::protocol
