// Spectrum: the variance density P(k) of the sea surface over the wavenumber plane, normalised so
// that the height variance is the integral of P(k) d^2k, with Tessendorf's small-wave filter
// exp(-k^2 l^2). Each spectrum's shape is one file of spectra/ (Phillips, Tessendorf 2001; JONSWAP
// with TMA depth attenuation and directional spreading, Horvath 2015).
#pragma once

#include "scene_params.hpp"

#include <memory>

namespace ocean::model {

// One spectrum's shape without the filter; spectrum.cpp picks it by SceneParams::spectrum.
template <class Math>
class SpectrumShape {
 public:
  virtual ~SpectrumShape() = default;
  // P(k) in m^2 per (rad/m)^2 for the wave along (kx, kz) of length k > 0.
  virtual double density(double kx, double kz, double k) const = 0;
  // S(w) in m^2 s for a spectrum defined over frequency, else 0.
  virtual double frequency_density(double /*omega*/) const { return 0.0; }
  virtual double omega_peak() const { return 0.0; }
};

template <class Math>
class Spectrum {
 public:
  explicit Spectrum(const SceneParams& params);  // params must already be valid

  // P(k) in m^2 per (rad/m)^2 for the wave component travelling along (kx, kz) (rad/m).
  double density(double kx, double kz) const;

  // JONSWAP S(w) times the TMA depth factor and the amplitude scale, in m^2 s; 0 for Phillips.
  double frequency_density(double omega) const { return shape_->frequency_density(omega); }

  double omega_peak() const { return shape_->omega_peak(); }       // JONSWAP w_p, rad/s
  double small_wave_length() const { return small_wave_m_; }       // Tessendorf's l in metres

 private:
  double wind_speed_;
  double amplitude_;
  double small_wave_m_;
  std::shared_ptr<const SpectrumShape<Math>> shape_;
};

// Tessendorf's suppression length l when the scene leaves it 0: half the coarser grid spacing.
double default_small_wave(const SceneParams& p);

}  // namespace ocean::model
