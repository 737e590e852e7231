// A single wave, alone in the spectrum, must travel at the phase speed w/k of the dispersion
// relation, deep and shallow, in the direction of its wavenumber.
#include "band_evaluator.hpp"
#include "ocean.hpp"
#include "spectrum.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

using namespace ocean::sim;

namespace {

using std::numbers::pi;

// A 64 x 64 band whose only wave is (kx, kz) with h0 = 0.5, so height = cos(k.x - w t).
BandEvaluator single_wave(const SceneParams& p, int kx, int kz) {
  ModeTable t = build_mode_table(p, Spectrum(p), p.size_x, p.size_z);
  for (std::size_t m = 0; m < t.modes(); ++m) t.sum_re[m] = t.sum_im[m] = t.diff_re[m] = t.diff_im[m] = 0.0f;
  const int row = kz >= 0 ? kz : kz + t.n_z;
  const std::size_t m = static_cast<std::size_t>(row) * t.columns + kx;
  t.sum_re[m] = 0.5f;   // a = 0.5, b = conj(h0(-k)) = 0
  t.diff_re[m] = 0.5f;
  return BandEvaluator(std::move(t), 0.0, p.patch_x_m, p.patch_z_m);
}

// Independent of the library: w = sqrt(g k tanh(k D)).
double expected_omega(double k, double g, double depth) {
  return std::sqrt(g * k * (std::isinf(depth) ? 1.0 : std::tanh(k * depth)));
}

void check_travelling_wave(double depth) {
  SceneParams p;
  p.size_x = p.size_z = 64;
  p.patch_x_m = p.patch_z_m = 64.0;
  p.depth_m = depth;
  const int kx = 3, kz = -2;
  BandEvaluator wave = single_wave(p, kx, kz);
  const double kxm = 2 * pi * kx / p.patch_x_m, kzm = 2 * pi * kz / p.patch_z_m;
  const double k = std::hypot(kxm, kzm);
  const double omega = expected_omega(k, p.gravity_mps2, depth);
  const double dx = p.patch_x_m / p.size_x;

  for (double t : {0.0, 0.37, 1.9, 250.0}) {
    Frame f;
    wave.evaluate(t, f, FrameRequest{true, false});
    // The field is the travelling wave cos(k.x - w t) everywhere.
    double max_err = 0.0;
    std::complex<double> projection = 0.0;
    for (int z = 0; z < p.size_z; ++z)
      for (int x = 0; x < p.size_x; ++x) {
        const double arg = kxm * x * dx + kzm * z * dx;
        const double h = f.height[z * p.size_x + x];
        max_err = std::max(max_err, std::fabs(h - std::cos(arg - omega * t)));
        projection += h * std::polar(1.0, -arg);
      }
    CHECK(max_err < 2e-5);
    // Its phase at the origin advances as -w t: crests move along +k at w/k.
    const double measured_phase = std::arg(projection);
    const double expected_phase = std::remainder(-omega * t, 2 * pi);
    CHECK(std::fabs(std::remainder(measured_phase - expected_phase, 2 * pi)) < 1e-5);
  }
  // Phase speed from a short interval, compared with sqrt(g/k tanh(kD)).
  Frame f0, f1;
  const double dt = 0.05;
  wave.evaluate(10.0, f0, FrameRequest{false, false});
  wave.evaluate(10.0 + dt, f1, FrameRequest{false, false});
  std::complex<double> p0 = 0.0, p1 = 0.0;
  for (int z = 0; z < p.size_z; ++z)
    for (int x = 0; x < p.size_x; ++x) {
      const std::complex<double> e = std::polar(1.0, -(kxm * x * dx + kzm * z * dx));
      p0 += double(f0.height[z * p.size_x + x]) * e;
      p1 += double(f1.height[z * p.size_x + x]) * e;
    }
  const double measured_speed = -std::arg(p1 / p0) / dt / k;
  CHECK(measured_speed == Approx(omega / k).epsilon(1e-4));
}

}  // namespace

TEST_CASE("a single deep-water wave travels at sqrt(g/k) along its wavenumber", "[sim][dispersion]") {
  check_travelling_wave(std::numeric_limits<double>::infinity());
}

TEST_CASE("a single wave in 2 m of water travels at sqrt(g/k tanh(kD))", "[sim][dispersion]") {
  check_travelling_wave(2.0);
}

TEST_CASE("shallow water slows the waves of the full spectrum", "[sim][dispersion]") {
  SceneParams deep;
  deep.size_x = deep.size_z = 32;
  SceneParams shallow = deep;
  shallow.depth_m = 1.0;
  const Ocean a(deep), b(shallow);
  // Same h0 (same seed and spectrum shape up to TMA-free Phillips), different rotation speed.
  const std::complex<double> h0 = a.mode_amplitude(0.0, 1, 0);
  CHECK(std::abs(h0 - b.mode_amplitude(0.0, 1, 0)) < 1e-15);
  const double k = 2 * pi / deep.patch_x_m;
  const std::complex<double> ha = a.mode_amplitude(1.0, 1, 0), hb = b.mode_amplitude(1.0, 1, 0);
  CHECK(std::abs(ha - b.mode_amplitude(1.0 * expected_omega(k, 9.81, INFINITY) / expected_omega(k, 9.81, 1.0), 1, 0)) <
        1e-9 * std::abs(ha) + 1e-15);
  CHECK(std::abs(ha - hb) > 1e-6 * std::abs(ha));
}
