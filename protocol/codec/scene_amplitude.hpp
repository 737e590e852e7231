// h0(k): the random complex amplitude of each wave at t = 0, from the spectrum and a hashed
// Box-Muller Gaussian that depends only on (seed, kx, kz). A copy of sim/mode_gaussian.cpp
// and initial_amplitude.cpp with det_ functions (the codec may not link the sim); the integer hash
// is the sim's exactly, so both draw the same Gaussian for every wave.
#pragma once

#include "scene_model_params.hpp"
#include "scene_spectrum.hpp"

#include <cstdint>

namespace ocean::codec {

struct SceneComplex {
  double re = 0.0;
  double im = 0.0;
};

// splitmix64 finaliser (Steele, Lea, Flood 2014), as sim/mode_gaussian.hpp.
constexpr std::uint64_t scene_mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Two independent N(0, 1) numbers for the integer wavenumber (kx, kz) (cycles per patch).
SceneComplex scene_gaussian(std::uint64_t seed, int kx, int kz);

// h0 in metres of the wave with integer wavenumber (kx, kz): xi sqrt(P dkx dkz) / 2, exactly 0 at
// k = 0 and where P dkx dkz <= 1e-40 (or NaN).
SceneComplex scene_initial_amplitude(const SceneModelParams& scene, const SceneSpectrum& spectrum, int kx, int kz);

}  // namespace ocean::codec
