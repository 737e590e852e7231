// FixedFft: radix-2 complex FFT on int64 fixed-point data with Q30 twiddles from det_math, so the
// decoder's spectral transforms give identical bits on every CPU. Unnormalized in both directions.
// The 2-D transform runs four lanes at a time where the CPU has AVX2 (fixed_fft_avx2.hpp), with the
// same bits as the scalar butterflies.
#pragma once

#include <cstdint>
#include <vector>

namespace ocean::codec {

enum class FftKernel { scalar, avx2 };

class FixedFft {
 public:
  static constexpr int kTwiddleBits = 30;

  explicit FixedFft(int n);  // n a power of two, 2..4096; the fastest kernel this CPU has

  // Whether this build and CPU can run `kernel` on an n x n transform.
  static bool kernel_available(FftKernel kernel, int n);
  // Pins the kernel (tests, benchmarks); std::invalid_argument where it is not available.
  void use_kernel(FftKernel kernel);
  FftKernel kernel() const { return kernel_; }

  int size() const { return n_; }

  // In place on an n x n row-major complex array (re, im): rows first, then columns.
  // forward: X[k] = sum x[m] e^{-2 pi i m.k / n};  inverse: the same with e^{+...} (no 1/n^2).
  void forward_2d(std::int64_t* re, std::int64_t* im) { transform_2d(re, im, false); }
  void inverse_2d(std::int64_t* re, std::int64_t* im) { transform_2d(re, im, true); }

  // One length-n transform of contiguous data.
  void transform_1d(std::int64_t* re, std::int64_t* im, bool inverse) const;

  const std::vector<std::int64_t>& cos_table() const { return cos_; }
  const std::vector<std::int64_t>& sin_table() const { return sin_; }

 private:
  void transform_2d(std::int64_t* re, std::int64_t* im, bool inverse);

  int n_;
  std::vector<std::int64_t> cos_, sin_;  // round(2^30 cos(2 pi j / n)), j < n/2, likewise sin
  std::vector<int> bitrev_;
  FftKernel kernel_ = FftKernel::scalar;
  std::vector<std::int64_t> scratch_;  // the AVX2 kernel's row blocks
};

}  // namespace ocean::codec
