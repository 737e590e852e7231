// Payload header layout, varints and CRC-16/CCITT-FALSE (CODEC.md 5).
#include "chunk_format.hpp"

namespace ocean::codec {
namespace {

constexpr std::uint8_t kFlagKey = 1u << 0;
constexpr std::uint8_t kFlagNormals = 1u << 1;
constexpr std::uint8_t kFlagModeled = 1u << 2;
constexpr std::uint8_t kFlagWhole = 1u << 3;
constexpr std::uint8_t kFlagChoppy = 1u << 4;  // codec version 3
// Codec version 4 synthesizes in binary32 (CODEC.md 7.2), so its predictions differ from version
// 3's in the last bits: every chunk says so, and a version 3 decoder refuses it (bad_flags) rather
// than decode it against the wrong prediction.
constexpr std::uint8_t kFlagBinary32 = 1u << 5;
// Codec version 5: the stream has cascades (several lattices); decoders of version 4 refuse it
// as a reserved bit, so they show nothing rather than one lattice's samples as the sea.
constexpr std::uint8_t kFlagCascaded = 1u << 6;
// Codec version 6: the stream has a wake lattice (its items follow the sea's); a version 5 decoder
// refuses the reserved bit rather than show the wake's samples as the sea's.
constexpr std::uint8_t kFlagWake = 1u << 7;
constexpr std::uint8_t kKnownFlags =
    kFlagKey | kFlagNormals | kFlagModeled | kFlagWhole | kFlagChoppy | kFlagBinary32 | kFlagCascaded | kFlagWake;
constexpr std::size_t kCrcOffset = 1;
constexpr std::size_t kFixedHeaderBytes = 4;  // flags, CRC (2), scene tag

void put_varint(std::vector<std::uint8_t>& out, std::uint32_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<std::uint8_t>(v | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<std::uint8_t>(v));
}

// false if the bytes end first or the value needs more than 32 bits / 5 bytes.
bool get_varint(std::span<const std::uint8_t> in, std::size_t& pos, std::uint32_t& v, bool& truncated) {
  std::uint64_t acc = 0;
  for (int i = 0; i < 5; ++i) {
    if (pos >= in.size()) {
      truncated = true;
      return false;
    }
    const std::uint8_t b = in[pos++];
    acc |= static_cast<std::uint64_t>(b & 0x7F) << (7 * i);
    if ((b & 0x80) == 0) {
      if (acc > 0xFFFFFFFFull) return false;
      v = static_cast<std::uint32_t>(acc);
      return true;
    }
  }
  return false;
}

// The pseudo header binds a payload to its envelope and to the stream's grid, so a chunk moved to
// another tick, baseline, index or stream fails the CRC before anything is decoded.
std::uint16_t chunk_crc(const ChunkView& e, int grid_log2, std::span<const std::uint8_t> payload) {
  std::uint8_t pseudo[22];
  for (int i = 0; i < 8; ++i) pseudo[i] = static_cast<std::uint8_t>(e.tick >> (8 * i));
  for (int i = 0; i < 8; ++i) pseudo[8 + i] = static_cast<std::uint8_t>(e.baseline >> (8 * i));
  pseudo[16] = e.key ? 1 : 0;
  pseudo[17] = static_cast<std::uint8_t>(e.index);
  pseudo[18] = static_cast<std::uint8_t>(e.index >> 8);
  pseudo[19] = static_cast<std::uint8_t>(e.count);
  pseudo[20] = static_cast<std::uint8_t>(e.count >> 8);
  pseudo[21] = static_cast<std::uint8_t>(grid_log2);
  std::uint16_t crc = crc16_ccitt(0xFFFF, pseudo);
  crc = crc16_ccitt(crc, payload.subspan(0, kCrcOffset));
  return crc16_ccitt(crc, payload.subspan(kCrcOffset + 2));
}

}  // namespace

std::string_view to_string(ChunkError e) {
  switch (e) {
    case ChunkError::ok: return "ok";
    case ChunkError::truncated: return "truncated";
    case ChunkError::oversized: return "oversized";
    case ChunkError::unknown_version: return "unknown_version";
    case ChunkError::bad_flags: return "bad_flags";
    case ChunkError::wrong_dimensions: return "wrong_dimensions";
    case ChunkError::bad_range: return "bad_range";
    case ChunkError::checksum_mismatch: return "checksum_mismatch";
    case ChunkError::bad_index: return "bad_index";
    case ChunkError::bad_value: return "bad_value";
    case ChunkError::bad_baseline: return "bad_baseline";
    case ChunkError::lag_too_large: return "lag_too_large";
    case ChunkError::unknown_baseline: return "unknown_baseline";
    case ChunkError::stale_tick: return "stale_tick";
    case ChunkError::inconsistent_frame: return "inconsistent_frame";
    case ChunkError::duplicate_chunk: return "duplicate_chunk";
    case ChunkError::overlapping_range: return "overlapping_range";
    case ChunkError::coverage_mismatch: return "coverage_mismatch";
    case ChunkError::unknown_scene: return "unknown_scene";
  }
  return "unknown";
}

std::uint16_t crc16_ccitt(std::uint16_t crc, std::span<const std::uint8_t> bytes) {
  for (std::uint8_t b : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ (static_cast<std::uint16_t>(b) << 8));
    for (int i = 0; i < 8; ++i)
      crc = static_cast<std::uint16_t>((crc & 0x8000) ? (crc << 1) ^ 0x1021 : crc << 1);
  }
  return crc;
}

