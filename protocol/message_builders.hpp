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
Bytes encode(const FrameChunk& message);
Bytes encode(const Ack& message);
Bytes encode(const KeyframeRequest& message);
Bytes encode(const SetTransport& message);
Bytes encode(const ParamChange& message);
Bytes encode(const SceneUpdate& message);
Bytes encode(const Error& message);
Bytes encode(const Bye& message);
Bytes encode(const Ping& message);
Bytes encode(const Pong& message);
Bytes encode(const FrameBundle& message);
// A FrameBundle of FrameChunk messages already encoded (each whole, as encode() made it), oldest
// first: the server re-sends the exact chunks it sent before without decoding them to structs.
Bytes encode_bundle(std::span<const std::span<const std::uint8_t>> chunk_messages);
Bytes encode(const AnyMessage& message);

// One frame of opaque bytes cut into FrameChunk messages of at most max_payload bytes each
// (kMaxChunkPayloadUdp for UDP, max_chunk_payload(max_message_bytes) for TCP). A codec that
// makes its own chunks encodes each as a FrameChunk instead. An empty payload gives one empty
// chunk; no chunks at all if it would take more than kMaxChunksPerFrame.
std::vector<Bytes> split_frame(const FrameHeader& header, std::span<const std::uint8_t> payload,
                               std::size_t max_payload);

// True when bytes may be sent as one UDP datagram (size <= kMaxDatagram); check before sending.
bool fits_datagram(std::span<const std::uint8_t> bytes);

}  // namespace ocean::protocol
