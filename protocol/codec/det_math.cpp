// Deterministic cos/sin/exp/tanh: range reduction plus fixed-length Taylor series (see CODEC.md 3).
#include "det_math.hpp"

#include <cmath>

namespace ocean::codec {
namespace {

// 2 pi = kTwoPiHi + kTwoPiLo to about 1e-32, so x - n 2pi is accurate for the |x| we meet.
constexpr double kTwoPiLo = 2.4492935982947064e-16;

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
  for (int j = 28; j >= 1; --j) acc = 1.0 - acc * r2 / static_cast<double>((2 * j - 1) * (2 * j));
  return acc;
}

double det_sin(double x) {
  const double r = reduce(x);
  const double r2 = r * r;
  // r (1 - r2/(2*3) (1 - r2/(4*5) (1 - ...))), 28 terms.
  double acc = 1.0;
  for (int j = 28; j >= 1; --j) {
    const double denom = static_cast<double>((2 * j) * (2 * j + 1));
    acc = 1.0 - acc * r2 / denom;
  }
  return r * acc;
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

double det_angular_frequency(double k, double gravity, double depth_m) {
  if (!(k > 0.0)) return 0.0;
  const double t = depth_m > 0.0 ? det_tanh(k * depth_m) : 1.0;
  return std::sqrt(gravity * k * t);
}

std::int64_t to_fixed(double x, int q) {
  return static_cast<std::int64_t>(std::floor(std::ldexp(x, q) + 0.5));
}

}  // namespace ocean::codec
