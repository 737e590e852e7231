// Codec version 4's binary32 synthesis path against transcriptions of CODEC.md 4.2 and 7.2: the
// FFT (whose stages the implementation fuses in pairs and vectorizes) and both field conversions
// (AVX2 where the CPU has it) must give the definitions' bits.
#include "det_math.hpp"
#include "field_conversion.hpp"
#include "float_bits.hpp"
#include "float_fft.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace ocean::codec;
namespace model = ocean::model;

namespace {

// CODEC.md 4.2 as written: bit reversal, then radix-2 stages, one stage after the other.
void reference_1d(std::vector<float>& re, std::vector<float>& im, int n) {
  int bits = 0;
  while ((1 << bits) < n) ++bits;
  for (int i = 0; i < n; ++i) {
    int r = 0;
    for (int b = 0; b < bits; ++b)
      if (i & (1 << b)) r |= 1 << (bits - 1 - b);
    if (r > i) {
      std::swap(re[i], re[r]);
      std::swap(im[i], im[r]);
    }
  }
  for (int len = 2; len <= n; len <<= 1) {
    const int half = len / 2, stride = n / len;
    for (int start = 0; start < n; start += len)
      for (int j = 0; j < half; ++j) {
        const int a = start + j, b = a + half;
        float wr = 1.0f, wi = 0.0f;
        if (4 * j == len) {
          wr = 0.0f;
          wi = 1.0f;
        } else if (j != 0) {
          const double angle = ocean::model::kTwoPi * (j * stride) / n;
          wr = static_cast<float>(model::det_cos(angle));
          wi = static_cast<float>(model::det_sin(angle));
        }
        const float p = re[b] * wr, q = im[b] * wi, u = re[b] * wi, v = im[b] * wr;
        const float tr = p - q, ti = u + v;
        const float ar = re[a], ai = im[a];
        re[b] = ar - tr;
        im[b] = ai - ti;
        re[a] = ar + tr;
        im[a] = ai + ti;
      }
  }
}

void reference_2d(std::vector<float>& re, std::vector<float>& im, int n) {
  std::vector<float> r(n), i(n);
  for (int row = 0; row < n; ++row) {
    for (int c = 0; c < n; ++c) r[c] = re[row * n + c], i[c] = im[row * n + c];
    reference_1d(r, i, n);
    for (int c = 0; c < n; ++c) re[row * n + c] = r[c], im[row * n + c] = i[c];
  }
  for (int col = 0; col < n; ++col) {
    for (int k = 0; k < n; ++k) r[k] = re[k * n + col], i[k] = im[k * n + col];
    reference_1d(r, i, n);
    for (int k = 0; k < n; ++k) re[k * n + col] = r[k], im[k * n + col] = i[k];
  }
}

using ocean::codec::test::same_bits;

}  // namespace

TEST_CASE("the binary32 inverse FFT gives CODEC.md 4.2's bits at every size a stream can have") {
  for (int n : {4, 8, 16, 32, 64, 128, 256}) {
    FloatFft fft(n);
    std::mt19937_64 rng(static_cast<std::uint64_t>(n) * 7);
    // Values as synthesis makes them (int64 state through double), a sparse spectrum with exact
    // zeros of both signs, tiny and huge magnitudes together, and infinities.
    for (int kind = 0; kind < 4; ++kind) {
      std::vector<float> re(static_cast<std::size_t>(n) * n), im(re.size());
      for (auto* v : {&re, &im})
        for (auto& x : *v) {
          const auto bits = static_cast<std::int64_t>(rng() >> 20) - (std::int64_t{1} << 43);
          x = kind == 1 && rng() % 3 ? (rng() % 2 ? 0.0f : -0.0f)
              : kind == 3 && rng() % 50 == 0 ? (rng() % 2 ? 1.0f : -1.0f) * std::numeric_limits<float>::infinity()
              : kind == 2            ? static_cast<float>(std::ldexp(static_cast<double>(bits), static_cast<int>(rng() % 60) - 40))
                                     : static_cast<float>(static_cast<double>(bits));
        }
      auto ref_re = re, ref_im = im;
      reference_2d(ref_re, ref_im, n);
      fft.inverse_2d(re.data(), im.data());
      INFO("n " << n << " kind " << kind);
      CHECK(same_bits(re, ref_re));
      CHECK(same_bits(im, ref_im));
    }
  }
}

