// The FixedFft's 2-D transform in AVX2: four columns (or, after a 4 x 4 transpose, four rows) per
// vector, with the same butterflies, order and rounding as the scalar code, so the same bits. A
// client decoding a 256 stream spends most of its time here (CODEC.md 4 fixes the arithmetic, so
// the only way to go faster is to do that arithmetic four lanes at a time).
#pragma once

#include <cstdint>

namespace ocean::codec::fft_avx2 {

// Whether this build has the kernel and this CPU can run it.
bool available();

struct Tables {
  int n;                     // a power of two, >= 4
  const std::int64_t* cos;   // round(2^30 cos(2 pi j / n)), j < n/2
  const std::int64_t* sin;   // likewise sin
  const int* bitrev;         // the bit-reversal permutation of n
};

// Rows first, then columns, exactly as FixedFft::transform_2d. scratch: 8 n int64 values.
void transform_2d(const Tables& t, std::int64_t* re, std::int64_t* im, bool inverse, std::int64_t* scratch);

}  // namespace ocean::codec::fft_avx2
