// AVX2 butterflies for FixedFft. The twiddle product is dot_round30 (fixed_point.hpp) four lanes at a
// time: AVX2 multiplies only 32 x 32 -> 64 bits, which is exactly what its split into high and low
// words needs. The low word is unsigned there; here it is biased by 2^31 into a signed word and the
// bias added back as a constant of the twiddle, so every intermediate is the same integer mod 2^64
// and the result the same bits.
#include "fixed_fft_avx2.hpp"

#include <algorithm>

#if defined(__x86_64__)
#include <immintrin.h>

namespace ocean::codec::fft_avx2 {
namespace {

#define OCEAN_AVX2 __attribute__((target("avx2")))

struct Twiddle {
  __m256i wr, wi, nwi, kr, ki;  // w; -Im w; the low words' bias terms (with the rounding half)
};

OCEAN_AVX2 inline Twiddle make_twiddle(std::int64_t wr, std::int64_t wi) {
  const std::int64_t half = std::int64_t{1} << 29;
  return {_mm256_set1_epi64x(wr), _mm256_set1_epi64x(wi), _mm256_set1_epi64x(-wi),
          _mm256_set1_epi64x((wr - wi) * (std::int64_t{1} << 31) + half),
          _mm256_set1_epi64x((wi + wr) * (std::int64_t{1} << 31) + half)};
}

// Arithmetic shift right by 30 (AVX2 has it only for 32-bit lanes): shift logically, then
// sign-extend from bit 33.
OCEAN_AVX2 inline __m256i sra30(__m256i x) {
  const __m256i sign = _mm256_set1_epi64x(std::int64_t{1} << 33);
  return _mm256_sub_epi64(_mm256_xor_si256(_mm256_srli_epi64(x, 30), sign), sign);
}

// (br + i bi)(wr + i wi), each part rounded at 2^30 as dot_round30.
OCEAN_AVX2 inline void twiddle(__m256i br, __m256i bi, const Twiddle& w, __m256i& tr, __m256i& ti) {
  const __m256i bias = _mm256_set1_epi64x(0x80000000LL);
  const __m256i brh = _mm256_srli_epi64(br, 32), bih = _mm256_srli_epi64(bi, 32);
  const __m256i brl = _mm256_xor_si256(br, bias), bil = _mm256_xor_si256(bi, bias);
  const __m256i hr = _mm256_add_epi64(_mm256_mul_epi32(brh, w.wr), _mm256_mul_epi32(bih, w.nwi));
  const __m256i lr = _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epi32(brl, w.wr), _mm256_mul_epi32(bil, w.nwi)), w.kr);
  const __m256i hi = _mm256_add_epi64(_mm256_mul_epi32(brh, w.wi), _mm256_mul_epi32(bih, w.wr));
  const __m256i li = _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epi32(brl, w.wi), _mm256_mul_epi32(bil, w.wr)), w.ki);
  tr = _mm256_add_epi64(_mm256_slli_epi64(hr, 2), sra30(lr));
  ti = _mm256_add_epi64(_mm256_slli_epi64(hi, 2), sra30(li));
}

OCEAN_AVX2 inline __m256i load(const std::int64_t* p) { return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)); }
OCEAN_AVX2 inline void store(std::int64_t* p, __m256i v) { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v); }

// (a, b) <- (a + t, a - t) on four lanes of one row pair.
OCEAN_AVX2 inline void butterfly(std::int64_t* ar, std::int64_t* ai, std::int64_t* br, std::int64_t* bi, __m256i tr,
                                 __m256i ti) {
  const __m256i xr = load(ar), xi = load(ai);
  store(br, _mm256_sub_epi64(xr, tr));
  store(bi, _mm256_sub_epi64(xi, ti));
  store(ar, _mm256_add_epi64(xr, tr));
  store(ai, _mm256_add_epi64(xi, ti));
}

// Every stage of the transform along the first axis of an n x width block whose rows are `stride`
// values apart, already in bit-reversed order; width a multiple of 4.
OCEAN_AVX2 void stages(const Tables& t, std::int64_t* re, std::int64_t* im, std::size_t stride, int width,
                       bool inverse) {
  const int n = t.n;
  for (int len = 2; len <= n; len <<= 1) {
    const int half = len >> 1;
    const int step = n / len;
    for (int j = 0; j < half; ++j) {
      const bool plain = j == 0, quarter = 4 * j == len;
      const Twiddle w = plain || quarter ? Twiddle{} : make_twiddle(t.cos[j * step], inverse ? t.sin[j * step] : -t.sin[j * step]);
      for (int start = 0; start < n; start += len) {
        std::int64_t* ar = re + static_cast<std::size_t>(start + j) * stride;
        std::int64_t* ai = im + static_cast<std::size_t>(start + j) * stride;
        std::int64_t* br = ar + static_cast<std::size_t>(half) * stride;
        std::int64_t* bi = ai + static_cast<std::size_t>(half) * stride;
        for (int x = 0; x < width; x += 4) {
          const __m256i yr = load(br + x), yi = load(bi + x);
          __m256i tr, ti;
          if (plain) {
            tr = yr;
            ti = yi;
          } else if (quarter) {  // w = +-i exactly
            const __m256i zero = _mm256_setzero_si256();
            tr = inverse ? _mm256_sub_epi64(zero, yi) : yi;
            ti = inverse ? yr : _mm256_sub_epi64(zero, yr);
          } else {
            twiddle(yr, yi, w, tr, ti);
          }
          butterfly(ar + x, ai + x, br + x, bi + x, tr, ti);
        }
      }
    }
  }
}

