#include "client/viewer/synthetic_sea.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ocean::viewer {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kGravity = 9.81;

// A small deterministic generator (splitmix64), so the sea looks the same on every platform.
double unit_random(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / 9007199254740992.0;
}

}  // namespace

SyntheticSea::SyntheticSea(const SyntheticSeaParams& p) : params_(p) {
  if (p.n < 4 || p.n > 1024) throw std::invalid_argument("SyntheticSeaParams::n must be 4..1024, got " + std::to_string(p.n));
  if (!(p.patch_m > 0.0f)) throw std::invalid_argument("SyntheticSeaParams::patch_m must be > 0 metres");
  if (p.wave_count < 1 || p.wave_count > 64)
    throw std::invalid_argument("SyntheticSeaParams::wave_count must be 1..64, got " + std::to_string(p.wave_count));
  if (!(p.steepness >= 0.0f && p.steepness < 1.5f))
    throw std::invalid_argument("SyntheticSeaParams::steepness must be in [0, 1.5)");

  std::uint64_t state = p.seed;
  float weight_sum = 0.0f;
  const int nyquist = p.n / 2 - 1;
  for (int i = 0; i < p.wave_count; ++i) {
    // Wavelengths from the patch size down to ~patch/14, directions within +-50 deg of the wind;
    // the wave vector is rounded onto the lattice so the field repeats exactly every patch.
    const double wavelength = p.patch_m / (1.0 + 1.3 * i);
    const double angle = p.wind_direction_rad + (unit_random(state) - 0.5) * 1.75;
    const double kmag = kTwoPi / wavelength;
    int m = static_cast<int>(std::lround(kmag * std::cos(angle) * p.patch_m / kTwoPi));
    int l = static_cast<int>(std::lround(kmag * std::sin(angle) * p.patch_m / kTwoPi));
    m = std::max(-nyquist, std::min(nyquist, m));
    l = std::max(-nyquist, std::min(nyquist, l));
    if (m == 0 && l == 0) m = 1;
    Wave w;
    w.kx = static_cast<float>(kTwoPi * m / p.patch_m);
    w.kz = static_cast<float>(kTwoPi * l / p.patch_m);
    w.k = std::sqrt(w.kx * w.kx + w.kz * w.kz);
    w.omega = std::sqrt(kGravity * w.k);
    w.phase = static_cast<float>(unit_random(state) * kTwoPi);
    // Longer waves carry more of the steepness budget, as in a real spectrum.
    w.amplitude = 1.0f / (1.0f + 0.35f * i);
    weight_sum += w.amplitude;
    waves_.push_back(w);
  }
  for (Wave& w : waves_) w.amplitude = p.steepness * (w.amplitude / weight_sum) / w.k;
}

float SyntheticSea::max_amplitude_m() const {
  float sum = 0.0f;
  for (const Wave& w : waves_) sum += w.amplitude;
  return sum;
}

void SyntheticSea::evaluate(double time_s, SeaFrame& out) const {
  const int n = params_.n;
  const std::size_t count = static_cast<std::size_t>(n) * n;
  out.n = n;
  out.height.assign(count, 0.0f);
  out.slope_x.assign(count, 0.0f);
  out.slope_z.assign(count, 0.0f);
  if (params_.choppy) {
    out.disp_x.assign(count, 0.0f);
    out.disp_z.assign(count, 0.0f);
    out.jacobian.assign(count, 0.0f);
  } else {
    out.disp_x.clear();
    out.disp_z.clear();
    out.jacobian.clear();
  }
  std::vector<float> dxx, dzz, dxz;
  if (params_.choppy) {
    dxx.assign(count, 0.0f);
    dzz.assign(count, 0.0f);
    dxz.assign(count, 0.0f);
  }
  const float spacing = params_.patch_m / n;
  for (const Wave& w : waves_) {
    // omega * t in double, reduced mod 2 pi, so long runs keep their phase precision.
    const float temporal = static_cast<float>(std::fmod(w.omega * time_s, kTwoPi));
    const float ux = w.kx / w.k, uz = w.kz / w.k;
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const float theta = w.kx * c * spacing + w.kz * r * spacing - temporal + w.phase;
        const float s = std::sin(theta), co = std::cos(theta);
        const std::size_t i = static_cast<std::size_t>(r) * n + c;
        out.height[i] += w.amplitude * co;
        out.slope_x[i] -= w.amplitude * w.kx * s;
        out.slope_z[i] -= w.amplitude * w.kz * s;
        if (params_.choppy) {
          out.disp_x[i] -= w.amplitude * ux * s;
          out.disp_z[i] -= w.amplitude * uz * s;
          dxx[i] -= w.amplitude * ux * w.kx * co;
          dzz[i] -= w.amplitude * uz * w.kz * co;
          dxz[i] -= w.amplitude * ux * w.kz * co;
        }
      }
    }
  }
  if (params_.choppy)
    for (std::size_t i = 0; i < count; ++i) out.jacobian[i] = (1.0f + dxx[i]) * (1.0f + dzz[i]) - dxz[i] * dxz[i];
}

}  // namespace ocean::viewer