TEST_CASE("fields round to the nearest integer, ties to even, saturated, NaN to 0") {
  const double scale = std::ldexp(1.0, -16);
  constexpr float kInf = std::numeric_limits<float>::infinity();
  std::vector<float> x = {0.0f, -0.0f, 0.5f * 65536, 1.5f * 65536, 2.5f * 65536, -0.5f * 65536, -1.5f * 65536,
                          0.49999997f * 65536, 3e30f, -3e30f, kInf, -kInf, std::numeric_limits<float>::quiet_NaN(),
                          1e-30f, 123456789.0f, -98765432.0f};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> any(-1e12f, 1e12f);
  for (int i = 0; i < 10001; ++i) x.push_back(any(rng));  // an odd count: the vector loop's tail too
  std::vector<std::int64_t> out(x.size());
  round_fields(x.data(), x.size(), scale, out.data());
  const double limit = std::ldexp(1.0, 51) - 1;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double y = static_cast<double>(x[k]) * scale;
    const double want = std::isnan(y) ? 0.0 : std::nearbyint(std::fmax(-limit, std::fmin(limit, y)));
    INFO("x " << x[k]);
    REQUIRE(out[k] == static_cast<std::int64_t>(want));
  }
  CHECK(out[2] == 0);   // 0.5: ties to even
  CHECK(out[3] == 2);   // 1.5
  CHECK(out[4] == 2);   // 2.5
  CHECK(out[5] == 0);
  CHECK(out[6] == -2);
  CHECK(out[10] == static_cast<std::int64_t>(limit));
  CHECK(out[12] == 0);
}

TEST_CASE("fields scale to output floats as float(double(v) * scale), beyond 2^51 too") {
  const double scale = 0.01 / 65536.0;
  std::vector<std::int64_t> v = {0, 1, -1, std::int64_t{1} << 51, -(std::int64_t{1} << 51), (std::int64_t{1} << 51) + 1,
                                 std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max()};
  std::mt19937_64 rng(9);
  for (int i = 0; i < 10001; ++i) v.push_back(static_cast<std::int64_t>(rng()) >> (rng() % 40));
  std::vector<float> out(v.size());
  scale_fields(v.data(), v.size(), scale, out.data());
  for (std::size_t k = 0; k < v.size(); ++k) {
    INFO("v " << v[k]);
    REQUIRE(out[k] == static_cast<float>(static_cast<double>(v[k]) * scale));
  }
}

TEST_CASE("rounding and scaling in one pass gives the floats of the two passes, in and beyond 32 bits") {
  const double round_scale = std::ldexp(1.0, -16), out_scale = 0.01 / 65536.0;
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const float two31 = std::ldexp(1.0f, 31) * 65536.0f;
  std::vector<float> x = {0.0f, -0.0f, 0.5f * 65536, 1.5f * 65536, -2.5f * 65536, 3e30f, -3e30f, kInf, -kInf,
                          std::numeric_limits<float>::quiet_NaN(), 1e-40f, -1e-45f, two31, -two31,
                          std::nextafter(two31, 0.0f), -std::nextafter(two31, 0.0f), (std::ldexp(1.0f, 31) - 128.0f) * 65536};
  std::mt19937_64 rng(11);
  for (int i = 0; i < 20003; ++i) {
    const float mantissa = std::uniform_real_distribution<float>(-2.0f, 2.0f)(rng);
    x.push_back(std::ldexp(mantissa, static_cast<int>(rng() % 80) - 20));  // 2^-20 .. 2^59 in field units x 2^16
  }
  std::vector<std::int64_t> v(x.size());
  std::vector<float> two_passes(x.size()), one_pass(x.size());
  round_fields(x.data(), x.size(), round_scale, v.data());
  scale_fields(v.data(), v.size(), out_scale, two_passes.data());
  round_scale_fields(x.data(), x.size(), round_scale, out_scale, one_pass.data());
  for (std::size_t k = 0; k < x.size(); ++k) {
    INFO("x " << x[k]);
    REQUIRE(std::memcmp(&one_pass[k], &two_passes[k], sizeof(float)) == 0);
    REQUIRE(round_field(x[k], round_scale) == v[k]);
  }
}

TEST_CASE("FloatFft refuses sizes that are not powers of two of at least 4") {
  CHECK_THROWS_AS(FloatFft(2), std::invalid_argument);
  CHECK_THROWS_AS(FloatFft(24), std::invalid_argument);
}
