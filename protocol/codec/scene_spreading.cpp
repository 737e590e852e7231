// Horvath 2015 eqs. 40-46 as sim/spreading.cpp evaluates them, with det_ functions. Angles
// wrap exactly like the sim's remainder (det_wrap_angle differs only in the sign of a tie at +-pi,
// where every spreading function is even).
#include "scene_spreading.hpp"

#include "det_math.hpp"

#include <cmath>

namespace ocean::codec {
namespace {

// pi/2 = kHalfPi + kHalfPiLo to about 1e-33.
constexpr double kHalfPiLo = 6.123233995736766e-17;

}  // namespace

double det_cos_2s_spreading(double s, double theta) {
  // In logarithms because s reaches hundreds of thousands for light wind over long fetch.
  const double log_q = det_log_gamma(s + 1.0) - det_log_gamma(s + 0.5) - det_log(2.0 * std::sqrt(kPi));
  // |cos(x)| as sin(pi/2 - |x|): upwind (x -> +-pi/2) cos(x) is tiny and a series for it would
  // lose all relative precision there, while libm's cos, which the sim calls, keeps it; and with
  // s < 1 even c ~ 1e-16 contributes c^(2s) to a mode. pi/2 - |x| is exact for |x| >= pi/4.
  const double x = 0.5 * det_wrap_angle(theta);
  const double c = det_sin((kHalfPi - std::fabs(x)) + kHalfPiLo);
  if (c == 0.0) return s == 0.0 ? det_exp(log_q) : 0.0;
  return det_exp(log_q + 2.0 * s * det_log(c));
}

SceneSpreading::SceneSpreading(ModelSpreading kind, double omega_peak, double wind_speed_mps, double gravity_mps2)
    : kind_(kind), omega_peak_(omega_peak), wind_speed_(wind_speed_mps), gravity_(gravity_mps2) {}

double SceneSpreading::operator()(double omega, double theta) const {
  switch (kind_) {
    case ModelSpreading::cos2s: return cos2s(omega, theta);
    case ModelSpreading::donelan_banner: return donelan_banner(omega, theta);
    case ModelSpreading::hasselmann: return hasselmann(omega, theta);
  }
  return 0.0;
}

double SceneSpreading::cos2s(double omega, double theta) const {
  const double ratio = omega / omega_peak_;
  const double s_peak = 11.5 * det_pow(gravity_ / (omega_peak_ * wind_speed_), 2.5);
  const double s = s_peak * (ratio <= 1.0 ? det_pow(ratio, 5.0) : det_pow(ratio, -2.5));
  return det_cos_2s_spreading(s, theta);
}

double SceneSpreading::donelan_banner(double omega, double theta) const {
  const double ratio = omega / omega_peak_;
  double beta;
  if (ratio > 0.56 && ratio < 0.95) {
    beta = 2.61 * det_pow(ratio, 1.3);
  } else if (ratio >= 0.95 && ratio < 1.6) {
    beta = 2.28 * det_pow(ratio, -1.3);
  } else {
    const double epsilon = -0.4 + 0.8393 * det_exp(-0.567 * det_log(ratio * ratio));
    beta = det_pow(10.0, epsilon);
  }
  const double x = beta * det_wrap_angle(theta);
  if (!std::isfinite(beta) || std::fabs(x) > 300.0) return 0.0;  // sech^2 underflows long before
  const double sech = 1.0 / det_cosh(x);
  return beta / (2.0 * det_tanh(beta * kPi)) * sech * sech;
}

double SceneSpreading::hasselmann(double omega, double theta) const {
  const double ratio = omega / omega_peak_;
  const double s = ratio <= 1.0
                       ? 6.97 * det_pow(ratio, 4.06)
                       : 9.77 * det_pow(ratio, -2.33 - 1.45 * (wind_speed_ * omega_peak_ / gravity_ - 1.17));
  return det_cos_2s_spreading(s, theta);
}

}  // namespace ocean::codec
