// SceneSpectrum: the sim's variance density P(k) (Phillips with the small-wave filter, or JONSWAP
// with TMA depth attenuation, directional spreading and the frequency-to-wavenumber Jacobian),
// written with det_ functions so that every decoder computes the same bits. A copy of
// sim/{spectrum,dispersion}.cpp's formulas in the same order: the codec may not link the sim
// (clients never do), and the sim's libm calls differ between platforms in the last bits.
#pragma once

#include "scene_model_params.hpp"
#include "scene_spreading.hpp"

namespace ocean::codec {

class SceneSpectrum {
 public:
  explicit SceneSpectrum(const SceneModelParams& scene);  // scene must already be valid

  // P(k) in m^2 per (rad/m)^2 for the wave travelling along (kx, kz) (rad/m) of length k.
  double density(double kx, double kz, double k) const;

  double omega_peak() const { return omega_peak_; }
  double small_wave_length() const { return small_wave_m_; }

 private:
  double phillips(double kx, double kz, double k) const;
  double jonswap(double kx, double kz, double k) const;
  double frequency_density(double omega) const;
  double tma_attenuation(double omega) const;
  double group_velocity(double k) const;

  ModelSpectrum kind_;
  double gravity_;
  double depth_m_;  // 0 = deep
  double amplitude_;
  double wind_speed_;
  double wind_cos_, wind_sin_;
  double wind_angle_;
  double phillips_length_;
  double small_wave_m_;
  double alpha_;
  double omega_peak_;
  SceneSpreading spreading_;
};

// The suppression length of a scene whose small_wave_m is 0, as the sim's default_small_wave.
double default_small_wave(const SceneModelParams& p);

}  // namespace ocean::codec
