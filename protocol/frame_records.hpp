// Frame records (PROTOCOL.md 7): how version 2 carries frame chunks - a compact block of records,
// the newest tick written once and every record relative to it, sent as a frames datagram on UDP
// (after the server datagram's kind byte) or inside a FrameData message on TCP. Pure bytes in,
// bytes out; decoding checks every length and range before anything reads a payload.
#pragma once

#include "tick.hpp"
#include "wire_reason.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace ocean::protocol {

using Bytes = std::vector<std::uint8_t>;

// One chunk of one frame: the envelope the codec binds its payload to, and the payload.
struct FrameRecord {
  Tick tick = 0;
  Tick baseline = 0;      // == tick for a keyframe; tick - baseline in [1, kMaxFrameLag] for a delta
  bool key = false;
  std::uint16_t index = 0;
  std::uint16_t count = 1;
  std::span<const std::uint8_t> payload;
};

// Server datagrams (version 2) start with one of these; client datagrams are messages as before.
enum class DatagramKind : std::uint8_t { message = 0, frames = 1 };

// The block of `records` (1..kMaxRecordsPerBlock, any ticks; they keep their order).
Bytes encode_frame_block(std::span<const FrameRecord> records);
// kind `frames` + block, and kind `message` + an encoded message.
Bytes frames_datagram(std::span<const FrameRecord> records);
Bytes message_datagram(std::span<const std::uint8_t> message);

struct FrameBlockResult {
  Reason reason = Reason::ok;
  std::string rule;  // what was expected, for logs; empty when ok
  explicit operator bool() const { return reason == Reason::ok; }
};

// Parses a block; on success `out` holds its records in order, their payloads viewing `block`.
// On failure `out` is cleared and nothing of the block may be used.
FrameBlockResult decode_frame_block(std::span<const std::uint8_t> block, std::vector<FrameRecord>& out);

// Bytes a record adds around its payload at most (tick offset, lag, count, index, length).
inline constexpr std::size_t kMaxRecordOverheadBytes = 10 + 5 + 3 + 3 + 5;
inline constexpr std::size_t kMaxRecordsPerBlock = 64;

}  // namespace ocean::protocol