std::vector<std::uint8_t> write_payload(const ChunkHeader& h, const ChunkView& e, int grid_log2,
                                        std::span<const std::uint8_t> body) {
  std::vector<std::uint8_t> out;
  out.reserve(16 + body.size());
  const bool explicit_key = h.key && !h.modeled;
  out.push_back(static_cast<std::uint8_t>((h.key ? kFlagKey : 0) | (h.normals ? kFlagNormals : 0) |
                                          (h.key && h.modeled ? kFlagModeled : 0) | (h.whole ? kFlagWhole : 0) |
                                          (h.choppy ? kFlagChoppy : 0) | (h.cascaded ? kFlagCascaded : 0) |
                                          (h.wake ? kFlagWake : 0) |
                                          kFlagBinary32));
  out.push_back(0);
  out.push_back(0);  // CRC placeholder
  out.push_back(h.scene_tag);
  if (!h.whole) {
    put_varint(out, h.item_begin);
    put_varint(out, h.item_end);
  }
  if (explicit_key) {
    out.push_back(h.pos_shift);
    out.push_back(h.vel_shift);
  }
  out.insert(out.end(), body.begin(), body.end());
  const std::uint16_t crc = chunk_crc(e, grid_log2, out);
  out[kCrcOffset] = static_cast<std::uint8_t>(crc);
  out[kCrcOffset + 1] = static_cast<std::uint8_t>(crc >> 8);
  return out;
}

ChunkError parse_payload(const ChunkView& c, std::size_t max_payload, int grid_log2, ChunkHeader& h,
                         std::span<const std::uint8_t>& body) {
  const auto p = c.payload;
  if (p.size() > max_payload) return ChunkError::oversized;
  if (p.size() < kFixedHeaderBytes) return ChunkError::truncated;
  const std::uint8_t flags = p[0];
  if (flags & ~kKnownFlags) return ChunkError::bad_flags;
  if (!(flags & kFlagBinary32)) return ChunkError::unknown_version;  // a version 2 or 3 chunk
  h.key = (flags & kFlagKey) != 0;
  h.normals = (flags & kFlagNormals) != 0;
  h.modeled = (flags & kFlagModeled) != 0;
  h.whole = (flags & kFlagWhole) != 0;
  h.choppy = (flags & kFlagChoppy) != 0;
  h.cascaded = (flags & kFlagCascaded) != 0;
  h.wake = (flags & kFlagWake) != 0;
  if (h.key != c.key || (h.modeled && !h.key)) return ChunkError::bad_flags;
  h.scene_tag = p[3];
  std::size_t pos = kFixedHeaderBytes;
  bool truncated = false;
  if (!h.whole) {
    if (!get_varint(p, pos, h.item_begin, truncated) || !get_varint(p, pos, h.item_end, truncated))
      return truncated ? ChunkError::truncated : ChunkError::bad_range;
  }
  if (h.key && !h.modeled) {
    if (pos + 2 > p.size()) return ChunkError::truncated;
    h.pos_shift = p[pos++];
    h.vel_shift = p[pos++];
  }
  const std::uint16_t crc = static_cast<std::uint16_t>(p[kCrcOffset] | (p[kCrcOffset + 1] << 8));
  if (crc != chunk_crc(c, grid_log2, p)) return ChunkError::checksum_mismatch;
  body = p.subspan(pos);
  return ChunkError::ok;
}

}  // namespace ocean::codec
