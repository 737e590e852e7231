// Chunk body: the range-coded contents of one chunk's item range - key spectral coefficients
// and sparse spatial corrections (height, slope_x, slope_z). Each body decodes on its own.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace ocean::codec {

struct Correction {
  std::uint32_t pos;    // sample index z * n + x
  std::int32_t value;   // in quanta (step / 4 or slope_step / 4), never 0
};

struct Corrections {
  std::vector<Correction> height, slope_x, slope_z;  // each sorted by pos
  std::size_t total() const { return height.size() + slope_x.size() + slope_z.size(); }
};

// One key mode: X(t) and X(t) - X(t-1), each a quantized complex coefficient.
struct KeyCoefficient {
  std::int64_t xr = 0, xi = 0, vr = 0, vi = 0;
};

// Items of a frame: keys number their spectral modes first, then every frame numbers samples.
struct BodyLayout {
  std::uint32_t spectral_items = 0;  // key_modes().size() for keys, 0 for deltas
  std::uint32_t samples = 0;         // n * n
  bool normals = false;
  std::uint32_t total() const { return spectral_items + samples; }
};

inline constexpr std::int32_t kMaxCorrection = 1 << 24;  // |value| limit in quanta

struct BodyCost {
  double key_bits = 0, height_bits = 0, slope_bits = 0;  // ideal coder cost, statistics only
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
