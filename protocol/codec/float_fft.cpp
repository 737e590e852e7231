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
// The butterflies are compiled twice: for AVX2 (eight lanes) and for the baseline (SSE2), chosen
// at run time; never with FMA, which would fuse b.re * w.re - b.im * w.im into one rounding.
// Not target_clones: its ifunc resolver runs before ThreadSanitizer's runtime and crashes it.
#define OCEAN_FLOAT_FFT_AVX2 1
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

struct Twiddle {
  float re, im;
};

// w = e^{+2 pi i j / len}, exactly 1 and i where the tables are not exact (CODEC.md 4.2 multiplies
// by those too: the products decide zeros' signs and what an infinity gives).
Twiddle twiddle(int n, const float* cos, const float* sin, int len, int j) {
  if (j == 0) return {1.0f, 0.0f};
  if (4 * j == len) return {0.0f, 1.0f};
  return {cos[j * (n / len)], sin[j * (n / len)]};
}

// The stage of length len == n alone, after the pairs of stages_body.
__attribute__((always_inline)) inline void last_stage(int n, const float* cos, const float* sin, float* re, float* im,
                                                     std::size_t stride, int width, int len) {
  const int h = len >> 1;
  for (int j = 0; j < h; ++j) {
    const Twiddle w = twiddle(n, cos, sin, len, j);
    float* __restrict r0 = re + static_cast<std::size_t>(j) * stride;
    float* __restrict i0 = im + static_cast<std::size_t>(j) * stride;
    float* __restrict r1 = r0 + static_cast<std::size_t>(h) * stride;
    float* __restrict i1 = i0 + static_cast<std::size_t>(h) * stride;
    OCEAN_IVDEP
    for (int x = 0; x < width; ++x) {
      const float tr = r1[x] * w.re - i1[x] * w.im, ti = r1[x] * w.im + i1[x] * w.re;
      const float ar = r0[x], ai = i0[x];
      r1[x] = ar - tr;
      i1[x] = ai - ti;
      r0[x] = ar + tr;
      i0[x] = ai + ti;
    }
  }
}

// Every stage along the first axis of an n x width block whose rows are `stride` apart, input in
// bit-reversed order. Stages go in pairs (len, 2 len): the four rows start + j + {0, 1, 2, 3} len/2
// meet only each other in both, so each is loaded and stored once per pair (the column pass is
// memory-bound).
__attribute__((always_inline)) inline void stages_body(int n, const float* cos, const float* sin, float* re, float* im,
                                                      std::size_t stride, int width) {
  int len = 2;
  for (; 2 * len <= n; len <<= 2) {
    const int h = len >> 1;
    for (int j = 0; j < h; ++j) {
      const Twiddle w1 = twiddle(n, cos, sin, len, j);
      const Twiddle w2 = twiddle(n, cos, sin, 2 * len, j);
      const Twiddle w3 = twiddle(n, cos, sin, 2 * len, j + h);
      for (int start = 0; start < n; start += 2 * len) {
        float* __restrict r0 = re + static_cast<std::size_t>(start + j) * stride;
        float* __restrict i0 = im + static_cast<std::size_t>(start + j) * stride;
        float* __restrict r1 = r0 + static_cast<std::size_t>(h) * stride;
        float* __restrict i1 = i0 + static_cast<std::size_t>(h) * stride;
        float* __restrict r2 = r1 + static_cast<std::size_t>(h) * stride;
        float* __restrict i2 = i1 + static_cast<std::size_t>(h) * stride;
        float* __restrict r3 = r2 + static_cast<std::size_t>(h) * stride;
        float* __restrict i3 = i2 + static_cast<std::size_t>(h) * stride;
        OCEAN_IVDEP
        for (int x = 0; x < width; ++x) {
          // Stage len: (0, 1) and (2, 3), both by w1.
          float tr = r1[x] * w1.re - i1[x] * w1.im, ti = r1[x] * w1.im + i1[x] * w1.re;
          const float b0r = r0[x] + tr, b0i = i0[x] + ti, b1r = r0[x] - tr, b1i = i0[x] - ti;
          tr = r3[x] * w1.re - i3[x] * w1.im;
          ti = r3[x] * w1.im + i3[x] * w1.re;
          const float b2r = r2[x] + tr, b2i = i2[x] + ti, b3r = r2[x] - tr, b3i = i2[x] - ti;
          // Stage 2 len: (0, 2) by w2, (1, 3) by w3.
          tr = b2r * w2.re - b2i * w2.im;
          ti = b2r * w2.im + b2i * w2.re;
          r0[x] = b0r + tr;
          i0[x] = b0i + ti;
          r2[x] = b0r - tr;
          i2[x] = b0i - ti;
          tr = b3r * w3.re - b3i * w3.im;
          ti = b3r * w3.im + b3i * w3.re;
          r1[x] = b1r + tr;
          i1[x] = b1i + ti;
          r3[x] = b1r - tr;
          i3[x] = b1i - ti;
        }
      }
    }
  }
  if (len <= n) last_stage(n, cos, sin, re, im, stride, width, len);  // an odd number of stages
}

#if defined(OCEAN_FLOAT_FFT_AVX2)
__attribute__((target("avx2"))) void stages_avx2(int n, const float* cos, const float* sin, float* re, float* im,
                                                 std::size_t stride, int width) {
  stages_body(n, cos, sin, re, im, stride, width);
}
#endif

void stages(int n, const float* cos, const float* sin, float* re, float* im, std::size_t stride, int width) {
#if defined(OCEAN_FLOAT_FFT_AVX2)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2) {
    stages_avx2(n, cos, sin, re, im, stride, width);
    return;
  }
#endif
  stages_body(n, cos, sin, re, im, stride, width);
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
    const double angle = model::kTwoPi * j / n;
    cos_[j] = static_cast<float>(model::det_cos(angle));
    sin_[j] = static_cast<float>(model::det_sin(angle));
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
