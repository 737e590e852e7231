// WaveTruth: the test server's ground truth - a few travelling grid modes with exact slopes (what
// the codec predicts perfectly), plus optional per-sample noise that forces corrections and so
// delta frames of several chunks.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "encoder.hpp"

namespace ocean::client::test {

class WaveTruth {
 public:
  WaveTruth(int n, double patch_m, double noise_m = 0.0) : n_(n), patch_(patch_m), noise_(noise_m) {}

  void at(std::uint32_t tick, double tick_period_s) {
    const double t = tick * tick_period_s, two_pi = 6.283185307179586, g = 9.81;
    const std::size_t size = static_cast<std::size_t>(n_) * n_;
    height.assign(size, 0.0f);
    slope_x.assign(size, 0.0f);
    slope_z.assign(size, 0.0f);
    const int modes[][2] = {{1, 2}, {3, -1}, {-2, 5}, {6, 4}};
    const double amps[] = {0.5, 0.2, 0.1, 0.04};
    for (int m = 0; m < 4; ++m) {
      const double kx = two_pi * modes[m][0] / patch_, kz = two_pi * modes[m][1] / patch_;
      const double w = std::sqrt(g * std::hypot(kx, kz));
      for (int z = 0; z < n_; ++z)
        for (int x = 0; x < n_; ++x) {
          const double phase = kx * x * patch_ / n_ + kz * z * patch_ / n_ - w * t + m;
          const std::size_t i = static_cast<std::size_t>(z) * n_ + x;
          height[i] += static_cast<float>(amps[m] * std::cos(phase));
          slope_x[i] -= static_cast<float>(amps[m] * kx * std::sin(phase));
          slope_z[i] -= static_cast<float>(amps[m] * kz * std::sin(phase));
        }
    }
    if (noise_ > 0.0)
      for (std::size_t i = 0; i < size; ++i) {
        std::uint64_t h = (std::uint64_t{tick} << 32 | i) * 0x9E3779B97F4A7C15ull;
        h ^= h >> 29;
        height[i] += static_cast<float>(noise_ * (static_cast<double>(h % 2001) / 1000.0 - 1.0));
      }
  }

  codec::TruthView view() const { return {height, slope_x, slope_z}; }

  std::vector<float> height, slope_x, slope_z;

 private:
  int n_;
  double patch_;
  double noise_;
};

}  // namespace ocean::client::test
