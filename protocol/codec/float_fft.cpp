// Radix-2 decimation-in-time butterflies in binary32, CODEC.md 4.2. Written as plain loops over
// independent columns so the compiler vectorizes them; vectorizing changes no bit, because each
// lane does the scalar operations in the scalar order.
#include "float_fft.hpp"

#include "bit_reversal.hpp"
#include "det_math.hpp"

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include <stdexcept>
#include <string>
#include <algorithm>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__EMSCRIPTEN__)
// AVX2 where the CPU has it (eight lanes), SSE2 otherwise; never FMA, which would fuse b.re * w.re
// - b.im * w.im into one rounding.
#define OCEAN_FLOAT_FFT_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define OCEAN_FLOAT_FFT_CLONES
#endif

// The rows a butterfly loop reads and writes are distinct: no alias checks around every loop.
#if defined(__clang__)
#define OCEAN_IVDEP _Pragma("clang loop vectorize(assume_safety)")
#else
#define OCEAN_IVDEP _Pragma("GCC ivdep")
#endif

namespace ocean::codec {

namespace {

constexpr int kBlockRows = 16;

// Every stage along the first axis of an n x width block whose rows are `stride` apart, input in
// bit-reversed order. j = 0 (w = 1) and 4j = len (w = i) are exact by definition, not by product.
OCEAN_FLOAT_FFT_CLONES
void stages(int n, const float* cos, const float* sin, float* re, float* im, std::size_t stride, int width) {
  for (int len = 2; len <= n; len <<= 1) {
    const int half = len >> 1;
    const int step = n / len;
    for (int j = 0; j < half; ++j) {
      const float wr = cos[j * step], wi = sin[j * step];
      for (int start = 0; start < n; start += len) {
        float* __restrict ar = re + static_cast<std::size_t>(start + j) * stride;
        float* __restrict ai = im + static_cast<std::size_t>(start + j) * stride;
        float* __restrict br = ar + static_cast<std::size_t>(half) * stride;
        float* __restrict bi = ai + static_cast<std::size_t>(half) * stride;
        if (j == 0) {
OCEAN_IVDEP
          for (int x = 0; x < width; ++x) {
            const float tr = br[x], ti = bi[x], xr = ar[x], xi = ai[x];
            br[x] = xr - tr;
            bi[x] = xi - ti;
            ar[x] = xr + tr;
            ai[x] = xi + ti;
          }
        } else if (4 * j == len) {
OCEAN_IVDEP
          for (int x = 0; x < width; ++x) {
            const float tr = -bi[x], ti = br[x], xr = ar[x], xi = ai[x];
            br[x] = xr - tr;
            bi[x] = xi - ti;
            ar[x] = xr + tr;
            ai[x] = xi + ti;
          }
        } else {
OCEAN_IVDEP
          for (int x = 0; x < width; ++x) {
            const float yr = br[x], yi = bi[x], xr = ar[x], xi = ai[x];
            const float pr = yr * wr, qr = yi * wi, pi = yr * wi, qi = yi * wr;
            const float tr = pr - qr, ti = pi + qi;
            br[x] = xr - tr;
            bi[x] = xi - ti;
            ar[x] = xr + tr;
            ai[x] = xi + ti;
          }
        }
      }
    }
  }
}

// Rows 0..rows-1 of src (n values each) into block[bitrev(c) * rows + l], four rows and four
// columns at a time through registers: element by element, the strided side of a transpose cost
// more than the butterflies.
void gather_rows(int n, int rows, const int* bitrev, const float* src, float* block) {
  for (int l = 0; l < rows; l += 4)
    for (int c = 0; c < n; c += 4) {
#if defined(__SSE2__)
      __m128 a = _mm_loadu_ps(src + static_cast<std::size_t>(l) * n + c);
      __m128 b = _mm_loadu_ps(src + static_cast<std::size_t>(l + 1) * n + c);
      __m128 d = _mm_loadu_ps(src + static_cast<std::size_t>(l + 2) * n + c);
      __m128 e = _mm_loadu_ps(src + static_cast<std::size_t>(l + 3) * n + c);
      _MM_TRANSPOSE4_PS(a, b, d, e);
      _mm_storeu_ps(block + static_cast<std::size_t>(bitrev[c]) * rows + l, a);
      _mm_storeu_ps(block + static_cast<std::size_t>(bitrev[c + 1]) * rows + l, b);
      _mm_storeu_ps(block + static_cast<std::size_t>(bitrev[c + 2]) * rows + l, d);
      _mm_storeu_ps(block + static_cast<std::size_t>(bitrev[c + 3]) * rows + l, e);
#else
      for (int k = 0; k < 4; ++k)
        for (int m = 0; m < 4; ++m)
          block[static_cast<std::size_t>(bitrev[c + k]) * rows + l + m] = src[static_cast<std::size_t>(l + m) * n + c + k];
#endif
    }
}

void scatter_rows(int n, int rows, const float* block, float* dst) {
  for (int l = 0; l < rows; l += 4)
    for (int c = 0; c < n; c += 4) {
#if defined(__SSE2__)
      __m128 a = _mm_loadu_ps(block + static_cast<std::size_t>(c) * rows + l);
      __m128 b = _mm_loadu_ps(block + static_cast<std::size_t>(c + 1) * rows + l);
      __m128 d = _mm_loadu_ps(block + static_cast<std::size_t>(c + 2) * rows + l);
      __m128 e = _mm_loadu_ps(block + static_cast<std::size_t>(c + 3) * rows + l);
      _MM_TRANSPOSE4_PS(a, b, d, e);
      _mm_storeu_ps(dst + static_cast<std::size_t>(l) * n + c, a);
      _mm_storeu_ps(dst + static_cast<std::size_t>(l + 1) * n + c, b);
      _mm_storeu_ps(dst + static_cast<std::size_t>(l + 2) * n + c, d);
      _mm_storeu_ps(dst + static_cast<std::size_t>(l + 3) * n + c, e);
#else
      for (int k = 0; k < 4; ++k)
        for (int m = 0; m < 4; ++m)
          dst[static_cast<std::size_t>(l + m) * n + c + k] = block[static_cast<std::size_t>(c + k) * rows + l + m];
#endif
    }
}

}  // namespace

FloatFft::FloatFft(int n) : n_(n) {
  if (n < 4 || n > 4096 || (n & (n - 1)) != 0)
    throw std::invalid_argument("FloatFft: size must be a power of two in [4, 4096], got " + std::to_string(n));
  cos_.resize(n / 2);
  sin_.resize(n / 2);
  for (int j = 0; j < n / 2; ++j) {
    const double angle = kTwoPi * j / n;
    cos_[j] = static_cast<float>(det_cos(angle));
    sin_[j] = static_cast<float>(det_sin(angle));
  }
  bitrev_ = bit_reversal(n);
  block_.resize(static_cast<std::size_t>(2) * kBlockRows * n);
}

void FloatFft::inverse_2d(float* re, float* im) {
  const int n = n_;
  const int rows = std::min(n, kBlockRows);
  float* block_re = block_.data();
  float* block_im = block_re + static_cast<std::size_t>(kBlockRows) * n;
  // Rows, `rows` at a time: transposed into a block (bit-reversed on the way) so that each row's
  // transform is one lane of the same column loops.
  for (int r0 = 0; r0 < n; r0 += rows) {
    const std::size_t at = static_cast<std::size_t>(r0) * n;
    gather_rows(n, rows, bitrev_.data(), re + at, block_re);
    gather_rows(n, rows, bitrev_.data(), im + at, block_im);
    stages(n, cos_.data(), sin_.data(), block_re, block_im, static_cast<std::size_t>(rows), rows);
    scatter_rows(n, rows, block_re, re + at);
    scatter_rows(n, rows, block_im, im + at);
  }
  for (int i = 0; i < n; ++i) {
    const int r = bitrev_[i];
    if (r > i) {
      std::swap_ranges(re + static_cast<std::size_t>(i) * n, re + static_cast<std::size_t>(i) * n + n, re + static_cast<std::size_t>(r) * n);
      std::swap_ranges(im + static_cast<std::size_t>(i) * n, im + static_cast<std::size_t>(i) * n + n, im + static_cast<std::size_t>(r) * n);
    }
  }
  stages(n, cos_.data(), sin_.data(), re, im, static_cast<std::size_t>(n), n);
}

}  // namespace ocean::codec
