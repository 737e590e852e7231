// Payload header layout, varints and CRC-16/CCITT-FALSE (CODEC.md 5).
#include "chunk_format.hpp"

namespace ocean::codec {
namespace {

constexpr std::uint8_t kFlagKey = 1u << 0;
constexpr std::uint8_t kFlagNormals = 1u << 1;
constexpr std::size_t kCrcOffset = 3;

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

std::uint16_t chunk_crc(const ChunkView& e, std::span<const std::uint8_t> payload) {
  std::uint8_t pseudo[13];
  for (int i = 0; i < 4; ++i) pseudo[i] = static_cast<std::uint8_t>(e.tick >> (8 * i));
  for (int i = 0; i < 4; ++i) pseudo[4 + i] = static_cast<std::uint8_t>(e.baseline >> (8 * i));
  pseudo[8] = e.key ? 1 : 0;
  pseudo[9] = static_cast<std::uint8_t>(e.index);
  pseudo[10] = static_cast<std::uint8_t>(e.index >> 8);
  pseudo[11] = static_cast<std::uint8_t>(e.count);
  pseudo[12] = static_cast<std::uint8_t>(e.count >> 8);
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

std::vector<std::uint8_t> write_payload(const ChunkHeader& h, const ChunkView& e, std::span<const std::uint8_t> body) {
  std::vector<std::uint8_t> out;
  out.reserve(16 + body.size());
  out.push_back(h.version);
  out.push_back(static_cast<std::uint8_t>((h.key ? kFlagKey : 0) | (h.normals ? kFlagNormals : 0)));
  out.push_back(h.grid_log2);
  out.push_back(0);
  out.push_back(0);  // CRC placeholder
  put_varint(out, h.item_begin);
  put_varint(out, h.item_end);
  if (h.key) {
    out.push_back(h.pos_shift);
    out.push_back(h.vel_shift);
  }
  put_varint(out, static_cast<std::uint32_t>(body.size()));
  out.insert(out.end(), body.begin(), body.end());
  const std::uint16_t crc = chunk_crc(e, out);
  out[kCrcOffset] = static_cast<std::uint8_t>(crc);
  out[kCrcOffset + 1] = static_cast<std::uint8_t>(crc >> 8);
  return out;
}

ChunkError parse_payload(const ChunkView& c, std::size_t max_payload, ChunkHeader& h,
                         std::span<const std::uint8_t>& body) {
  const auto p = c.payload;
  if (p.size() > max_payload) return ChunkError::oversized;
  if (p.empty()) return ChunkError::truncated;
  if (p[0] != kCodecVersion) return ChunkError::unknown_version;
  if (p.size() < kCrcOffset + 2) return ChunkError::truncated;
  h.version = p[0];
  if (p[1] & ~(kFlagKey | kFlagNormals)) return ChunkError::bad_flags;
  h.key = (p[1] & kFlagKey) != 0;
  h.normals = (p[1] & kFlagNormals) != 0;
  if (h.key != c.key) return ChunkError::bad_flags;
  h.grid_log2 = p[2];
  std::size_t pos = kCrcOffset + 2;
  bool truncated = false;
  std::uint32_t body_len = 0;
  if (!get_varint(p, pos, h.item_begin, truncated) || !get_varint(p, pos, h.item_end, truncated))
    return truncated ? ChunkError::truncated : ChunkError::bad_range;
  if (h.key) {
    if (pos + 2 > p.size()) return ChunkError::truncated;
    h.pos_shift = p[pos++];
    h.vel_shift = p[pos++];
  }
  if (!get_varint(p, pos, body_len, truncated)) return truncated ? ChunkError::truncated : ChunkError::oversized;
  if (body_len > p.size() - pos) return ChunkError::truncated;
  if (body_len < p.size() - pos) return ChunkError::oversized;
  const std::uint16_t crc = static_cast<std::uint16_t>(p[kCrcOffset] | (p[kCrcOffset + 1] << 8));
  if (crc != chunk_crc(c, p)) return ChunkError::checksum_mismatch;
  body = p.subspan(pos, body_len);
  return ChunkError::ok;
}

}  // namespace ocean::codec
