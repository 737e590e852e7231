// Deterministic elementary functions: argument reduction by exact scalings or a split constant,
// then a fixed-length series in Horner form (see CODEC.md 3 and 7.6).
#include "det_math.hpp"

#include <cmath>
#include <limits>

namespace ocean::model {
namespace {

// 2 pi = kTwoPiHi + kTwoPiLo to about 1e-32, so x - n 2pi is accurate for the |x| we meet.
constexpr double kTwoPiLo = 2.4492935982947064e-16;
// ln 2 split so that k * kLn2Hi is exact for |k| < 2^11 (kLn2Hi has 32 significant bits).
constexpr double kLn2Hi = 0.69314718036912382;
constexpr double kLn2Lo = 1.9082149292705877e-10;
constexpr double kInvLn2 = 1.4426950408889634;
constexpr double kSqrtHalf = 0.70710678118654757;
constexpr double kHalfLog2Pi = 0.91893853320467278;  // ln(2 pi) / 2
// Stirling's series B_2j / (2j (2j - 1)), j = 1..8.
constexpr double kStirling[8] = {0.083333333333333329,  -0.0027777777777777779, 0.00079365079365079365,
                                 -0.00059523809523809529, 0.00084175084175084171, -0.0019175269175269176,
                                 0.0064102564102564100,  -0.029550653594771242};

constexpr int kTrigTerms = 28;
constexpr int kExpTerms = 16;
constexpr int kLogTerms = 12;
constexpr int kAtanTerms = 12;
constexpr double kLogGammaShift = 16.0;

// Reduce x to r in about [-pi, pi]; std::floor is exact, so this is deterministic.
double reduce(double x) {
  const double n = std::floor(x / kTwoPi + 0.5);
  return (x - n * kTwoPi) - n * kTwoPiLo;
}

}  // namespace

double det_cos(double x) {
  const double r = reduce(x);
  const double r2 = r * r;
  // 1 - r2/(1*2) (1 - r2/(3*4) (1 - ...)), 28 terms, Horner from the innermost; |r| <= pi leaves
  // a remainder far below one ulp.
  double acc = 1.0;
  for (int j = kTrigTerms; j >= 1; --j) acc = 1.0 - acc * r2 / static_cast<double>((2 * j - 1) * (2 * j));
  return acc;
}

double det_sin(double x) {
  const double r = reduce(x);
  const double r2 = r * r;
  // r (1 - r2/(2*3) (1 - r2/(4*5) (1 - ...))), 28 terms.
  double acc = 1.0;
  for (int j = kTrigTerms; j >= 1; --j) {
    const double denom = static_cast<double>((2 * j) * (2 * j + 1));
    acc = 1.0 - acc * r2 / denom;
  }
  return r * acc;
}

void det_cos_sin(const double* x, std::size_t count, double* cos_out, double* sin_out) {
  // The scalar series are one long chain of dependent divisions; a block of independent elements
  // per step keeps the divider busy (and lets the compiler use vector divisions). Each element
  // still sees exactly det_cos's and det_sin's operations.
  constexpr std::size_t kBlock = 16;
  double r[kBlock], r2[kBlock], c[kBlock], s[kBlock];
  for (std::size_t at = 0; at < count; at += kBlock) {
    const std::size_t m = count - at < kBlock ? count - at : kBlock;
    for (std::size_t i = 0; i < kBlock; ++i) {
      r[i] = i < m ? reduce(x[at + i]) : 0.0;
      r2[i] = r[i] * r[i];
      c[i] = 1.0;
      s[i] = 1.0;
    }
    for (int j = kTrigTerms; j >= 1; --j) {
      const double dc = static_cast<double>((2 * j - 1) * (2 * j));
      const double ds = static_cast<double>((2 * j) * (2 * j + 1));
      for (std::size_t i = 0; i < kBlock; ++i) {
        c[i] = 1.0 - c[i] * r2[i] / dc;
        s[i] = 1.0 - s[i] * r2[i] / ds;
      }
    }
    for (std::size_t i = 0; i < m; ++i) {
      cos_out[at + i] = c[i];
      sin_out[at + i] = r[i] * s[i];
    }
  }
}

double det_wrap_angle(double x) {
  double r = std::fmod(x, kTwoPi);
  // |r| > pi is at least half of 2 pi, so these subtractions are exact (Sterbenz).
  if (r > kPi) r = r - kTwoPi;
  else if (r < -kPi) r = r + kTwoPi;
  return r;
}

double det_exp_neg(double y) {
  if (!(y >= 0.0)) return 1.0;
  if (y > 745.0) return 0.0;
  // e^-y = (e^-(y / 2^m))^(2^m) with y / 2^m < 1/2 (exact scaling by a power of two).
  int m = 0;
  double z = y;
  while (z >= 0.5) {
    z *= 0.5;
    ++m;
  }
  double acc = 1.0;
  for (int j = 24; j >= 1; --j) acc = 1.0 - acc * z / static_cast<double>(j);
  for (int i = 0; i < m; ++i) acc *= acc;
  return acc;
}

double det_tanh(double x) {
  if (!(x > 0.0)) return 0.0;
  if (x > 20.0) return 1.0;
  const double e = det_exp_neg(2.0 * x);
  return (1.0 - e) / (1.0 + e);
}

double det_log(double x) {
  if (x != x || x < 0.0) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0.0) return -std::numeric_limits<double>::infinity();
  if (x == std::numeric_limits<double>::infinity()) return x;
  // x = m 2^e with m in [sqrt(1/2), sqrt(2)): then s = (m - 1) / (m + 1) is at most 0.172 and
  // ln m = 2 atanh(s) = 2 (s + s^3/3 + s^5/5 + ...); m - 1 is exact, so ln m keeps its relative
  // precision near x = 1.
  int e = 0;
  double m = std::frexp(x, &e);
  if (m < kSqrtHalf) {
    m = m * 2.0;
    e = e - 1;
  }
  const double f = m - 1.0;
  const double s = f / (m + 1.0);
  const double s2 = s * s;
  double acc = 0.0;
  for (int j = kLogTerms; j >= 1; --j) acc = 1.0 / static_cast<double>(2 * j + 1) + s2 * acc;
  const double t = s + s;
  const double ln_m = t + t * (s2 * acc);
  const double de = static_cast<double>(e);
  return de * kLn2Hi + (ln_m + de * kLn2Lo);
}

