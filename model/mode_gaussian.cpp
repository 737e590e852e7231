// Hash-based Box-Muller: no generator state, so no dependence on the order modes are visited in.
#include "mode_gaussian.hpp"

#include "arithmetic.hpp"

#include <cmath>
#include <numbers>

namespace ocean::model {

template <class Math>
GaussianPair mode_gaussian(std::uint64_t seed, int kx, int kz) {
  const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(kx)) << 32) |
                            static_cast<std::uint32_t>(kz);
  const std::uint64_t a = mix64(seed ^ mix64(key));
  const std::uint64_t b = mix64(a);
  // 53-bit uniforms (exact in double); u1 in (0, 1] so the logarithm is finite.
  const double u1 = static_cast<double>((a >> 11) + 1) * 0x1.0p-53;
  const double u2 = static_cast<double>(b >> 11) * 0x1.0p-53;
  const double r = std::sqrt(-2.0 * Math::log(u1));
  const double phi = 2.0 * std::numbers::pi * u2;
  return {r * Math::cos(phi), r * Math::sin(phi)};
}

template GaussianPair mode_gaussian<Libm>(std::uint64_t, int, int);
template GaussianPair mode_gaussian<Det>(std::uint64_t, int, int);

}  // namespace ocean::model
