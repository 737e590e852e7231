// Chunk body: the range-coded contents of one chunk's item range - key spectral coefficients
// and sparse spatial corrections, channel by channel (common/channels.hpp). Each body decodes on
// its own.
#pragma once

#include "common/channels.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace ocean::codec {

struct Correction {
  std::uint32_t pos;    // sample index z * n + x
  std::int32_t value;   // in quanta (step / 4 or slope_step / 4), never 0
};

// A frame's corrections, one list per channel of common/channels.hpp (in coding order), each
// sorted by pos: heights and displacement in step / 4 quanta, slopes and the displacement's
// derivatives in slope_step / 4. A channel the stream does not carry has none.
struct Corrections : PerChannel<std::vector<Correction>> {
  std::size_t total() const {
    std::size_t sum = 0;
    for (const auto& list : by_index) sum += list.size();
    return sum;
  }
};

inline constexpr int kCorrectionChannels = kChannelCount;

// One key mode: X(t) and X(t) - X(t-1), each a quantized complex coefficient.
struct KeyCoefficient {
  std::int64_t xr = 0, xi = 0, vr = 0, vi = 0;
};

// Items of a frame: keys number their spectral modes first, then every frame numbers samples.
struct BodyLayout {
  std::uint32_t spectral_items = 0;  // key_modes().size() for keys, 0 for deltas
  std::uint32_t samples = 0;         // n * n
  bool normals = false;
  bool choppy = false;
  std::uint32_t total() const { return spectral_items + samples; }
};

inline constexpr std::int32_t kMaxCorrection = 1 << 24;  // |value| limit in quanta

struct BodyCost {
  double key_bits = 0, height_bits = 0, slope_bits = 0, choppy_bits = 0;  // ideal coder cost, statistics only
};

std::vector<std::uint8_t> encode_body(const BodyLayout& layout, std::uint32_t begin, std::uint32_t end,
                                      std::span<const KeyCoefficient> key, const Corrections& corrections,
                                      BodyCost* cost = nullptr);

struct DecodedBody {
  std::vector<KeyCoefficient> key;  // for items [begin, min(end, spectral_items))
  Corrections corrections;
};

// false when the body cannot come from encode_body for this layout and range.
bool decode_body(const BodyLayout& layout, std::uint32_t begin, std::uint32_t end,
                 std::span<const std::uint8_t> body, DecodedBody& out);

}  // namespace ocean::codec
