// Dispersion of surface gravity waves: w^2 = g k tanh(k D), which is w^2 = g k in deep water
// (depth = infinity), and its derivative dw/dk used by the frequency-to-wavenumber Jacobian.
#pragma once

namespace ocean::model {

// Angular frequency (rad/s) of a wave of wavenumber k (rad/m) in water of depth depth_m (m, may be inf).
template <class Math>
double angular_frequency(double k, double gravity, double depth_m);

// dw/dk (m/s, the group velocity) at wavenumber k.
template <class Math>
double group_velocity(double k, double gravity, double depth_m);

}  // namespace ocean::model
