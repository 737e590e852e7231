// Spectrum: the variance density P(k) of the sea surface over the wavenumber plane, normalised so
// that the height variance is the integral of P(k) d^2k. Phillips (Tessendorf 2001) or JONSWAP with
// TMA finite-depth attenuation and directional spreading (Horvath 2015).
#pragma once

#include "scene_params.hpp"
#include "spreading.hpp"

#include <numbers>

namespace ocean::sim {

class Spectrum {
 public:
  // Phillips A for amplitude = 1. Without the small-wave filter the Phillips integral is
  // A pi L^2 / 2 (L = U^2/g), so Hs = 4 sqrt(A pi / 2) L; A = 0.005/pi gives Hs = 0.2 U^2/g, the
  // Pierson-Moskowitz significant height of a fully developed sea (about 2 m at U = 10 m/s).
  static constexpr double phillips_constant = 0.005 / std::numbers::pi;

  explicit Spectrum(const SceneParams& params);  // params must already be valid

  // P(k) in m^2 per (rad/m)^2 for the wave component travelling along (kx, kz) (rad/m).
  double density(double kx, double kz) const;

  // JONSWAP S(w) times the TMA depth factor and the amplitude scale, in m^2 s; 0 for Phillips.
  double frequency_density(double omega) const;

  double omega_peak() const { return omega_peak_; }               // JONSWAP w_p, rad/s
  double small_wave_length() const { return small_wave_m_; }       // Tessendorf's l in metres
  double gravity() const { return gravity_; }
  double depth() const { return depth_m_; }

 private:
  double phillips(double kx, double kz, double k) const;
  double jonswap(double kx, double kz, double k) const;
  double tma_attenuation(double omega) const;

  SpectrumKind kind_;
  double gravity_;
  double depth_m_;
  double amplitude_;
  double wind_speed_;
  double wind_cos_, wind_sin_;
  double wind_angle_;      // radians
  double phillips_length_;  // L = U^2 / g
  double small_wave_m_;
  double alpha_;       // JONSWAP energy scale
  double omega_peak_;  // JONSWAP peak frequency
  Spreading spreading_;
};

// Tessendorf's suppression length l when the scene leaves it 0: half the coarser grid spacing.
double default_small_wave(const SceneParams& p);

}  // namespace ocean::sim
