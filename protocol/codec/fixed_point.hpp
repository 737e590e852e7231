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
inline std::int64_t round_shift64(std::int64_t p, int s) { return round_shift(static_cast<__int128>(p), s); }

// round(a * b / 2^s) with ties away from zero, so that x and -x give exactly opposite results
// (keeps Hermitian pairs exact).
inline std::int64_t mul_round_sym(std::int64_t a, std::int64_t b, int s) {
  const __int128 p = static_cast<__int128>(a) * b;
  const __int128 neg = p >> 127;  // 0 or -1; branch-free because signs are random here
  const __int128 mag = (p ^ neg) - neg;
  const __int128 r = (mag + (static_cast<__int128>(1) << (s - 1))) >> s;
  return static_cast<std::int64_t>((r ^ neg) - neg);
}

}  // namespace ocean::codec
