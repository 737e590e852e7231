// Adding 1.5 * 2^52 to a double of magnitude below 2^51 rounds it to an integer (ties to even, as
// every IEEE add does) and leaves that integer in the low bits of the sum's encoding; read the
// other way, an integer below 2^51 in those bits, less the bias, is that integer as a double.
#include "field_conversion.hpp"

#include <climits>
#include <cstring>

#if defined(__x86_64__) && !defined(__EMSCRIPTEN__)
#include <immintrin.h>
#endif

namespace ocean::codec {
namespace {

constexpr double kFieldLimit = 2251799813685247.0;    // 2^51 - 1
constexpr double kRoundingBias = 6755399441055744.0;  // 1.5 * 2^52

// Emscripten's libc++ has no std::bit_cast.
inline std::int64_t bits_of(double d) {
  std::int64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

inline std::int64_t to_field(float x, double scale) {
  double y = static_cast<double>(x) * scale;  // exact: scale is a power of two
  y = y == y ? y : 0.0;
  y = y > kFieldLimit ? kFieldLimit : y;
  y = y < -kFieldLimit ? -kFieldLimit : y;
  return bits_of(y + kRoundingBias) - bits_of(kRoundingBias);
}

#if defined(__x86_64__) && !defined(__EMSCRIPTEN__)
__attribute__((target("avx2"))) void round_fields_avx2(const float* x, std::size_t count, double scale, std::int64_t* out) {
  const __m256d s = _mm256_set1_pd(scale), hi = _mm256_set1_pd(kFieldLimit), lo = _mm256_set1_pd(-kFieldLimit);
  const __m256d bias = _mm256_set1_pd(kRoundingBias);
  const __m256i bias_bits = _mm256_castpd_si256(bias);
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    __m256d y = _mm256_mul_pd(_mm256_cvtps_pd(_mm_loadu_ps(x + i)), s);
    y = _mm256_and_pd(y, _mm256_cmp_pd(y, y, _CMP_ORD_Q));  // NaN to +0 first: max/min would keep a bound
    y = _mm256_min_pd(_mm256_max_pd(y, lo), hi);
    const __m256i v = _mm256_sub_epi64(_mm256_castpd_si256(_mm256_add_pd(y, bias)), bias_bits);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + i), v);
  }
  for (; i < count; ++i) out[i] = to_field(x[i], scale);
}

__attribute__((target("avx2"))) void scale_fields_avx2(const std::int64_t* v, std::size_t count, double scale, float* out) {
  const __m256d s = _mm256_set1_pd(scale), bias = _mm256_set1_pd(kRoundingBias);
  const __m256i bias_bits = _mm256_castpd_si256(bias);
  const __m256i hi = _mm256_set1_epi64x(std::int64_t{1} << 51), lo = _mm256_set1_epi64x(-(std::int64_t{1} << 51));
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    const __m256i x = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(v + i));
    const __m256i outside = _mm256_or_si256(_mm256_cmpgt_epi64(x, hi), _mm256_cmpgt_epi64(lo, x));
    if (!_mm256_testz_si256(outside, outside)) {  // beyond 2^51 (hostile streams): the scalar form
      for (std::size_t k = i; k < i + 4; ++k) out[k] = static_cast<float>(static_cast<double>(v[k]) * scale);
      continue;
    }
    const __m256d d = _mm256_sub_pd(_mm256_castsi256_pd(_mm256_add_epi64(x, bias_bits)), bias);  // exact
    _mm_storeu_ps(out + i, _mm256_cvtpd_ps(_mm256_mul_pd(d, s)));
  }
  for (; i < count; ++i) out[i] = static_cast<float>(static_cast<double>(v[i]) * scale);
}

// Eight samples at a time in 32-bit lanes: x * round_scale is exact in binary32 (a power of two
// scaling down; what falls below the normal range rounds to 0 either way), and the conversion
// rounds to nearest even as the double path does. Lanes beyond int32 (and NaN) come back as
// INT32_MIN, and those eight take the scalar path.
__attribute__((target("avx2"))) void round_scale_fields_avx2(const float* x, std::size_t count, double round_scale,
                                                             double out_scale, float* out) {
  const __m256 rs = _mm256_set1_ps(static_cast<float>(round_scale));
  const __m256d s = _mm256_set1_pd(out_scale);
  const __m256i indefinite = _mm256_set1_epi32(INT32_MIN);
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    const __m256i v = _mm256_cvtps_epi32(_mm256_mul_ps(_mm256_loadu_ps(x + i), rs));
    if (!_mm256_testz_si256(_mm256_cmpeq_epi32(v, indefinite), _mm256_set1_epi32(-1))) {
      for (std::size_t k = i; k < i + 8; ++k)
        out[k] = static_cast<float>(static_cast<double>(to_field(x[k], round_scale)) * out_scale);
      continue;
    }
    const __m128 lo = _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_castsi256_si128(v)), s));
    const __m128 hi = _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_extracti128_si256(v, 1)), s));
    _mm256_storeu_ps(out + i, _mm256_set_m128(hi, lo));
  }
  for (; i < count; ++i) out[i] = static_cast<float>(static_cast<double>(to_field(x[i], round_scale)) * out_scale);
}
#endif

#if defined(__x86_64__) && !defined(__EMSCRIPTEN__)
bool have_avx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}
#endif

}  // namespace

void round_fields(const float* x, std::size_t count, double scale, std::int64_t* out) {
#if defined(__x86_64__) && !defined(__EMSCRIPTEN__)
  if (have_avx2()) {
    round_fields_avx2(x, count, scale, out);
    return;
  }
#endif
  for (std::size_t i = 0; i < count; ++i) out[i] = to_field(x[i], scale);
}

std::int64_t round_field(float x, double scale) { return to_field(x, scale); }

void round_scale_fields(const float* x, std::size_t count, double round_scale, double out_scale, float* out) {
#if defined(__x86_64__) && !defined(__EMSCRIPTEN__)
  if (have_avx2()) {
    round_scale_fields_avx2(x, count, round_scale, out_scale, out);
    return;
  }
#endif
  for (std::size_t i = 0; i < count; ++i)
    out[i] = static_cast<float>(static_cast<double>(to_field(x[i], round_scale)) * out_scale);
}

void scale_fields(const std::int64_t* v, std::size_t count, double scale, float* out) {
#if defined(__x86_64__) && !defined(__EMSCRIPTEN__)
  if (have_avx2()) {
    scale_fields_avx2(v, count, scale, out);
    return;
  }
#endif
  for (std::size_t i = 0; i < count; ++i) out[i] = static_cast<float>(static_cast<double>(v[i]) * scale);
}

}  // namespace ocean::codec
