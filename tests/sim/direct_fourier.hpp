// Direct (slow, double-precision) spectral sums used as the reference the FFT frames must match.
#pragma once

#include "ocean.hpp"

#include <complex>
#include <numbers>
#include <vector>

namespace ocean::sim::testing {

// Full-plane spectrum of a field: kx in [-nx/2, nx/2), kz in [-nz/2, nz/2), index (kz + nz/2) * nx + kx + nx/2.
struct PlaneSpectrum {
  int n_x = 0;
  int n_z = 0;
  std::vector<std::complex<double>> c;
  std::complex<double>& at(int kx, int kz) { return c[(kz + n_z / 2) * n_x + kx + n_x / 2]; }
  std::complex<double> at(int kx, int kz) const { return c[(kz + n_z / 2) * n_x + kx + n_x / 2]; }
};

// h(k, t) of every mode of the ocean's full grid, from Ocean::mode_amplitude.
inline PlaneSpectrum height_spectrum(const Ocean& ocean, double t) {
  PlaneSpectrum s{ocean.params().size_x, ocean.params().size_z, {}};
  s.c.resize(static_cast<std::size_t>(s.n_x) * s.n_z);
  for (int kz = -s.n_z / 2; kz < s.n_z / 2; ++kz)
    for (int kx = -s.n_x / 2; kx < s.n_x / 2; ++kx) s.at(kx, kz) = ocean.mode_amplitude(t, kx, kz);
  return s;
}

// sum_k s(k) e^{i k.x} at the point (x, z) in metres (any point, also outside the patch).
inline std::complex<double> evaluate_at(const PlaneSpectrum& s, double patch_x, double patch_z, double x, double z) {
  const double two_pi = 2.0 * std::numbers::pi;
  std::complex<double> sum = 0.0;
  for (int kz = -s.n_z / 2; kz < s.n_z / 2; ++kz)
    for (int kx = -s.n_x / 2; kx < s.n_x / 2; ++kx) {
      const std::complex<double> v = s.at(kx, kz);
      if (v != 0.0) sum += v * std::polar(1.0, two_pi * (kx * x / patch_x + kz * z / patch_z));
    }
  return sum;
}

// Separable direct DFT along one axis of a row-major complex grid (rows along z).
// sign = -1: forward (analysis, divided by n), +1: inverse (synthesis).
inline std::vector<std::complex<double>> dft_axis(const std::vector<std::complex<double>>& in, int n_x, int n_z,
                                                  bool along_x, int sign) {
  const int n = along_x ? n_x : n_z;
  std::vector<std::complex<double>> twiddle(n);
  for (int i = 0; i < n; ++i) twiddle[i] = std::polar(1.0, sign * 2.0 * std::numbers::pi * i / n);
  std::vector<std::complex<double>> out(in.size());
  const double scale = sign < 0 ? 1.0 / n : 1.0;
  for (int z = 0; z < n_z; ++z)
    for (int x = 0; x < n_x; ++x) {
      std::complex<double> sum = 0.0;
      const int k = along_x ? x : z;
      for (int j = 0; j < n; ++j) sum += in[along_x ? z * n_x + j : j * n_x + x] * twiddle[(k * j) % n];
      out[z * n_x + x] = sum * scale;
    }
  return out;
}

}  // namespace ocean::sim::testing
