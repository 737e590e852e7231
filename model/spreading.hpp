// Directional spreading D(w, theta) of a wind sea (Horvath 2015, section 5): cos-2s (Mitsuyasu),
// Donelan-Banner and Hasselmann. For every w each integrates to 1 over theta in [-pi, pi].
#pragma once

#include "scene_params.hpp"

namespace ocean::model {

template <class Math>
class Spreading {
 public:
  // omega_peak: the spectral peak w_p (rad/s); wind speed U10 (m/s) and gravity enter the widths.
  Spreading(SpreadingKind kind, double omega_peak, double wind_speed_mps, double gravity_mps2);

  // theta: angle from the wind direction in radians (any value; wrapped to [-pi, pi]).
  double operator()(double omega, double theta) const;

 private:
  double cos2s(double omega, double theta) const;
  double donelan_banner(double omega, double theta) const;
  double hasselmann(double omega, double theta) const;

  SpreadingKind kind_;
  double omega_peak_;
  double wind_speed_;
  double gravity_;
};

// The cos-2s family Q(s) |cos(theta/2)|^(2s) with Q(s) = Gamma(s+1) / (2 sqrt(pi) Gamma(s+1/2)),
// which integrates to 1 over [-pi, pi] for every s >= 0.
template <class Math>
double cos_2s_spreading(double s, double theta);

}  // namespace ocean::model
