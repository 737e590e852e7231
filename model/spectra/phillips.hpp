// Phillips (Tessendorf 2001): A exp(-1/(kL)^2) / k^4 |k.w|^2 with L = U^2/g. Its own |k.w|^2 factor
// spreads it, so it ignores the scene's spreading and fetch. Private to spectrum.cpp, which
// instantiates it with the model's compile flags.
#pragma once

#include "../spectrum.hpp"

#include <numbers>

namespace ocean::model {

template <class Math>
class Phillips final : public SpectrumShape<Math> {
 public:
  // Phillips A for amplitude = 1. Without the small-wave filter the Phillips integral is
  // A pi L^2 / 2 (L = U^2/g), so Hs = 4 sqrt(A pi / 2) L; A = 0.005/pi gives Hs = 0.2 U^2/g, the
  // Pierson-Moskowitz significant height of a fully developed sea (about 2 m at U = 10 m/s).
  static constexpr double phillips_constant = 0.005 / std::numbers::pi;

  explicit Phillips(const SceneParams& p)
      : amplitude_(p.amplitude),
        wind_cos_(Math::cos(p.wind_dir_deg * std::numbers::pi / 180.0)),
        wind_sin_(Math::sin(p.wind_dir_deg * std::numbers::pi / 180.0)),
        length_(p.wind_speed_mps * p.wind_speed_mps / p.gravity_mps2) {}

  double density(double kx, double kz, double k) const override {
    const double kl = k * length_;
    const double cos_wind = (kx * wind_cos_ + kz * wind_sin_) / k;
    const double k2 = k * k;
    return amplitude_ * phillips_constant * Math::exp(-1.0 / (kl * kl)) / (k2 * k2) * cos_wind * cos_wind;
  }

 private:
  double amplitude_;
  double wind_cos_, wind_sin_;
  double length_;  // L = U^2 / g
};

}  // namespace ocean::model
