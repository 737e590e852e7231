// Radix-2 decimation-in-time FFT in int64 with one rounding per twiddle product (CODEC.md 4).
#include "fixed_fft.hpp"

#include "bit_reversal.hpp"
#include "det_math.hpp"
#include "fixed_fft_avx2.hpp"
#include "fixed_point.hpp"

#include <stdexcept>
#include <string>
#include <algorithm>
#include <utility>

namespace ocean::codec {

FixedFft::FixedFft(int n) : n_(n) {
  if (n < 2 || n > 4096 || (n & (n - 1)) != 0)
    throw std::invalid_argument("FixedFft: size must be a power of two in [2, 4096], got " + std::to_string(n));
  cos_.resize(n / 2);
  sin_.resize(n / 2);
  for (int j = 0; j < n / 2; ++j) {
    const double angle = model::kTwoPi * j / n;
    cos_[j] = model::to_fixed(model::det_cos(angle), kTwiddleBits);
    sin_[j] = model::to_fixed(model::det_sin(angle), kTwiddleBits);
  }
  bitrev_ = bit_reversal(n);
  // The exact shortcuts in the butterflies rely on w(n/4) = (0, 1) exactly.
  if (n >= 4 && (cos_[n / 4] != 0 || sin_[n / 4] != (std::int64_t{1} << kTwiddleBits)))
    throw std::logic_error("FixedFft: twiddle table is not exact at a quarter turn");
  if (kernel_available(FftKernel::avx2, n)) use_kernel(FftKernel::avx2);
}

bool FixedFft::kernel_available(FftKernel kernel, int n) {
  switch (kernel) {
    case FftKernel::scalar:
      return true;
    case FftKernel::avx2:
      return n >= 4 && fft_avx2::available();  // four lanes need four rows and columns
  }
  return false;
}

void FixedFft::use_kernel(FftKernel kernel) {
  if (!kernel_available(kernel, n_))
    throw std::invalid_argument("FixedFft: this CPU or build cannot run the requested kernel at size " + std::to_string(n_));
  kernel_ = kernel;
  if (kernel == FftKernel::avx2) scratch_.resize(static_cast<std::size_t>(8) * n_);
}

namespace {

// t = b * w rounded (CODEC.md 4). j == 0 (w = 1) and 4j == len (w = -+i) are exact, so their
// shortcuts give the same bits as the general product.
struct Twiddled {
  std::int64_t re, im;
};
static_assert(FixedFft::kTwiddleBits == 30, "dot_round30 rounds at 2^30 and needs |w| <= 2^30");
inline Twiddled twiddle(std::int64_t br, std::int64_t bi, std::int64_t wr, std::int64_t wi) {
  return {dot_round30(br, wr, bi, -wi), dot_round30(br, wi, bi, wr)};
}

// (a, b) <- (a + t, a - t); t is passed by value, so it may be computed from b.
inline void butterfly(std::int64_t& ar, std::int64_t& ai, std::int64_t& br, std::int64_t& bi, std::int64_t tr,
                      std::int64_t ti) {
  br = wsub(ar, tr);
  bi = wsub(ai, ti);
  ar = wadd(ar, tr);
  ai = wadd(ai, ti);
}

}  // namespace

void FixedFft::transform_1d(std::int64_t* re, std::int64_t* im, bool inverse) const {
  const int n = n_;
  for (int i = 0; i < n; ++i) {
    const int r = bitrev_[i];
    if (r > i) {
      std::swap(re[i], re[r]);
      std::swap(im[i], im[r]);
    }
  }
  // Same butterflies as CODEC.md 4, visited twiddle-major so the exact cases are hoisted.
  for (int len = 2; len <= n; len <<= 1) {
    const int half = len >> 1;
    const int stride = n / len;
    for (int j = 0; j < half; ++j) {
      if (j == 0) {
        for (int a = 0; a < n; a += len) butterfly(re[a], im[a], re[a + half], im[a + half], re[a + half], im[a + half]);
      } else if (4 * j == len) {
        if (inverse)
          for (int a = j; a < n; a += len)
            butterfly(re[a], im[a], re[a + half], im[a + half], wsub(0, im[a + half]), re[a + half]);
        else
          for (int a = j; a < n; a += len)
            butterfly(re[a], im[a], re[a + half], im[a + half], im[a + half], wsub(0, re[a + half]));
      } else {
        const std::int64_t wr = cos_[j * stride];
        const std::int64_t wi = inverse ? sin_[j * stride] : -sin_[j * stride];
        for (int a = j; a < n; a += len) {
          const Twiddled t = twiddle(re[a + half], im[a + half], wr, wi);
          butterfly(re[a], im[a], re[a + half], im[a + half], t.re, t.im);
        }
      }
    }
  }
}

void FixedFft::transform_2d(std::int64_t* re, std::int64_t* im, bool inverse) {
  const int n = n_;
  if (kernel_ == FftKernel::avx2) {
    fft_avx2::transform_2d({n, cos_.data(), sin_.data(), bitrev_.data()}, re, im, inverse, scratch_.data());
    return;
  }
  for (int r = 0; r < n; ++r) transform_1d(re + r * n, im + r * n, inverse);
  // Columns: the same butterflies with whole rows as the unit, so memory is walked contiguously.
  for (int i = 0; i < n; ++i) {
    const int r = bitrev_[i];
    if (r > i) {
      std::swap_ranges(re + i * n, re + i * n + n, re + r * n);
      std::swap_ranges(im + i * n, im + i * n + n, im + r * n);
    }
  }
  for (int len = 2; len <= n; len <<= 1) {
    const int half = len >> 1;
    const int stride = n / len;
    for (int start = 0; start < n; start += len) {
      for (int j = 0; j < half; ++j) {
        std::int64_t* ar = re + (start + j) * n;
        std::int64_t* ai = im + (start + j) * n;
        std::int64_t* br = ar + half * n;
        std::int64_t* bi = ai + half * n;
        const std::int64_t wr = cos_[j * stride];
        const std::int64_t wi = inverse ? sin_[j * stride] : -sin_[j * stride];
        if (j == 0) {
          for (int x = 0; x < n; ++x) butterfly(ar[x], ai[x], br[x], bi[x], br[x], bi[x]);
        } else if (4 * j == len) {
          if (inverse)
            for (int x = 0; x < n; ++x) butterfly(ar[x], ai[x], br[x], bi[x], wsub(0, bi[x]), br[x]);
          else
            for (int x = 0; x < n; ++x) butterfly(ar[x], ai[x], br[x], bi[x], bi[x], wsub(0, br[x]));
        } else {
          for (int x = 0; x < n; ++x) {
            const Twiddled t = twiddle(br[x], bi[x], wr, wi);
            butterfly(ar[x], ai[x], br[x], bi[x], t.re, t.im);
          }
        }
      }
    }
  }
}

}  // namespace ocean::codec
