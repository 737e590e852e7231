// fft_bin: FFT bin i of an n-point transform as a signed wavenumber index, the Nyquist bin -n/2
// (CODEC.md 4: every lattice and the scene model number their modes this way).
#pragma once

namespace ocean::codec {

constexpr int signed_index(int i, int n) { return i < n / 2 ? i : i - n; }

}  // namespace ocean::codec
