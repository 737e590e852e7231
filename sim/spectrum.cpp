// Phillips and JONSWAP/TMA wavenumber spectra; the JONSWAP frequency-direction spectrum is carried
// to the wavenumber plane with the Jacobian dw/dk / k (finite depth included).
#include "spectrum.hpp"

#include "dispersion.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::sim {
namespace {

constexpr double jonswap_gamma = 3.3;
}  // namespace

double default_small_wave(const SceneParams& p) {
  // Half the coarser grid spacing: at the Nyquist wavenumber pi/dx the filter exp(-k^2 l^2) is
  // exp(-pi^2/4) = 0.085 in energy, which tames aliasing of the slopes without flattening the grid.
  return 0.5 * std::max(p.patch_x_m / p.size_x, p.patch_z_m / p.size_z);
}

Spectrum::Spectrum(const SceneParams& p)
    : kind_(p.spectrum),
      gravity_(p.gravity_mps2),
      depth_m_(p.depth_m),
      amplitude_(p.amplitude),
      wind_speed_(p.wind_speed_mps),
      wind_cos_(std::cos(p.wind_dir_deg * std::numbers::pi / 180.0)),
      wind_sin_(std::sin(p.wind_dir_deg * std::numbers::pi / 180.0)),
      wind_angle_(p.wind_dir_deg * std::numbers::pi / 180.0),
      phillips_length_(p.wind_speed_mps * p.wind_speed_mps / p.gravity_mps2),
      small_wave_m_(p.small_wave_m > 0.0 ? p.small_wave_m : default_small_wave(p)),
      // Horvath eq. 28-30 (fetch-limited JONSWAP of Hasselmann et al. 1973).
      alpha_(0.076 * std::pow(p.gravity_mps2 * p.fetch_m / (p.wind_speed_mps * p.wind_speed_mps), -0.22)),
      omega_peak_(22.0 * std::cbrt(p.gravity_mps2 * p.gravity_mps2 / (p.wind_speed_mps * p.fetch_m))),
      spreading_(p.spreading, omega_peak_, p.wind_speed_mps, p.gravity_mps2) {}

double Spectrum::density(double kx, double kz) const {
  const double k = std::hypot(kx, kz);
  if (k == 0.0 || wind_speed_ == 0.0 || amplitude_ == 0.0) return 0.0;
  const double filter = std::exp(-k * k * small_wave_m_ * small_wave_m_);
  if (filter == 0.0) return 0.0;
  const double p = kind_ == SpectrumKind::phillips ? phillips(kx, kz, k) : jonswap(kx, kz, k);
  return p * filter;
}

double Spectrum::phillips(double kx, double kz, double k) const {
  const double kl = k * phillips_length_;
  const double cos_wind = (kx * wind_cos_ + kz * wind_sin_) / k;
  const double k2 = k * k;
  return amplitude_ * phillips_constant * std::exp(-1.0 / (kl * kl)) / (k2 * k2) * cos_wind * cos_wind;
}

double Spectrum::jonswap(double kx, double kz, double k) const {
  const double omega = angular_frequency(k, gravity_, depth_m_);
  const double s = frequency_density(omega);
  if (s == 0.0) return 0.0;  // also keeps 0 * (huge spreading) away from far below the peak
  const double theta = std::atan2(kz, kx) - wind_angle_;
  // P(k) d^2k = S(w) D(w, theta) dw dtheta and d^2k = k dk dtheta.
  return s * spreading_(omega, theta) * group_velocity(k, gravity_, depth_m_) / k;
}

double Spectrum::frequency_density(double omega) const {
  if (kind_ != SpectrumKind::jonswap || omega <= 0.0 || wind_speed_ == 0.0 || amplitude_ == 0.0) return 0.0;
  const double ratio = omega_peak_ / omega;
  const double ratio4 = ratio * ratio * ratio * ratio;
  const double sigma = omega <= omega_peak_ ? 0.07 : 0.09;
  const double d = (omega - omega_peak_) / (sigma * omega_peak_);
  const double peak_enhancement = std::pow(jonswap_gamma, std::exp(-0.5 * d * d));
  const double omega2 = omega * omega;
  const double pm = alpha_ * gravity_ * gravity_ / (omega2 * omega2 * omega) * std::exp(-1.25 * ratio4);
  return amplitude_ * pm * peak_enhancement * tma_attenuation(omega);
}

// Kitaigorodskii depth attenuation as approximated in Horvath eq. 31.
double Spectrum::tma_attenuation(double omega) const {
  if (std::isinf(depth_m_)) return 1.0;
  const double wh = omega * std::sqrt(depth_m_ / gravity_);
  if (wh <= 1.0) return 0.5 * wh * wh;
  if (wh < 2.0) return 1.0 - 0.5 * (2.0 - wh) * (2.0 - wh);
  return 1.0;
}

}  // namespace ocean::sim
