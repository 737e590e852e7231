// Deterministic elementary functions for the codec's coefficient tables and its scene model: built
// from + - * / and sqrt in double only (all correctly rounded by IEEE 754), plus exact operations
// (floor, frexp, ldexp, comparisons), evaluated in a fixed order with fixed loop counts, so every
// CPU, compiler and language gets the same bits (compile with -ffp-contract=off). The exact
// operation order is normative: CODEC.md sections 3 and 7.6. Not for hot loops
// (det_cos_sin is the batched form for the scene model's per-tick phases).
#pragma once

#include <cstddef>
#include <cstdint>

namespace ocean::model {

inline constexpr double kTwoPi = 6.283185307179586;  // nearest double to 2 pi
inline constexpr double kPi = 3.141592653589793;     // nearest double to pi (= kTwoPi / 2 exactly)
inline constexpr double kHalfPi = 1.5707963267948966;  // nearest double to pi / 2 (= kTwoPi / 4)

double det_cos(double x);
double det_sin(double x);
double det_exp_neg(double y);  // e^-y for y >= 0
double det_tanh(double x);     // x >= 0

// cos_out[i] = det_cos(x[i]), sin_out[i] = det_sin(x[i]) bit for bit; written so the series loops
// vectorise across elements.
void det_cos_sin(const double* x, std::size_t count, double* cos_out, double* sin_out);

// x - m kTwoPi in [-kPi, kPi], exactly (fmod is exact): IEEE remainder(x, kTwoPi) as the sim wraps
// angles, except that a tie (|result| = kPi) keeps fmod's sign.
double det_wrap_angle(double x);

// Natural logarithm, x > 0 (0 -> -inf, inf -> inf, negative or NaN -> NaN).
double det_log(double x);
// e^x for any x: above 710 inf, below -746 0; NaN stays NaN.
double det_exp(double x);
// x^y = det_exp(y det_log(x)) for x > 0; relative error grows with |y ln x| (about |y ln x| 2^-52).
double det_pow(double x, double y);
// atan2 for finite arguments; (+-0, +-0) gives +0 and y = -0 gives +0 or +pi (libm keeps the signs).
double det_atan2(double y, double x);
// ln Gamma(x), x > 0: shifted up to at least 16, then Stirling's series.
double det_log_gamma(double x);
double det_cosh(double x);

// floor(x * 2^q + 1/2) as int64; |x * 2^q| must stay below 2^62.
std::int64_t to_fixed(double x, int q);

}  // namespace ocean::model
