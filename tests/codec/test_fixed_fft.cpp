// The fixed-point FFT against a double-precision DFT, and its inverse round trip; its twiddle product
// in 64-bit arithmetic against the 128-bit one.
#include "fixed_fft.hpp"
#include "fixed_point.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <limits>
#include <random>
#include <vector>

using namespace ocean::codec;

namespace {

std::vector<std::complex<double>> reference_dft_2d(const std::vector<std::int64_t>& re, const std::vector<std::int64_t>& im,
                                                   int n, double sign) {
  std::vector<std::complex<double>> out(n * n);
  const double pi2 = 2.0 * M_PI;
  for (int kz = 0; kz < n; ++kz)
    for (int kx = 0; kx < n; ++kx) {
      std::complex<double> acc = 0;
      for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
          const double a = sign * pi2 * double((kx * x + kz * z) % n) / n;
          acc += std::complex<double>(double(re[z * n + x]), double(im[z * n + x])) * std::polar(1.0, a);
        }
      out[kz * n + kx] = acc;
    }
  return out;
}

}  // namespace

TEST_CASE("forward and inverse 2-D FFT match a double DFT to within a few units") {
  for (int n : {8, 16}) {
    FixedFft fft(n);
    std::mt19937_64 rng(n);
    std::uniform_int_distribution<std::int64_t> val(-(std::int64_t{1} << 40), std::int64_t{1} << 40);
    std::vector<std::int64_t> re(n * n), im(n * n);
    for (auto& v : re) v = val(rng);
    for (auto& v : im) v = val(rng);
    for (bool inverse : {false, true}) {
      auto ref = reference_dft_2d(re, im, n, inverse ? 1.0 : -1.0);
      auto r = re, i = im;
      if (inverse)
        fft.inverse_2d(r.data(), i.data());
      else
        fft.forward_2d(r.data(), i.data());
      double worst = 0.0, scale = 0.0;
      for (int k = 0; k < n * n; ++k) {
        worst = std::max(worst, std::abs(std::complex<double>(double(r[k]), double(i[k])) - ref[k]));
        scale = std::max(scale, std::abs(ref[k]));
      }
      INFO("n " << n << " inverse " << inverse << " worst " << worst << " scale " << scale);
      // Q30 twiddles: relative error ~ log2(n^2) * 2^-30.
      CHECK(worst <= scale * 1e-8);
    }
  }
}

TEST_CASE("inverse(forward(x)) / n^2 returns x within two units (one rounding per stage)") {
  const int n = 64;
  FixedFft fft(n);
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<std::int64_t> val(-(std::int64_t{1} << 30), std::int64_t{1} << 30);
  std::vector<std::int64_t> re(n * n), im(n * n, 0), orig(n * n);
  for (int k = 0; k < n * n; ++k) orig[k] = re[k] = val(rng);
  fft.forward_2d(re.data(), im.data());
  fft.inverse_2d(re.data(), im.data());
  std::int64_t worst = 0;
  for (int k = 0; k < n * n; ++k) {
    const std::int64_t back = (re[k] + (std::int64_t{1} << 11)) >> 12;
    worst = std::max<std::int64_t>(worst, std::llabs(back - orig[k]));
  }
  CHECK(worst <= 2);
}

TEST_CASE("FixedFft refuses sizes that are not powers of two") {
  CHECK_THROWS_AS(FixedFft(12), std::invalid_argument);
  CHECK_THROWS_AS(FixedFft(1), std::invalid_argument);
}

TEST_CASE("dot_round30 gives the 128-bit product's bits for any int64 inputs and twiddle-sized factors") {
  const auto reference = [](std::int64_t a, std::int64_t x, std::int64_t b, std::int64_t y) {
    return ocean::codec::round_shift(static_cast<__int128>(a) * x + static_cast<__int128>(b) * y, 30);
  };
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min(), kMax = std::numeric_limits<std::int64_t>::max();
  constexpr std::int64_t kOne = std::int64_t{1} << 30;
  const std::int64_t values[] = {0, 1, -1, kMin, kMax, kMin + 1, kMax - 1, std::int64_t{1} << 32, -(std::int64_t{1} << 32),
                                 (std::int64_t{1} << 32) - 1, std::int64_t{0xffffffff} << 31, kOne, -kOne, 12345678901234};
  const std::int64_t factors[] = {0, 1, -1, kOne, -kOne, kOne - 1, -(kOne - 1), 759250125, -759250125};
  int checked = 0;
  for (const std::int64_t a : values)
    for (const std::int64_t b : values)
      for (const std::int64_t x : factors)
        for (const std::int64_t y : factors) {
          REQUIRE(ocean::codec::dot_round30(a, x, b, y) == reference(a, x, b, y));
          ++checked;
        }
  std::mt19937_64 random(42);
  for (int i = 0; i < 200000; ++i) {
    const auto a = static_cast<std::int64_t>(random()), b = static_cast<std::int64_t>(random());
    const std::int64_t x = static_cast<std::int64_t>(random() % (2 * kOne + 1)) - kOne;
    const std::int64_t y = static_cast<std::int64_t>(random() % (2 * kOne + 1)) - kOne;
    REQUIRE(ocean::codec::dot_round30(a, x, b, y) == reference(a, x, b, y));
    ++checked;
  }
  CHECK(checked > 200000);
}

