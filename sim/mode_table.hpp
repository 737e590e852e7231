// ModeTable: the per-mode constants of one n_x x n_z band, laid out as the half spectrum FFTW's
// c2r reads (rows kz in FFT order, columns kx = 0 .. n_x/2). The Nyquist row and column and the DC
// mode are zero, so a band keeps exactly the modes with |kx| < n_x/2 and |kz| < n_z/2.
#pragma once

#include "sea_model.hpp"

#include <cstddef>
#include <vector>

namespace ocean::sim {

struct ModeTable {
  int n_x = 0;
  int n_z = 0;
  int columns = 0;              // n_x / 2 + 1
  std::vector<float> kx;        // per column, rad/m
  std::vector<float> kz;        // per row, rad/m
  std::vector<double> omega;    // per mode, rad/s
  // With a = h0(k), b = conj(h0(-k)) and phase p = w t:
  // h(k,t) = a e^{-ip} + b e^{ip} = (sum_re cos p + diff_im sin p) + i (sum_im cos p - diff_re sin p)
  std::vector<float> sum_re, sum_im;    // a + b
  std::vector<float> diff_re, diff_im;  // a - b

  std::size_t modes() const { return static_cast<std::size_t>(n_z) * columns; }
  int kz_index(int row) const { return row < n_z / 2 ? row : row - n_z; }  // signed integer wavenumber
};

// The table of the central n_x x n_z modes of the scene (n_x, n_z powers of two up to the grid size).
ModeTable build_mode_table(const SceneParams& params, const Spectrum& spectrum, int n_x, int n_z);

}  // namespace ocean::sim
