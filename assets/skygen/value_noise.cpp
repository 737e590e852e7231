#include "assets/skygen/value_noise.hpp"

#include <cmath>

namespace ocean::assets {

namespace {

float lattice(std::int32_t ix, std::int32_t iy, std::uint32_t seed) {
  // A few rounds of multiply-xorshift mixing (the lowbias32 constants).
  std::uint32_t h = static_cast<std::uint32_t>(ix) * 0x8da6b343u ^ static_cast<std::uint32_t>(iy) * 0xd8163841u ^ seed * 0xcb1ab31fu;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return static_cast<float>(h & 0xffffffu) / static_cast<float>(0xffffff);
}

float smooth(float t) { return t * t * (3.0f - 2.0f * t); }

}  // namespace

float value_noise(float x, float y, std::uint32_t seed) {
  const float fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int32_t>(fx), iy = static_cast<std::int32_t>(fy);
  const float tx = smooth(x - fx), ty = smooth(y - fy);
  const float a = lattice(ix, iy, seed), b = lattice(ix + 1, iy, seed);
  const float c = lattice(ix, iy + 1, seed), d = lattice(ix + 1, iy + 1, seed);
  return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

float fractal_noise(float x, float y, int octaves, std::uint32_t seed) {
  float sum = 0.0f, amplitude = 1.0f, total = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * value_noise(x, y, seed + static_cast<std::uint32_t>(o));
    total += amplitude;
    x = x * 2.03f + 17.1f;  // offset and irrational-ish scale keep octaves from lining up
    y = y * 2.03f - 9.7f;
    amplitude *= 0.5f;
  }
  return total > 0.0f ? sum / total : 0.0f;
}

}  // namespace ocean::assets
