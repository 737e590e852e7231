// Chunk wire format: the envelope fields every chunk travels with (PROTOCOL.md's frame record),
// the payload header this codec writes inside the record's payload, its CRC, and the reasons a
// chunk is refused.
#pragma once

#include "tick.hpp"

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace ocean::codec {

inline constexpr std::uint8_t kCodecVersion = 7;
inline constexpr std::size_t kDefaultMaxPayload = 1100;
// Bytes a frame record adds around the payload in a lean UDP datagram (PROTOCOL.md 7): lag,
// count, length and its share of the datagram's kind byte and tick; the bench charges this per
// chunk, plus kIpUdpHeaderBytes per datagram.
inline constexpr std::size_t kEnvelopeOverheadBytes = 9;
inline constexpr std::size_t kIpUdpHeaderBytes = 28;

// One datagram's worth of a frame: the envelope of a frame record plus the codec payload.
struct Chunk {
  Tick tick = 0;
  Tick baseline = 0;           // tick of the acknowledged frame this one is predicted from; = tick for keys
  bool key = false;
  std::uint16_t index = 0;     // 0 .. count-1
  std::uint16_t count = 0;     // chunks in this frame
  std::vector<std::uint8_t> payload;
};

struct ChunkView {
  Tick tick = 0;
  Tick baseline = 0;
  bool key = false;
  std::uint16_t index = 0;
  std::uint16_t count = 0;
  std::span<const std::uint8_t> payload;
};
inline ChunkView view(const Chunk& c) { return {c.tick, c.baseline, c.key, c.index, c.count, c.payload}; }

// Why a chunk was refused; the decoder's state is unchanged whenever this is not `ok`.
enum class ChunkError : std::uint8_t {
  ok = 0,
  truncated,           // payload shorter than its header
  oversized,           // payload longer than max_payload
  unknown_version,     // flag bit 5 clear: a chunk of codec version 2 or 3 (CODEC.md 9)
  bad_flags,           // reserved flag bits set, or key flag differs from the envelope
  wrong_dimensions,    // grid or channel set differs from the stream configuration
  bad_range,           // item range empty or outside the frame
  checksum_mismatch,   // CRC-16 over envelope + payload does not match
  bad_index,           // count == 0, count > kMaxChunksPerFrame or index >= count
  bad_value,           // body does not decode: overlong integer, position or magnitude out of range
  bad_baseline,        // key chunk with baseline != tick, or delta with baseline >= tick
  lag_too_large,       // tick - baseline above the decoder's max_lag
  unknown_baseline,    // baseline is not a complete frame the decoder holds
  stale_tick,          // tick not newer than the oldest frame the decoder still keeps
  inconsistent_frame,  // baseline / key / count differ from earlier chunks of the same tick
  duplicate_chunk,     // this index of this tick was already accepted
  overlapping_range,   // item range overlaps a chunk already accepted for this tick
  coverage_mismatch,   // all chunks present but their ranges do not cover the frame exactly
  unknown_scene,       // the chunk's scene tag is not the scene the decoder knows for its tick
};
std::string_view to_string(ChunkError e);

inline constexpr std::uint16_t kMaxChunksPerFrame = 4096;

// Parsed payload header (CODEC.md 5).
struct ChunkHeader {
  bool key = false;
  bool normals = false;
  bool choppy = false;         // codec version 3: the choppy channels follow the slopes
  bool cascaded = false;       // codec version 5: the stream has cascades (StreamConfig::cascades)
  bool wake = false;           // codec version 6: the stream has a wake lattice (StreamConfig::wake)
  bool modeled = false;        // key only: the state comes from the scene model, not coefficients
  bool whole = false;          // the chunk covers every item of its frame; no range is written
  std::uint8_t scene_tag = 0;  // the scene in force at the chunk's tick (SceneUpdate.serial mod 256)
  std::uint32_t item_begin = 0;
  std::uint32_t item_end = 0;
  std::uint8_t pos_shift = 0;  // explicit key only: X(t) = coefficient << pos_shift
  std::uint8_t vel_shift = 0;  // explicit key only: X(t) - X(t-1) = coefficient << vel_shift
};

// header || body with the CRC filled in; grid_log2 is bound by the CRC, not written.
std::vector<std::uint8_t> write_payload(const ChunkHeader& h, const ChunkView& envelope_fields, int grid_log2,
                                        std::span<const std::uint8_t> body);

// Checks the header, lengths and CRC (not the meaning against a stream); on success `body`
// views the body inside payload. A `whole` header leaves the item range for the caller to set.
ChunkError parse_payload(const ChunkView& chunk, std::size_t max_payload, int grid_log2, ChunkHeader& h,
                         std::span<const std::uint8_t>& body);

std::uint16_t crc16_ccitt(std::uint16_t crc, std::span<const std::uint8_t> bytes);

}  // namespace ocean::codec
