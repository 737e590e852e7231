// FloatFft: the radix-2 inverse FFT of synthesis in IEEE binary32 (CODEC.md 4.2). Float add,
// subtract and multiply are correctly rounded on every CPU a client runs on (x86 SSE/AVX, ARM,
// WebAssembly), so with the order of operations fixed and nothing fused or reassociated (the codec
// builds with -ffp-contract=off) every implementation gives the same bits, four or eight lanes at a
// time: several times the speed of the int64 transform it replaces in codec version 4.
#pragma once

#include <cstddef>
#include <vector>

namespace ocean::codec {

class FloatFft {
 public:
  explicit FloatFft(int n);  // n a power of two, 4..4096

  int size() const { return n_; }

  // In place on an n x n row-major complex array: rows first, then columns; e^{+2 pi i m.k / n},
  // no 1/n^2.
  void inverse_2d(float* re, float* im);

  const std::vector<float>& cos_table() const { return cos_; }
  const std::vector<float>& sin_table() const { return sin_; }

 private:
  int n_;
  std::vector<float> cos_, sin_;  // float(det_cos(2 pi j / n)), j < n/2, likewise sin
  std::vector<int> bitrev_;
  std::vector<float> block_;      // eight rows at a time, transposed
};

}  // namespace ocean::codec
