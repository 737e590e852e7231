// WakeField: the water's linear response to hulls moving over it - a vessel's Kelvin wake, a
// dropped object's rings - on a square region of the world of its own (not the ocean's repeating
// patch, so a wake is cast once, not once per patch). Each Fourier mode k of the region is a damped
// oscillator at the scene's w(k) (finite depth included), forced by the hulls' surface pressure:
//   eta'' + 2 gamma eta' + w^2 (eta + p / (rho g)) = 0,
// so a hull at rest sits in its hydrostatic hollow and a moving one radiates exactly the waves the
// dispersion relation allows: the Kelvin wedge, the transverse wavelength 2 pi U^2 / g, rings at
// the group velocity, all without tuning. Pressure is held over a step at its value mid-step and
// the oscillator is advanced exactly, so a step costs one rotation per mode. The hulls' pressure
// comes straight as Fourier coefficients (model/hull_pressure.hpp: the codec predicts the same
// forcing), a complex product per mode and hull a step. gamma = decay + 2 nu k^2: a wake fades, so the sea at a tick depends on a
// bounded history of poses.
// Pure: time steps are arguments; the same poses give the same bits in any process.
#pragma once

#include "hull_pressure.hpp"
#include "vessel_track.hpp"

#include <complex>
#include <cstddef>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace ocean::sim {

class C2rTransform;

using model::Hull;
using model::HullPose;

struct WakeRegion {
  double size_m = 1024.0;   // the square's side
  int n = 256;              // modes (and samples) per side, a power of two
  double gravity_mps2 = 9.81;
  double depth_m = std::numeric_limits<double>::infinity();  // deep water, as in a scene
  double decay_per_s = 0.02;  // amplitude decay of every wave (about 50 s)
  double viscosity_m2ps = 1e-6;  // kinematic: short waves fade faster (2 nu k^2)
};

class WakeField {
 public:
  explicit WakeField(const WakeRegion& region);
  ~WakeField();
  WakeField(WakeField&&) noexcept;
  WakeField& operator=(WakeField&&) noexcept;

  // Advances by dt seconds with the hulls at `mid` (their poses at the middle of the step, in the
  // region's metres from its corner).
  void step(double dt_s, std::span<const HullPose> mid);

  // Heights (m) at the n x n sample points x = i size/n, z = j size/n, row j = z, column i = x.
  std::vector<double> heights() const;
  // The wake's Fourier coefficients (height = sum a e^{i k.x} over the full spectrum): n rows (kz
  // in FFT order) of n/2 + 1 columns (kx >= 0), row-major.
  const std::vector<std::complex<double>>& modes() const { return eta_; }
  // The height at one point (a sum over the modes: for checks and buoyancy, not for frames).
  double height_at(double x_m, double z_m) const;

  // The water's depth from the next step on (a scene's change of depth): every mode's w(k) follows.
  void set_depth(double depth_m);

  const WakeRegion& region() const { return region_; }
  double time_s() const { return time_s_; }

 private:
  void prepare_step(double dt_s);
  void set_frequencies();

  WakeRegion region_;
  int columns_;                  // n / 2 + 1: the half spectrum a real field needs
  std::vector<double> kx_, kz_;  // per column (kx >= 0) / row (FFT order), rad/m
  std::vector<double> omega_, gamma_;
  // Per mode of the half spectrum: eta and eta' (complex Fourier coefficients of the height).
  std::vector<std::complex<double>> eta_, velocity_;
  model::HullPressure<model::Libm> pressure_;  // p / (rho g) of the hulls, per mode
  std::vector<std::complex<double>> forcing_;
  std::unique_ptr<C2rTransform> synthesis_;
  // The exact propagator of each mode for the last dt (recomputed when dt changes).
  double step_dt_ = 0.0;
  std::vector<double> c_ee_, c_ev_, c_ve_, c_vv_;
  double time_s_ = 0.0;
};

}  // namespace ocean::sim
