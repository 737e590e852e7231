// Channel pairs (CODEC.md 7.2): every synthesized channel's half-spectrum follows from X(t) in
// binary32 mode by mode, and two channels A, B share one inverse FFT as Z = A + iB over the full
// grid. The channels' values are made as Z is written, never stored as half-spectra of their own.
#pragma once

#include "common/channels.hpp"

#include <cstdint>

namespace ocean::codec {

// A channel's half-spectrum as its kind (common/channels.hpp) makes it from X(t).
struct ChannelSource {
  ChannelKind kind = ChannelKind::none;
  const float* factor = nullptr;  // G per half-spectrum mode (disp, derivative)
};

// X(t) in binary32 with the slope factors of its stream: n x (n/2 + 1) half-spectrum.
struct FloatSpectrum {
  int n = 0;
  const float* re = nullptr;
  const float* im = nullptr;
  const float* kx = nullptr;  // KX per column, n/2 + 1
  const float* kz = nullptr;  // KZ per row, n
};

// Z (n x n, row-major) of the pair (a, b): Z[r][c] = (A.re - B.im, A.im + B.re) for c <= n/2, and
// its conjugate partner Z[(n - r) mod n][n - c] = (A.re + B.im, B.re - A.im) for 0 < c < n/2.
void pack_channel_pair(const FloatSpectrum& x, ChannelSource a, ChannelSource b, float* z_re, float* z_im);

}  // namespace ocean::codec
