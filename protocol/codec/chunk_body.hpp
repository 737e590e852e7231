// Chunk body: the range-coded contents of one chunk's item range - key spectral coefficients
// and sparse spatial corrections (height, slope_x, slope_z, and the five choppy channels). Each
// body decodes on its own.
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
  // Choppy streams: displacement in disp_step / 4 quanta, its derivatives in slope_step / 4.
  std::vector<Correction> disp_x, disp_z, disp_xx, disp_zz, disp_xz;
  std::size_t total() const {
    return height.size() + slope_x.size() + slope_z.size() + disp_x.size() + disp_z.size() + disp_xx.size() +
           disp_zz.size() + disp_xz.size();
  }
};

inline constexpr int kCorrectionChannels = 8;
// The channels of a frame in coding order: height, slope_x, slope_z, disp_x, disp_z, disp_xx,
// disp_zz, disp_xz.
inline std::vector<Correction>& channel(Corrections& c, int i) {
  std::vector<Correction>* all[kCorrectionChannels] = {&c.height, &c.slope_x, &c.slope_z, &c.disp_x,
                                                       &c.disp_z, &c.disp_xx, &c.disp_zz, &c.disp_xz};
  return *all[i];
}
inline const std::vector<Correction>& channel(const Corrections& c, int i) {
  return channel(const_cast<Corrections&>(c), i);
}

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
