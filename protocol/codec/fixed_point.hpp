// Fixed-point primitives of the prediction path: wrapping int64 add/sub and rounded Q-format
// products through a 128-bit intermediate. Wrapping makes hostile input produce garbage, never UB.
#pragma once

#include <cstdint>

namespace ocean::codec {

inline std::int64_t wadd(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b));
}
inline std::int64_t wsub(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) - static_cast<std::uint64_t>(b));
}
inline std::int64_t wshl(std::int64_t a, int s) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) << s);
}

// floor(p / 2^s + 1/2) truncated to 64 bits (two's complement); s >= 1.
inline std::int64_t round_shift(__int128 p, int s) {
  return static_cast<std::int64_t>((p + (static_cast<__int128>(1) << (s - 1))) >> s);
}
// The same bits in 64-bit arithmetic: adding half and flooring carries exactly bit s - 1 of p.
inline std::int64_t round_shift64(std::int64_t p, int s) { return wadd(p >> s, (p >> (s - 1)) & 1); }

// round_shift(a * x + b * y, 30) for |x|, |y| <= 2^30 (the FFT's twiddles), in 64-bit products
// only: the same bits, since a = ah * 2^32 + al splits the exact sum into 4 * (ah x + bh y) +
// (al x + bl y + 2^29) / 2^30, neither part of which overflows. WebAssembly has no 64 x 64 -> 128
// multiply: the 128-bit form costs a library call per product there (4x the native decode time).
inline std::int64_t dot_round30(std::int64_t a, std::int64_t x, std::int64_t b, std::int64_t y) {
  const std::int64_t high = (a >> 32) * x + (b >> 32) * y;  // |high| <= 2^62
  const std::int64_t low = (a & 0xffffffff) * x + (b & 0xffffffff) * y + (std::int64_t{1} << 29);  // |low| < 2^63
  return wadd(wshl(high, 2), low >> 30);
}

// round(a * b / 2^s) with ties away from zero, so that x and -x give exactly opposite results
// (keeps Hermitian pairs exact).
// For p < 0, -floor((-p + h) / 2^s) = floor((p + h - 1) / 2^s) with h = 2^(s-1): one add and one
// shift instead of negating the 128-bit product twice (the decoder does this for every mode of
// every channel).
// v / d rounded half away from zero (d >= 1), so -v gives the opposite result.
inline std::int64_t div_round_sym(std::int64_t v, std::uint64_t d) {
  const std::uint64_t magnitude = v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
  const std::uint64_t q = magnitude / d + (magnitude % d >= d - d / 2 ? 1 : 0);
  return v < 0 ? static_cast<std::int64_t>(0 - q) : static_cast<std::int64_t>(q);
}

inline std::int64_t mul_round_sym(std::int64_t a, std::int64_t b, int s) {
  const __int128 p = static_cast<__int128>(a) * b;
  const __int128 neg = p >> 127;  // 0 or -1; branch-free because signs are random here
  return static_cast<std::int64_t>((p + (static_cast<__int128>(1) << (s - 1)) + neg) >> s);
}

}  // namespace ocean::codec
