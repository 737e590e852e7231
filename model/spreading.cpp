// Spreading functions of Horvath 2015 (eqs. 40-46), written from the paper's formulas.
#include "spreading.hpp"

#include "arithmetic.hpp"

#include <cmath>
#include <numbers>

namespace ocean::model {

template <class Math>
double cos_2s_spreading(double s, double theta) {
  // Q(s) = 2^(2s-1) Gamma(s+1)^2 / (pi Gamma(2s+1)) simplified with Legendre's duplication formula;
  // in logarithms because s reaches hundreds of thousands for light wind over long fetch.
  const double log_q =
      Math::log_gamma(s + 1.0) - Math::log_gamma(s + 0.5) - Math::log(2.0 * std::sqrt(std::numbers::pi));
  const double c = Math::abs_cos(0.5 * Math::wrap_angle(theta));
  if (c == 0.0) return s == 0.0 ? Math::exp(log_q) : 0.0;
  return Math::exp(log_q + 2.0 * s * Math::log(c));
}

template <class Math>
Spreading<Math>::Spreading(SpreadingKind kind, double omega_peak, double wind_speed_mps, double gravity_mps2)
    : kind_(kind), omega_peak_(omega_peak), wind_speed_(wind_speed_mps), gravity_(gravity_mps2) {}

template <class Math>
double Spreading<Math>::operator()(double omega, double theta) const {
  switch (kind_) {
    case SpreadingKind::cos2s: return cos2s(omega, theta);
    case SpreadingKind::donelan_banner: return donelan_banner(omega, theta);
    case SpreadingKind::hasselmann: return hasselmann(omega, theta);
  }
  return 0.0;
}

// Mitsuyasu: s = s_p (w/w_p)^5 below the peak, s_p (w/w_p)^-2.5 above, s_p = 11.5 (g / (w_p U))^2.5.
template <class Math>
double Spreading<Math>::cos2s(double omega, double theta) const {
  const double ratio = omega / omega_peak_;
  const double s_peak = 11.5 * Math::pow(gravity_ / (omega_peak_ * wind_speed_), 2.5);
  const double s = s_peak * (ratio <= 1.0 ? Math::pow(ratio, 5.0) : Math::pow(ratio, -2.5));
  return cos_2s_spreading<Math>(s, theta);
}

// Donelan-Banner: beta/(2 tanh(beta pi)) sech^2(beta theta), beta piecewise in w/w_p.
template <class Math>
double Spreading<Math>::donelan_banner(double omega, double theta) const {
  const double ratio = omega / omega_peak_;
  double beta;
  if (ratio > 0.56 && ratio < 0.95) {
    beta = 2.61 * Math::pow(ratio, 1.3);
  } else if (ratio >= 0.95 && ratio < 1.6) {
    beta = 2.28 * Math::pow(ratio, -1.3);
  } else {
    const double epsilon = -0.4 + 0.8393 * Math::exp(-0.567 * Math::log(ratio * ratio));
    beta = Math::pow(10.0, epsilon);
  }
  const double x = beta * Math::wrap_angle(theta);
  if (!std::isfinite(beta) || std::fabs(x) > 300.0) return 0.0;  // sech^2 underflows long before
  const double sech = 1.0 / Math::cosh(x);
  return beta / (2.0 * Math::tanh(beta * std::numbers::pi)) * sech * sech;
}

// Hasselmann: s = 6.97 (w/w_p)^4.06 below the peak, 9.77 (w/w_p)^(-2.33 - 1.45 (U w_p / g - 1.17)) above.
template <class Math>
double Spreading<Math>::hasselmann(double omega, double theta) const {
  const double ratio = omega / omega_peak_;
  const double s = ratio <= 1.0
                       ? 6.97 * Math::pow(ratio, 4.06)
                       : 9.77 * Math::pow(ratio, -2.33 - 1.45 * (wind_speed_ * omega_peak_ / gravity_ - 1.17));
  return cos_2s_spreading<Math>(s, theta);
}

template class Spreading<Libm>;
template class Spreading<Det>;
template double cos_2s_spreading<Libm>(double, double);
template double cos_2s_spreading<Det>(double, double);

}  // namespace ocean::model
