// dominant_wavenumber: the wavenumber whose wave best matches samples spaced dx apart (Hann
// window, scanned finely between k_lo and k_hi): how the wake tests read a wavelength off a
// line of heights, the sim's or a decoder's.
#pragma once

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace ocean::test_support {

inline double dominant_wavenumber(const std::vector<double>& samples, double dx, double k_lo, double k_hi) {
  const std::size_t n = samples.size();
  double best_k = 0.0, best = -1.0;
  for (double k = k_lo; k <= k_hi; k += 1e-4 * (k_hi - k_lo)) {
    std::complex<double> sum{};
    for (std::size_t i = 0; i < n; ++i) {
      const double w = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n - 1));
      sum += w * samples[i] * std::complex<double>(std::cos(k * dx * i), -std::sin(k * dx * i));
    }
    if (std::abs(sum) > best) best = std::abs(sum), best_k = k;
  }
  return best_k;
}

}  // namespace ocean::test_support
