// The bit-reversal permutation both FFTs start from (CODEC.md 4).
#pragma once

#include <vector>

namespace ocean::codec {

// r[i] = i with its log2(n) low bits reversed; n a power of two.
inline std::vector<int> bit_reversal(int n) {
  int bits = 0;
  while ((1 << bits) < n) ++bits;
  std::vector<int> r(n);
  for (int i = 0; i < n; ++i)
    for (int b = 0; b < bits; ++b)
      if (i & (1 << b)) r[i] |= 1 << (bits - 1 - b);
  return r;
}

}  // namespace ocean::codec
