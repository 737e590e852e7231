// JONSWAP (Hasselmann et al. 1973) with the TMA finite-depth factor and directional spreading
// (Horvath 2015, eqs. 28-31); the frequency-direction spectrum is carried to the wavenumber plane
// with the Jacobian dw/dk / k (finite depth included). Private to spectrum.cpp, which instantiates
// it with the model's compile flags.
#pragma once

#include "../dispersion.hpp"
#include "../spectrum.hpp"
#include "../spreading.hpp"

#include <cmath>
#include <numbers>

namespace ocean::model {

template <class Math>
class Jonswap final : public SpectrumShape<Math> {
 public:
  static constexpr double gamma = 3.3;  // peak enhancement

  explicit Jonswap(const SceneParams& p)
      : gravity_(p.gravity_mps2),
        depth_m_(p.depth_m),
        amplitude_(p.amplitude),
        wind_speed_(p.wind_speed_mps),
        wind_angle_(p.wind_dir_deg * std::numbers::pi / 180.0),
        // Horvath eq. 28-30 (fetch-limited JONSWAP).
        alpha_(0.076 * Math::pow(p.gravity_mps2 * p.fetch_m / (p.wind_speed_mps * p.wind_speed_mps), -0.22)),
        omega_peak_(22.0 * Math::cbrt(p.gravity_mps2 * p.gravity_mps2 / (p.wind_speed_mps * p.fetch_m))),
        spreading_(p.spreading, omega_peak_, p.wind_speed_mps, p.gravity_mps2) {}

  double density(double kx, double kz, double k) const override {
    const double omega = angular_frequency<Math>(k, gravity_, depth_m_);
    const double s = frequency_density(omega);
    if (s == 0.0) return 0.0;  // also keeps 0 * (huge spreading) away from far below the peak
    const double theta = Math::atan2(kz, kx) - wind_angle_;
    // P(k) d^2k = S(w) D(w, theta) dw dtheta and d^2k = k dk dtheta.
    return s * spreading_(omega, theta) * group_velocity<Math>(k, gravity_, depth_m_) / k;
  }

  double frequency_density(double omega) const override {
    if (omega <= 0.0 || wind_speed_ == 0.0 || amplitude_ == 0.0) return 0.0;
    const double ratio = omega_peak_ / omega;
    const double ratio4 = ratio * ratio * ratio * ratio;
    const double sigma = omega <= omega_peak_ ? 0.07 : 0.09;
    const double d = (omega - omega_peak_) / (sigma * omega_peak_);
    const double peak_enhancement = Math::pow(gamma, Math::exp(-0.5 * d * d));
    const double omega2 = omega * omega;
    const double pm = alpha_ * gravity_ * gravity_ / (omega2 * omega2 * omega) * Math::exp(-1.25 * ratio4);
    return amplitude_ * pm * peak_enhancement * tma_attenuation(omega);
  }

  double omega_peak() const override { return omega_peak_; }

 private:
  // Kitaigorodskii depth attenuation as approximated in Horvath eq. 31.
  double tma_attenuation(double omega) const {
    if (std::isinf(depth_m_)) return 1.0;
    const double wh = omega * std::sqrt(depth_m_ / gravity_);
    if (wh <= 1.0) return 0.5 * wh * wh;
    if (wh < 2.0) return 1.0 - 0.5 * (2.0 - wh) * (2.0 - wh);
    return 1.0;
  }

  double gravity_;
  double depth_m_;
  double amplitude_;
  double wind_speed_;
  double wind_angle_;  // radians
  double alpha_;       // energy scale
  double omega_peak_;  // peak frequency, rad/s
  Spreading<Math> spreading_;
};

}  // namespace ocean::model
