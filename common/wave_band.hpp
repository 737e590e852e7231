// WaveBand: which waves of one lattice a realization of the spectrum keeps, by the wave's radius in
// integer cycles per patch. Integers make the cut exact on every platform, so the sim and the
// codec's scene model (which may not share code or libm) drop the very same waves. Cascades are
// lattices of one scene at patch sizes in integer ratios: a coarse lattice keeping radii below
// s * R and a fine one s times smaller keeping radii from R up share no wave and leave none out.
#pragma once

#include <cstdint>

namespace ocean {

struct WaveBand {
  static constexpr int kMaxCycles = 4096;  // radii beyond any lattice's Nyquist (2048 / 2 * sqrt 2)

  int min_cycles = 0;  // keep kx^2 + kz^2 >= min_cycles^2
  int max_cycles = 0;  // and kx^2 + kz^2 < max_cycles^2; 0 = no upper limit

  bool keeps(int kx, int kz) const {
    const std::int64_t r2 = std::int64_t{kx} * kx + std::int64_t{kz} * kz;
    return r2 >= std::int64_t{min_cycles} * min_cycles &&
           (max_cycles == 0 || r2 < std::int64_t{max_cycles} * max_cycles);
  }
  bool whole() const { return min_cycles == 0 && max_cycles == 0; }
  // Both radii in [0, kMaxCycles] and the upper one (if any) above the lower one.
  bool valid() const {
    return min_cycles >= 0 && min_cycles <= kMaxCycles && max_cycles >= 0 && max_cycles <= kMaxCycles &&
           (max_cycles == 0 || max_cycles > min_cycles);
  }
  bool operator==(const WaveBand&) const = default;
};

}  // namespace ocean
