// h0(k): the random complex amplitude of each wave at t = 0, from the spectrum and the portable
// Gaussian source. A function of (params, kx, kz) only, shared by every grid and band.
#pragma once

#include "scene_params.hpp"
#include "spectrum.hpp"

#include <complex>
#include <numbers>

namespace ocean::model {

// Integer wavenumber (cycles per patch) to physical wavenumber in rad/m.
inline double wavenumber(int k_index, double patch_m) { return 2.0 * std::numbers::pi * k_index / patch_m; }

// h0 of the wave with integer wavenumber (kx, kz) in metres; 0 at k = 0, outside the scene's band
// and where P dkx dkz <= 1e-40 (or NaN), so that no subnormal floats reach the per-tick arithmetic.
// Normalisation: h0 = xi sqrt(P(k) dkx dkz / 2) with xi a unit complex Gaussian (E|xi|^2 = 1, i.e.
// real and imaginary parts N(0, 1/2)). The real field pairs h0(k) with conj(h0(k)) at -k into one
// wave of variance 2|h0|^2, so the expected height variance is sum P(k) dkx dkz = integral of P d^2k.
// (Tessendorf's xi_r, xi_i ~ N(0, 1) would double that.)
template <class Math>
std::complex<double> initial_amplitude(const SceneParams& params, const Spectrum<Math>& spectrum, int kx, int kz);

}  // namespace ocean::model
