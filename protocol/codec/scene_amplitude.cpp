// Hashed Box-Muller and h0 = xi sqrt(P dk^2) / 2, as the sim draws them.
#include "scene_amplitude.hpp"

#include "det_math.hpp"

#include <cmath>

namespace ocean::codec {

SceneComplex scene_gaussian(std::uint64_t seed, int kx, int kz) {
  const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(kx)) << 32) |
                            static_cast<std::uint32_t>(kz);
  const std::uint64_t a = scene_mix64(seed ^ scene_mix64(key));
  const std::uint64_t b = scene_mix64(a);
  // 53-bit uniforms (exact in double); u1 in (0, 1] so the logarithm is finite.
  const double u1 = static_cast<double>((a >> 11) + 1) * 0x1.0p-53;
  const double u2 = static_cast<double>(b >> 11) * 0x1.0p-53;
  const double r = std::sqrt(-2.0 * det_log(u1));
  const double phi = kTwoPi * u2;
  return {r * det_cos(phi), r * det_sin(phi)};
}

SceneComplex scene_initial_amplitude(const SceneModelParams& p, const SceneSpectrum& spectrum, int kx, int kz) {
  if ((kx == 0 && kz == 0) || !p.band.keeps(kx, kz)) return {};
  const double dkx = kTwoPi / p.patch_x_m;
  const double dkz = kTwoPi / p.patch_z_m;
  const double wx = kx * dkx, wz = kz * dkz;
  const double variance = spectrum.density(wx, wz, std::sqrt(wx * wx + wz * wz)) * dkx * dkz;
  if (!(variance > 1e-40)) return {};  // below 1e-20 m of amplitude; also catches NaN
  const SceneComplex xi = scene_gaussian(p.seed, kx, kz);
  const double scale = std::sqrt(variance) * 0.5;
  return {xi.re * scale, xi.im * scale};
}

}  // namespace ocean::codec
