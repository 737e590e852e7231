// Every size and range limit of the wire protocol, in one place so the builders, the verifier,
// the framer and PROTOCOL.md agree. Sizes count the whole message including its 4-byte size prefix.
#pragma once

#include <cstddef>
#include <cstdint>

namespace ocean::protocol {

// UDP: one message per datagram, never more than this (fits any path MTU >= 1280 with headers).
inline constexpr std::size_t kMaxDatagram = 1200;

// TCP: the default and the allowed range of Welcome.max_message_bytes.
inline constexpr std::size_t kDefaultMaxMessageBytes = 64 * 1024;
inline constexpr std::size_t kMinMaxMessageBytes = kMaxDatagram;
inline constexpr std::size_t kMaxMaxMessageBytes = 4 * 1024 * 1024;

// 4-byte size prefix + 4-byte root offset + 4-byte identifier: nothing shorter can be a message.
inline constexpr std::size_t kSizePrefixBytes = 4;
inline constexpr std::size_t kMinMessageBytes = 12;

// Bytes a frame record needs besides its payload, in a frames datagram (kind byte, newest tick,
// record header: at most 37) or a FrameData message (FlatBuffers wrapper too: at most 88, tests/protocol
// checks both), so payload <= max message - this always fits.
inline constexpr std::size_t kChunkOverheadBytes = 96;
inline constexpr std::size_t kMaxChunkPayloadUdp = kMaxDatagram - kChunkOverheadBytes;
constexpr std::size_t max_chunk_payload(std::size_t max_message_bytes) {
  return max_message_bytes > kChunkOverheadBytes ? max_message_bytes - kChunkOverheadBytes : 0;
}

// Frame sequencing.
inline constexpr std::uint16_t kMaxChunksPerFrame = 4096;
// Records in one frames datagram from ocean-server: the newest plus up to 7 unacknowledged copies.
inline constexpr std::size_t kMaxBundleChunks = 8;
// tick - baseline of a delta frame, in ticks: the client keeps the frames of the 64 ticks before
// its newest complete one, so a baseline at most this old is one it still holds (PROTOCOL.md
// section 7) - except its newest complete frame (a key that arrived late on a thin link), which it
// keeps however old. 64 ticks (2.1 s at 30 Hz) cover the acks of a 2G link (600+ ms round trip)
// with room for jitter and queueing.
inline constexpr std::uint32_t kMaxBaselineGap = 64;
// The largest tick - baseline a record may carry (the decoder advances that many steps).
inline constexpr std::uint32_t kMaxFrameLag = 1024;

// UdpHello is padded to this size so the server's answer is never larger (no amplification).
inline constexpr std::size_t kUdpHelloMinBytes = 256;

// Vectors and strings.
inline constexpr std::size_t kMinCookieBytes = 8;
inline constexpr std::size_t kMaxCookieBytes = 64;
inline constexpr std::size_t kMaxOfferedProfiles = 16;
// Welcome.vessels (PROTOCOL.md 8): at most this many, each of at most kMaxWaypoints points.
inline constexpr std::size_t kMaxVessels = 32;
inline constexpr std::size_t kMaxWaypoints = 64;
// HeightQuery.points (PROTOCOL.md 8): the answer, 20 bytes a point, fits the default message size.
inline constexpr std::size_t kMaxQueryPoints = 2048;
inline constexpr std::size_t kMaxClientNameBytes = 64;
inline constexpr std::size_t kMaxAdminTokenBytes = 128;
inline constexpr std::size_t kMaxTextBytes = 256;

// Scene ranges: model/scene_params.hpp's (model::kMinSceneSize ...), which the wire checks too.

// Stream and timing ranges.
inline constexpr std::uint16_t kMaxRateHz = 240;
inline constexpr double kMaxTickPeriodS = 10.0;

// FlatBuffers Verifier limits: our deepest message is Message > Welcome > SceneParams.
inline constexpr unsigned kVerifierMaxDepth = 8;
inline constexpr unsigned kVerifierMaxTables = 64;

}  // namespace ocean::protocol