TEST_CASE("the AVX2 kernel gives the scalar butterflies' bits, wrapping included") {
  for (int n : {4, 8, 16, 64, 256}) {
    if (!FixedFft::kernel_available(FftKernel::avx2, n)) {
      WARN("no AVX2 on this CPU or build: only the scalar kernel is tested");
      return;
    }
    FixedFft simd(n), scalar(n);
    simd.use_kernel(FftKernel::avx2);
    scalar.use_kernel(FftKernel::scalar);
    std::mt19937_64 rng(n);
    // Decoder-sized values, then any int64 (hostile streams wrap; they must wrap alike).
    for (int bits : {40, 64}) {
      std::vector<std::int64_t> re(n * n), im(n * n);
      for (auto* v : {&re, &im})
        for (auto& x : *v) x = bits == 64 ? static_cast<std::int64_t>(rng()) : static_cast<std::int64_t>(rng() >> 24) - (std::int64_t{1} << 39);
      if (bits == 64) {
        re[0] = std::numeric_limits<std::int64_t>::min();
        im[1] = std::numeric_limits<std::int64_t>::max();
      }
      for (bool inverse : {false, true}) {
        auto ar = re, ai = im, br = re, bi = im;
        if (inverse) {
          simd.inverse_2d(ar.data(), ai.data());
          scalar.inverse_2d(br.data(), bi.data());
        } else {
          simd.forward_2d(ar.data(), ai.data());
          scalar.forward_2d(br.data(), bi.data());
        }
        INFO("n " << n << " bits " << bits << " inverse " << inverse);
        CHECK(ar == br);
        CHECK(ai == bi);
      }
    }
  }
}

TEST_CASE("a kernel the CPU cannot run is refused by name") {
  FixedFft fft(2);
  CHECK_FALSE(FixedFft::kernel_available(FftKernel::avx2, 2));
  CHECK_THROWS_AS(fft.use_kernel(FftKernel::avx2), std::invalid_argument);
  fft.use_kernel(FftKernel::scalar);
  CHECK(fft.kernel() == FftKernel::scalar);
}

TEST_CASE("mul_round_sym and round_shift64 give their 128-bit definitions' bits for any int64 inputs") {
  // CODEC.md 4 and 7: round(a b / 2^s), ties away from zero; floor(p / 2^s + 1/2).
  const auto sym = [](std::int64_t a, std::int64_t b, int s) {
    const __int128 p = static_cast<__int128>(a) * b;
    const __int128 mag = p < 0 ? -p : p;
    const __int128 r = (mag + (static_cast<__int128>(1) << (s - 1))) >> s;
    return static_cast<std::int64_t>(p < 0 ? -r : r);
  };
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min(), kMax = std::numeric_limits<std::int64_t>::max();
  std::vector<std::int64_t> values = {0, 1, -1, 2, -2, 3, -3, kMin, kMax, kMin + 1, kMax - 1, std::int64_t{1} << 31,
                                      -(std::int64_t{1} << 31), std::int64_t{1} << 47, -(std::int64_t{1} << 47),
                                      (std::int64_t{1} << 48) + 1, -(std::int64_t{1} << 48) - 1};
  std::mt19937_64 random(7);
  for (int i = 0; i < 400; ++i) values.push_back(static_cast<std::int64_t>(random()) >> (random() % 64));
  int checked = 0;
  for (const int s : {1, 12, 16, 24, 32, 48, 62})
    for (const std::int64_t a : values) {
      REQUIRE(round_shift64(a, s) == round_shift(static_cast<__int128>(a), s));
      for (const std::int64_t b : values) {
        REQUIRE(mul_round_sym(a, b, s) == sym(a, b, s));
        ++checked;
      }
    }
  CHECK(checked > 1000000);
}
