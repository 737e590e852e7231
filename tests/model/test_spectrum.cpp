// Spectra, spreading and the Gaussian source, checked against integrals and empirical relations
// computed here, not against the library's own numbers - in both arithmetics the model is
// evaluated in (the sim's Libm, the codec's Det).
#include "arithmetic.hpp"
#include "initial_amplitude.hpp"
#include "mode_gaussian.hpp"
#include "spectrum.hpp"
#include "spreading.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <numbers>

using namespace ocean::model;

namespace {

using std::numbers::pi;

double simpson(const std::function<double(double)>& f, double a, double b, int intervals) {
  const double h = (b - a) / intervals;
  double sum = f(a) + f(b);
  for (int i = 1; i < intervals; ++i) sum += f(a + i * h) * (i % 2 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

// Integral of P over the wavenumber plane in polar coordinates, k log-spaced around k_scale.
template <class Math>
double plane_integral(const Spectrum<Math>& s, double k_scale) {
  return simpson(
      [&](double log_k) {
        const double k = std::exp(log_k);
        const double ring = simpson([&](double th) { return s.density(k * std::cos(th), k * std::sin(th)); }, -pi, pi,
                                    360);
        return ring * k * k;  // d^2k = k dk dtheta = k^2 dlogk dtheta
      },
      std::log(k_scale * 1e-2), std::log(k_scale * 1e3), 600);
}

// Over [-pi, pi] with theta = pi sin(u): smooths the cusp of |cos(theta/2)|^(2s) at +-pi for small s,
// and a fine middle piece resolves the narrowest spreading functions (width ~ 1e-3) around 0.
double angle_integral(const std::function<double(double)>& f) {
  const auto g = [&](double u) { return f(pi * std::sin(u)) * pi * std::cos(u); };
  return simpson(g, -pi / 2, -0.05, 10000) + simpson(g, -0.05, 0.05, 20000) + simpson(g, 0.05, pi / 2, 10000);
}

}  // namespace

TEMPLATE_TEST_CASE("every spreading function integrates to 1 over direction", "[model][spectrum]", Libm, Det) {
  for (SpreadingKind kind : {SpreadingKind::cos2s, SpreadingKind::donelan_banner, SpreadingKind::hasselmann}) {
    for (double wind : {4.0, 20.0}) {
      const double omega_peak = 0.9;
      const Spreading<TestType> spread(kind, omega_peak, wind, 9.81);
      for (double ratio : {0.3, 0.5, 0.56, 0.7, 0.95, 1.0, 1.3, 1.6, 2.0, 3.0, 6.0}) {
        CAPTURE(static_cast<int>(kind), wind, ratio);
        const double integral = angle_integral([&](double th) { return spread(ratio * omega_peak, th); });
        CHECK(integral == Approx(1.0).epsilon(1e-6));
        // Most energy travels with the wind.
        CHECK(spread(ratio * omega_peak, 0.0) > spread(ratio * omega_peak, pi / 2));
        CHECK(spread(ratio * omega_peak, 0.3) == Approx(spread(ratio * omega_peak, -0.3)));
      }
    }
  }
  for (double s : {0.0, 0.5, 3.0, 20.0, 150.0, 600.0})
    CHECK(angle_integral([&](double th) { return cos_2s_spreading<TestType>(s, th); }) == Approx(1.0).epsilon(1e-6));
}

TEMPLATE_TEST_CASE("Phillips with amplitude 1 gives Hs of 0.2 U^2/g (fully developed sea)", "[model][spectrum]", Libm, Det) {
  for (double wind : {5.0, 10.0, 20.0}) {
    SceneParams p;
    p.wind_speed_mps = wind;
    p.wind_dir_deg = 30.0;
    p.small_wave_m = 1e-4;  // keep the filter out of the integral
    const Spectrum<TestType> s(p);
    const double l = wind * wind / 9.81;
    const double hs = 4.0 * std::sqrt(plane_integral(s, 1.0 / l));
    CAPTURE(wind);
    CHECK(hs == Approx(0.2 * l).epsilon(0.01));
    // Waves along the wind, none across it.
    const double k = 1.0 / l;
    const double along = s.density(k * std::cos(pi / 6), k * std::sin(pi / 6));
    CHECK(along > 0.0);
    CHECK(s.density(-k * std::sin(pi / 6), k * std::cos(pi / 6)) < 1e-12 * along);
  }
}

TEMPLATE_TEST_CASE("JONSWAP keeps its energy when carried to the wavenumber plane", "[model][spectrum]", Libm, Det) {
  // The Jacobian dw/dk / k is right iff the plane integral of P equals the integral of S(w) (with
  // TMA) over frequency, deep or shallow.
  for (double depth : {double(INFINITY), 30.0, 4.0}) {
    for (SpreadingKind kind : {SpreadingKind::cos2s, SpreadingKind::donelan_banner, SpreadingKind::hasselmann}) {
      SceneParams p;
      p.spectrum = SpectrumKind::jonswap;
      p.spreading = kind;
      p.depth_m = depth;
      p.small_wave_m = 1e-4;
      const Spectrum<TestType> s(p);
      const double wp = s.omega_peak();
      const double frequency_integral =
          simpson([&](double log_w) { return s.frequency_density(std::exp(log_w)) * std::exp(log_w); },
                  std::log(wp * 0.2), std::log(wp * 50.0), 20000);
      const double kp = wp * wp / 9.81;
      CAPTURE(depth, static_cast<int>(kind));
      CHECK(plane_integral(s, kp) == Approx(frequency_integral).epsilon(0.005));
    }
  }
}

TEMPLATE_TEST_CASE("JONSWAP peaks at w_p with the PM shape and gamma = 3.3 enhancement", "[model][spectrum]", Libm, Det) {
  SceneParams p;
  p.spectrum = SpectrumKind::jonswap;
  p.wind_speed_mps = 10.0;
  p.fetch_m = 100e3;
  const Spectrum<TestType> s(p);
  // w_p = 22 (g^2 / (U F))^(1/3)
  CHECK(s.omega_peak() == Approx(22.0 * std::cbrt(9.81 * 9.81 / (10.0 * 100e3))));
  double best_w = 0.0, best = 0.0;
  for (double w = 0.2; w < 4.0; w += 0.001)
    if (s.frequency_density(w) > best) best = s.frequency_density(w), best_w = w;
  CHECK(best_w == Approx(s.omega_peak()).epsilon(0.01));
  // Away from the peak JONSWAP is the Pierson-Moskowitz shape alpha g^2 w^-5 exp(-5/4 (w_p/w)^4)
  // with Horvath's alpha = 0.076 (g F / U^2)^-0.22; at the peak it is gamma = 3.3 times that.
  const double alpha = 0.076 * std::pow(9.81 * 100e3 / 100.0, -0.22);
  const auto pierson_moskowitz = [&](double w) {
    return alpha * 9.81 * 9.81 / std::pow(w, 5) * std::exp(-1.25 * std::pow(s.omega_peak() / w, 4));
  };
  const double wp = s.omega_peak();
  CHECK(s.frequency_density(3.0 * wp) == Approx(pierson_moskowitz(3.0 * wp)).epsilon(1e-9));
  CHECK(s.frequency_density(0.6 * wp) == Approx(pierson_moskowitz(0.6 * wp)).epsilon(1e-6));
  CHECK(s.frequency_density(wp) == Approx(3.3 * pierson_moskowitz(wp)).epsilon(1e-12));
  // Energy: the PM integral alpha g^2 / (5 w_p^4) times the peak enhancement, about 1.5 for gamma 3.3.
  const double m0 = simpson([&](double w) { return s.frequency_density(w); }, 0.05, 20.0, 40000);
  const double pm_m0 = alpha * 9.81 * 9.81 / (5.0 * std::pow(wp, 4));
  CHECK(m0 / pm_m0 > 1.35);
  CHECK(m0 / pm_m0 < 1.65);
  // TMA: shallow water removes energy at low frequency, none in deep water.
  SceneParams shallow = p;
  shallow.depth_m = 5.0;
  const Spectrum<TestType> t(shallow);
  CHECK(t.frequency_density(0.6) < 0.9 * s.frequency_density(0.6));
  CHECK(t.frequency_density(3.0) == Approx(s.frequency_density(3.0)));
}

TEMPLATE_TEST_CASE("no wind, no amplitude: a flat sea", "[model][spectrum]", Libm, Det) {
  for (SpectrumKind kind : {SpectrumKind::phillips, SpectrumKind::jonswap}) {
    SceneParams calm;
    calm.spectrum = kind;
    calm.wind_speed_mps = 0.0;
    SceneParams silent;
    silent.spectrum = kind;
    silent.amplitude = 0.0;
    for (const SceneParams& p : {calm, silent}) {
      const Spectrum<TestType> s(p);
      for (double k : {0.01, 0.1, 1.0}) CHECK(s.density(k, 0.5 * k) == 0.0);
    }
  }
}

TEMPLATE_TEST_CASE("the Gaussian source depends only on (seed, kx, kz) and is standard normal", "[model][gaussian]", Libm, Det) {
  CHECK(mode_gaussian<TestType>(5, 3, -7).re == mode_gaussian<TestType>(5, 3, -7).re);
  CHECK(mode_gaussian<TestType>(5, 3, -7).re != mode_gaussian<TestType>(6, 3, -7).re);
  CHECK(mode_gaussian<TestType>(5, 3, -7).re != mode_gaussian<TestType>(5, -7, 3).re);
  double sum = 0.0, sum2 = 0.0, cross = 0.0, sum4 = 0.0;
  int n = 0;
  for (int kz = -200; kz < 200; ++kz)
    for (int kx = -200; kx < 200; ++kx) {
      const GaussianPair g = mode_gaussian<TestType>(42, kx, kz);
      sum += g.re + g.im;
      sum2 += g.re * g.re + g.im * g.im;
      sum4 += g.re * g.re * g.re * g.re;
      cross += g.re * g.im;
      n += 2;
    }
  CHECK(std::fabs(sum / n) < 0.01);
  CHECK(sum2 / n == Approx(1.0).epsilon(0.01));
  CHECK(std::fabs(cross / (n / 2)) < 0.01);
  CHECK(sum4 / (n / 2) == Approx(3.0).epsilon(0.03));  // Gaussian kurtosis
}

TEMPLATE_TEST_CASE("h0 has E|h0|^2 = P dkx dkz / 2", "[model][gaussian]", Libm, Det) {
  SceneParams p;
  p.wind_speed_mps = 30.0;  // spread the energy over many modes
  const Spectrum<TestType> s(p);
  const double dk = 2 * pi / p.patch_x_m;
  double ratio_sum = 0.0;
  int count = 0;
  for (int kz = -127; kz < 128; ++kz)
    for (int kx = -127; kx < 128; ++kx) {
      const double expected = s.density(kx * dk, kz * dk) * dk * dk / 2.0;
      if (expected < 1e-30) continue;
      ratio_sum += std::norm(initial_amplitude(p, s, kx, kz)) / expected;
      ++count;
    }
  REQUIRE(count > 30000);
  CHECK(ratio_sum / count == Approx(1.0).epsilon(0.03));
}
