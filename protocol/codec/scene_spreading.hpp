// SceneSpreading: the sim's directional spreading functions D(w, theta) (cos-2s, Donelan-Banner,
// Hasselmann; Horvath 2015) written with det_ functions, so every decoder gets the same bits. A copy
// of sim/spreading.cpp's formulas in the same order: the codec may not link the sim.
#pragma once

#include "scene_model_params.hpp"

namespace ocean::codec {

class SceneSpreading {
 public:
  SceneSpreading(ModelSpreading kind, double omega_peak, double wind_speed_mps, double gravity_mps2);

  // theta: angle from the wind direction in radians (any value; wrapped to about [-pi, pi]).
  double operator()(double omega, double theta) const;

 private:
  double cos2s(double omega, double theta) const;
  double donelan_banner(double omega, double theta) const;
  double hasselmann(double omega, double theta) const;

  ModelSpreading kind_;
  double omega_peak_;
  double wind_speed_;
  double gravity_;
};

// Q(s) |cos(theta/2)|^(2s) with Q(s) = Gamma(s+1) / (2 sqrt(pi) Gamma(s+1/2)).
double det_cos_2s_spreading(double s, double theta);

}  // namespace ocean::codec