double det_exp(double x) {
  if (x != x) return x;
  if (x > 710.0) return std::numeric_limits<double>::infinity();
  if (x < -746.0) return 0.0;
  // x = k ln2 + r, |r| <= ln2 / 2; k * kLn2Hi is exact, so r carries no cancellation error.
  const double k = std::floor(x * kInvLn2 + 0.5);
  const double r = (x - k * kLn2Hi) - k * kLn2Lo;
  double acc = 1.0;
  for (int j = kExpTerms; j >= 1; --j) acc = 1.0 + acc * r / static_cast<double>(j);
  // Exact unless the result is subnormal or overflows; then one correct rounding.
  return std::ldexp(acc, static_cast<int>(k));
}

double det_pow(double x, double y) { return det_exp(y * det_log(x)); }

double det_atan2(double y, double x) {
  if (x != x || y != y) return std::numeric_limits<double>::quiet_NaN();
  const double ax = std::fabs(x), ay = std::fabs(y);
  if (ax == 0.0 && ay == 0.0) return 0.0;
  const bool swap = ay > ax;
  double a = swap ? ax / ay : ay / ax;  // in [0, 1]
  // atan(a) = 2 atan(a / (1 + sqrt(1 + a^2))), twice: the argument drops to tan(pi/16) < 0.2.
  for (int i = 0; i < 2; ++i) a = a / (1.0 + std::sqrt(1.0 + a * a));
  const double a2 = a * a;
  double acc = 0.0;
  for (int j = kAtanTerms; j >= 1; --j) acc = 1.0 / static_cast<double>(2 * j + 1) - a2 * acc;
  double angle = 4.0 * (a - a * (a2 * acc));
  if (swap) angle = kHalfPi - angle;
  if (x < 0.0) angle = kPi - angle;
  return y < 0.0 ? -angle : angle;
}

double det_log_gamma(double x) {
  if (x != x || x <= 0.0) return std::numeric_limits<double>::quiet_NaN();
  if (x == std::numeric_limits<double>::infinity()) return x;
  // Gamma(x) = Gamma(z) / (x (x+1) ... (z-1)) with z >= 16, where Stirling's series with 8 terms
  // is accurate to far below one ulp.
  double z = x;
  double product = 1.0;
  while (z < kLogGammaShift) {
    product = product * z;
    z = z + 1.0;
  }
  const double inv = 1.0 / z;
  const double inv2 = inv * inv;
  double series = 0.0;
  for (int j = 7; j >= 0; --j) series = kStirling[j] + inv2 * series;
  const double stirling = (((z - 0.5) * det_log(z) - z) + kHalfLog2Pi) + inv * series;
  return stirling - det_log(product);
}

double det_cosh(double x) {
  const double e = det_exp(std::fabs(x));
  return (e + 1.0 / e) * 0.5;
}

std::int64_t to_fixed(double x, int q) {
  return static_cast<std::int64_t>(std::floor(std::ldexp(x, q) + 0.5));
}

}  // namespace ocean::model
