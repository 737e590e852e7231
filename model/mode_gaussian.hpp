// The portable Gaussian source of h0: two independent N(0, 1) numbers per integer wavenumber,
// a pure function of (seed, kx, kz). Because it does not depend on the grid, every grid size and
// every band of one scene draws the same numbers for the same wave.
#pragma once

#include <cstdint>

namespace ocean::model {

struct GaussianPair {
  double re;
  double im;
};

// splitmix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mixer with full avalanche.
constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Box-Muller over two hashed uniforms; kx, kz are integer wavenumbers (cycles per patch). The
// integer hash is exact in any arithmetic, so both arithmetics draw the same uniforms.
template <class Math>
GaussianPair mode_gaussian(std::uint64_t seed, int kx, int kz);

}  // namespace ocean::model
