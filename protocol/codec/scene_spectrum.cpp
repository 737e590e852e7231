// Phillips and JONSWAP/TMA as sim/spectrum.cpp evaluates them (see CODEC.md 7.6 for
// the normative order). Deep water is depth 0 here, the sim's infinity.
#include "scene_spectrum.hpp"

#include "det_math.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::codec {
namespace {

constexpr double kJonswapGamma = 3.3;
// Beyond k D = 20 tanh(k D) is 1 in double, as in the sim's dispersion.
constexpr double kDeepKd = 20.0;
}  // namespace

double default_small_wave(const SceneModelParams& p) {
  return 0.5 * std::max(p.patch_x_m / p.size_x, p.patch_z_m / p.size_z);
}

SceneSpectrum::SceneSpectrum(const SceneModelParams& p)
    : kind_(p.spectrum),
      gravity_(p.gravity_mps2),
      depth_m_(p.depth_m),
      amplitude_(p.amplitude),
      wind_speed_(p.wind_speed_mps),
      wind_cos_(det_cos(p.wind_dir_deg * kPi / 180.0)),
      wind_sin_(det_sin(p.wind_dir_deg * kPi / 180.0)),
      wind_angle_(p.wind_dir_deg * kPi / 180.0),
      phillips_length_(p.wind_speed_mps * p.wind_speed_mps / p.gravity_mps2),
      small_wave_m_(p.small_wave_m > 0.0 ? p.small_wave_m : default_small_wave(p)),
      alpha_(0.076 * det_pow(p.gravity_mps2 * p.fetch_m / (p.wind_speed_mps * p.wind_speed_mps), -0.22)),
      omega_peak_(22.0 * det_pow(p.gravity_mps2 * p.gravity_mps2 / (p.wind_speed_mps * p.fetch_m), 1.0 / 3.0)),
      spreading_(p.spreading, omega_peak_, p.wind_speed_mps, p.gravity_mps2) {}

double SceneSpectrum::density(double kx, double kz, double k) const {
  if (k == 0.0 || wind_speed_ == 0.0 || amplitude_ == 0.0) return 0.0;
  const double filter = det_exp(-k * k * small_wave_m_ * small_wave_m_);
  if (filter == 0.0) return 0.0;
  const double p = kind_ == ModelSpectrum::phillips ? phillips(kx, kz, k) : jonswap(kx, kz, k);
  return p * filter;
}

double SceneSpectrum::phillips(double kx, double kz, double k) const {
  // The sim's Phillips constant 0.005 / pi, rounded once like its constexpr.
  const double phillips_constant = 0.005 / kPi;
  const double kl = k * phillips_length_;
  const double cos_wind = (kx * wind_cos_ + kz * wind_sin_) / k;
  const double k2 = k * k;
  return amplitude_ * phillips_constant * det_exp(-1.0 / (kl * kl)) / (k2 * k2) * cos_wind * cos_wind;
}

double SceneSpectrum::jonswap(double kx, double kz, double k) const {
  const double omega = det_angular_frequency(k, gravity_, depth_m_);
  const double s = frequency_density(omega);
  if (s == 0.0) return 0.0;  // also keeps 0 * (huge spreading) away from far below the peak
  const double theta = det_atan2(kz, kx) - wind_angle_;
  // P(k) d^2k = S(w) D(w, theta) dw dtheta and d^2k = k dk dtheta.
  return s * spreading_(omega, theta) * group_velocity(k) / k;
}

double SceneSpectrum::frequency_density(double omega) const {
  if (omega <= 0.0 || wind_speed_ == 0.0 || amplitude_ == 0.0) return 0.0;
  const double ratio = omega_peak_ / omega;
  const double ratio4 = ratio * ratio * ratio * ratio;
  const double sigma = omega <= omega_peak_ ? 0.07 : 0.09;
  const double d = (omega - omega_peak_) / (sigma * omega_peak_);
  const double peak_enhancement = det_pow(kJonswapGamma, det_exp(-0.5 * d * d));
  const double omega2 = omega * omega;
  const double pm = alpha_ * gravity_ * gravity_ / (omega2 * omega2 * omega) * det_exp(-1.25 * ratio4);
  return amplitude_ * pm * peak_enhancement * tma_attenuation(omega);
}

double SceneSpectrum::tma_attenuation(double omega) const {
  if (depth_m_ == 0.0) return 1.0;
  const double wh = omega * std::sqrt(depth_m_ / gravity_);
  if (wh <= 1.0) return 0.5 * wh * wh;
  if (wh < 2.0) return 1.0 - 0.5 * (2.0 - wh) * (2.0 - wh);
  return 1.0;
}

double SceneSpectrum::group_velocity(double k) const {
  const double w = det_angular_frequency(k, gravity_, depth_m_);
  const double kd = k * depth_m_;
  if (depth_m_ == 0.0 || kd > kDeepKd) return 0.5 * w / k;
  const double sech = 1.0 / det_cosh(kd);
  // d/dk (g k tanh(kD)) = g (tanh(kD) + kD sech^2(kD)) = 2 w dw/dk
  return gravity_ * (det_tanh(kd) + kd * sech * sech) / (2.0 * w);
}

}  // namespace ocean::codec
