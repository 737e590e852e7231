// The two arithmetics the sea model is evaluated in. The formulas are written once (spectrum,
// spreading, dispersion, amplitude draw) over an arithmetic; each side picks its own:
// - Det: the codec's reproducible functions (det_math.hpp), so every decoder - native, another
//   language, WebAssembly - predicts the same bits from a scene (CODEC.md 7.6 is normative);
// - Libm: the C library's, which the sim has always used. Measured (CONTRIBUTING, "The sea
//   model"): Det would change the sim's frames in finite depth and costs a scene change more, and the
//   sim needs no cross-platform bits, since FFTW's float transforms already differ by CPU.
// Where the two arithmetics need different formulas for the same quantity (|cos x| near pi/2,
// the length of a wavevector), the arithmetic owns the formula.
#pragma once

#include "det_math.hpp"

#include <cmath>
#include <numbers>

namespace ocean::model {

struct Libm {
  static double sin(double x) { return std::sin(x); }
  static double cos(double x) { return std::cos(x); }
  static double exp(double x) { return std::exp(x); }
  static double log(double x) { return std::log(x); }
  static double pow(double x, double y) { return std::pow(x, y); }
  static double cbrt(double x) { return std::cbrt(x); }
  static double atan2(double y, double x) { return std::atan2(y, x); }
  static double cosh(double x) { return std::cosh(x); }
  static double tanh(double x) { return std::tanh(x); }
  static double hypot(double x, double z) { return std::hypot(x, z); }
  // Into [-pi, pi] by IEEE remainder.
  static double wrap_angle(double x) { return std::remainder(x, 2.0 * std::numbers::pi); }
  // glibc's lgamma() writes the global signgam; lgamma_r() is the thread-safe form.
  static double log_gamma(double x) {
    int sign = 0;
    return ::lgamma_r(x, &sign);
  }
  // |cos x| for x in [-pi/2, pi/2].
  static double abs_cos(double x) { return std::fabs(std::cos(x)); }
};

struct Det {
  static double sin(double x) { return det_sin(x); }
  static double cos(double x) { return det_cos(x); }
  static double exp(double x) { return det_exp(x); }
  static double log(double x) { return det_log(x); }
  static double pow(double x, double y) { return det_pow(x, y); }
  static double cbrt(double x) { return det_pow(x, 1.0 / 3.0); }
  static double atan2(double y, double x) { return det_atan2(y, x); }
  static double cosh(double x) { return det_cosh(x); }
  static double tanh(double x) { return det_tanh(x); }
  static double hypot(double x, double z) { return std::sqrt(x * x + z * z); }
  static double wrap_angle(double x) { return det_wrap_angle(x); }
  static double log_gamma(double x) { return det_log_gamma(x); }
  // |cos x| as sin(pi/2 - |x|): near +-pi/2 cos x is tiny and a series for it would lose all
  // relative precision there, while libm's cos keeps it; and with a spreading exponent s < 1 even
  // c ~ 1e-16 contributes c^(2s) to a mode. pi/2 - |x| is exact for |x| >= pi/4;
  // pi/2 = kHalfPi + 6.123233995736766e-17 to about 1e-33.
  static double abs_cos(double x) { return det_sin((kHalfPi - std::fabs(x)) + 6.123233995736766e-17); }
};

}  // namespace ocean::model