// 4 x 4 transpose of int64 lanes.
OCEAN_AVX2 inline void transpose4(__m256i& a, __m256i& b, __m256i& c, __m256i& d) {
  const __m256i t0 = _mm256_unpacklo_epi64(a, b), t1 = _mm256_unpackhi_epi64(a, b);
  const __m256i t2 = _mm256_unpacklo_epi64(c, d), t3 = _mm256_unpackhi_epi64(c, d);
  a = _mm256_permute2x128_si256(t0, t2, 0x20);
  b = _mm256_permute2x128_si256(t1, t3, 0x20);
  c = _mm256_permute2x128_si256(t0, t2, 0x31);
  d = _mm256_permute2x128_si256(t1, t3, 0x31);
}

// Rows r..r+3 of an n x n array into an n x 4 block (element c of row r + l at [bitrev(c)][l]), so
// that their four transforms run as four lanes.
OCEAN_AVX2 void gather_rows(const Tables& t, const std::int64_t* src, std::int64_t* block) {
  const int n = t.n;
  for (int c = 0; c < n; c += 4) {
    __m256i v0 = load(src + c), v1 = load(src + n + c), v2 = load(src + 2 * n + c), v3 = load(src + 3 * n + c);
    transpose4(v0, v1, v2, v3);
    store(block + 4 * t.bitrev[c], v0);
    store(block + 4 * t.bitrev[c + 1], v1);
    store(block + 4 * t.bitrev[c + 2], v2);
    store(block + 4 * t.bitrev[c + 3], v3);
  }
}

OCEAN_AVX2 void scatter_rows(int n, const std::int64_t* block, std::int64_t* dst) {
  for (int c = 0; c < n; c += 4) {
    __m256i v0 = load(block + 4 * c), v1 = load(block + 4 * c + 4), v2 = load(block + 4 * c + 8), v3 = load(block + 4 * c + 12);
    transpose4(v0, v1, v2, v3);
    store(dst + c, v0);
    store(dst + n + c, v1);
    store(dst + 2 * n + c, v2);
    store(dst + 3 * n + c, v3);
  }
}

}  // namespace

bool available() { return __builtin_cpu_supports("avx2"); }

OCEAN_AVX2 void transform_2d(const Tables& t, std::int64_t* re, std::int64_t* im, bool inverse, std::int64_t* scratch) {
  const int n = t.n;
  std::int64_t* block_re = scratch;
  std::int64_t* block_im = scratch + 4 * n;
  for (int r = 0; r < n; r += 4) {
    std::int64_t* row_re = re + static_cast<std::size_t>(r) * n;
    std::int64_t* row_im = im + static_cast<std::size_t>(r) * n;
    gather_rows(t, row_re, block_re);
    gather_rows(t, row_im, block_im);
    stages(t, block_re, block_im, 4, 4, inverse);
    scatter_rows(n, block_re, row_re);
    scatter_rows(n, block_im, row_im);
  }
  for (int i = 0; i < n; ++i) {
    const int r = t.bitrev[i];
    if (r > i) {
      std::swap_ranges(re + static_cast<std::size_t>(i) * n, re + static_cast<std::size_t>(i) * n + n, re + static_cast<std::size_t>(r) * n);
      std::swap_ranges(im + static_cast<std::size_t>(i) * n, im + static_cast<std::size_t>(i) * n + n, im + static_cast<std::size_t>(r) * n);
    }
  }
  stages(t, re, im, static_cast<std::size_t>(n), n, inverse);
}

}  // namespace ocean::codec::fft_avx2

#else  // no AVX2 in this build (WebAssembly, other CPUs): FixedFft keeps its scalar butterflies

namespace ocean::codec::fft_avx2 {
bool available() { return false; }
void transform_2d(const Tables&, std::int64_t*, std::int64_t*, bool, std::int64_t*) {}
}  // namespace ocean::codec::fft_avx2

#endif
