// Smooth 2D value noise and its fractal sum, used to paint clouds into the generated sky.
// Deterministic: the lattice values come from an integer hash of the cell and the seed.
#pragma once

#include <cstdint>

namespace ocean::assets {

// In [0, 1]; continuous, with a smoothstep blend between lattice values.
float value_noise(float x, float y, std::uint32_t seed);

// Sum of octaves at doubling frequency and halving amplitude, normalised back to [0, 1].
float fractal_noise(float x, float y, int octaves, std::uint32_t seed);

}  // namespace ocean::assets
