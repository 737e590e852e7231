// Properties every frame must have: it is the real spectral sum of a Hermitian spectrum (heights,
// slopes, displacement, Jacobian), has zero mean, obeys Parseval, is periodic with no seam, its
// slopes are the derivatives of its heights, and its Jacobian has mean exactly 1.
#include "direct_fourier.hpp"
#include "field_stats.hpp"
#include "ocean.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

using namespace ocean::sim;
using ocean::model::SpectrumKind;
using ocean::model::SpreadingKind;
using ocean::sim::testing::PlaneSpectrum;

namespace {

using std::numbers::pi;

using ocean::sim::test::max_abs;

double mean(const std::vector<float>& v) {
  double s = 0.0;
  for (float x : v) s += x;
  return s / v.size();
}

double variance(const std::vector<float>& v) {
  const double m = mean(v);
  double s = 0.0;
  for (float x : v) s += (x - m) * (x - m);
  return s / v.size();
}

SceneParams small_choppy_scene() {
  SceneParams p;
  p.size_x = 32;
  p.size_z = 16;
  p.patch_x_m = 32.0;
  p.patch_z_m = 20.0;
  p.wind_speed_mps = 6.0;
  p.wind_dir_deg = 25.0;
  p.choppiness = 0.8;
  p.seed = 99;
  return p;
}

}  // namespace

TEST_CASE("every field is the real spectral sum of a Hermitian h(k,t)", "[sim][fields]") {
  for (SpectrumKind kind : {SpectrumKind::phillips, SpectrumKind::jonswap}) {
    SceneParams p = small_choppy_scene();
    p.spectrum = kind;
    p.fetch_m = 2000.0;
    Ocean ocean(p);
    const double t = 3.7;
    Frame f;
    ocean.evaluate(t, f, FrameRequest{true, true});
    const PlaneSpectrum s = testing::height_spectrum(ocean, t);

    double scale = 0.0;
    for (auto v : s.c) scale = std::max(scale, std::abs(v));
    REQUIRE(scale > 0.0);
    for (int kz = -p.size_z / 2 + 1; kz < p.size_z / 2; ++kz)
      for (int kx = -p.size_x / 2 + 1; kx < p.size_x / 2; ++kx)
        REQUIRE(std::abs(s.at(-kx, -kz) - std::conj(s.at(kx, kz))) < 1e-12 * scale);
    for (int k = -p.size_x / 2; k < p.size_x / 2; ++k) CHECK(s.at(k, -p.size_z / 2) == 0.0);  // Nyquist row
    for (int k = -p.size_z / 2; k < p.size_z / 2; ++k) CHECK(s.at(-p.size_x / 2, k) == 0.0);  // Nyquist column
    CHECK(s.at(0, 0) == 0.0);

    // Direct complex sums of each field's spectrum at every grid point: imaginary part zero, real
    // part equal to the FFT frame.
    const double lambda = p.choppiness;
    double max_imag = 0.0, err_h = 0.0, err_sx = 0.0, err_sz = 0.0, err_dx = 0.0, err_dz = 0.0, err_j = 0.0;
    double max_j_dev = 0.0;
    for (int zi = 0; zi < p.size_z; ++zi)
      for (int xi = 0; xi < p.size_x; ++xi) {
        std::complex<double> h = 0, sx = 0, sz = 0, dx = 0, dz = 0, dxx = 0, dzz = 0, dxz = 0;
        for (int kz = -p.size_z / 2; kz < p.size_z / 2; ++kz)
          for (int kx = -p.size_x / 2; kx < p.size_x / 2; ++kx) {
            const std::complex<double> v = s.at(kx, kz);
            if (v == 0.0) continue;
            const double kxm = 2 * pi * kx / p.patch_x_m, kzm = 2 * pi * kz / p.patch_z_m;
            const double k = std::hypot(kxm, kzm);
            const std::complex<double> e = v * std::polar(1.0, 2 * pi * (double(kx) * xi / p.size_x +
                                                                         double(kz) * zi / p.size_z));
            const std::complex<double> i(0.0, 1.0);
            h += e;
            sx += i * kxm * e;
            sz += i * kzm * e;
            dx += -i * (kxm / k) * lambda * e;
            dz += -i * (kzm / k) * lambda * e;
            dxx += lambda * kxm * kxm / k * e;
            dzz += lambda * kzm * kzm / k * e;
            dxz += lambda * kxm * kzm / k * e;
          }
        const int idx = zi * p.size_x + xi;
        max_imag = std::max({max_imag, std::fabs(h.imag()), std::fabs(sx.imag()), std::fabs(dx.imag())});
        err_h = std::max(err_h, std::fabs(h.real() - f.height[idx]));
        err_sx = std::max(err_sx, std::fabs(sx.real() - f.slope_x[idx]));
        err_sz = std::max(err_sz, std::fabs(sz.real() - f.slope_z[idx]));
        err_dx = std::max(err_dx, std::fabs(dx.real() - f.disp_x[idx]));
        err_dz = std::max(err_dz, std::fabs(dz.real() - f.disp_z[idx]));
        const double j = (1 + dxx.real()) * (1 + dzz.real()) - dxz.real() * dxz.real();
        err_j = std::max(err_j, std::fabs(j - f.jacobian[idx]));
        max_j_dev = std::max(max_j_dev, std::fabs(j - 1.0));
      }
    CAPTURE(static_cast<int>(kind));
    CHECK(max_imag < 1e-12);
    CHECK(err_h < 1e-5 * max_abs(f.height));
    CHECK(err_sx < 1e-5 * max_abs(f.slope_x));
    CHECK(err_sz < 1e-5 * max_abs(f.slope_z));
    CHECK(err_dx < 1e-5 * max_abs(f.disp_x));
    CHECK(err_dz < 1e-5 * max_abs(f.disp_z));
    CHECK(max_j_dev > 0.05);  // the test scene is really choppy
    CHECK(err_j < 1e-5 * max_j_dev);
  }
}

TEST_CASE("zero mean and Parseval hold for every frame", "[sim][fields]") {
  for (SpectrumKind kind : {SpectrumKind::phillips, SpectrumKind::jonswap}) {
    SceneParams p;
    p.spectrum = kind;
    p.choppiness = 1.0;
    Ocean ocean(p);
    Frame f;
    for (double t : {0.0, 1.5, 77.7, 123456.789}) {
      ocean.evaluate(t, f, FrameRequest{true, true});
      double spectral_h = 0.0, spectral_sx = 0.0;
      for (int kz = -p.size_z / 2; kz < p.size_z / 2; ++kz)
        for (int kx = -p.size_x / 2; kx < p.size_x / 2; ++kx) {
          const double a = std::norm(ocean.mode_amplitude(t, kx, kz));
          const double kxm = 2 * pi * kx / p.patch_x_m;
          spectral_h += a;
          spectral_sx += kxm * kxm * a;
        }
      CAPTURE(static_cast<int>(kind), t);
      const double var = variance(f.height);
      REQUIRE(var > 0.0);
      CHECK(std::fabs(mean(f.height)) < 1e-5 * std::sqrt(var));
      CHECK(std::fabs(mean(f.slope_x)) < 1e-5 * std::sqrt(variance(f.slope_x)));
      CHECK(std::fabs(mean(f.disp_z)) < 1e-5 * std::sqrt(variance(f.disp_z)));
      CHECK(var == Approx(spectral_h).epsilon(1e-4));
      CHECK(variance(f.slope_x) == Approx(spectral_sx).epsilon(1e-4));
    }
  }
}

TEST_CASE("the field is periodic: the spectral sum at x + L is the frame at x, tiles meet with no seam",
          "[sim][fields]") {
  const SceneParams p = small_choppy_scene();
  Ocean ocean(p);
  Frame f;
  const double t = 11.0;
  ocean.evaluate(t, f);
  const PlaneSpectrum s = testing::height_spectrum(ocean, t);
  const double tol = 1e-5 * max_abs(f.height);
  const double dx = p.patch_x_m / p.size_x, dz = p.patch_z_m / p.size_z;
  for (int zi = 0; zi < p.size_z; zi += 3)
    for (int xi = 0; xi < p.size_x; xi += 5) {
      const float h = f.height[zi * p.size_x + xi];
      CHECK(std::fabs(testing::evaluate_at(s, p.patch_x_m, p.patch_z_m, xi * dx + p.patch_x_m, zi * dz).real() - h) <
            tol);
      CHECK(std::fabs(testing::evaluate_at(s, p.patch_x_m, p.patch_z_m, xi * dx, zi * dz - p.patch_z_m).real() - h) <
            tol);
    }
  // Across the tile edge the step is like any other step inside the tile.
  double inner = 0.0, edge = 0.0;
  for (int zi = 0; zi < p.size_z; ++zi) {
    for (int xi = 0; xi + 1 < p.size_x; ++xi)
      inner = std::max<double>(inner, std::fabs(f.height[zi * p.size_x + xi + 1] - f.height[zi * p.size_x + xi]));
    edge = std::max<double>(edge, std::fabs(f.height[zi * p.size_x] - f.height[zi * p.size_x + p.size_x - 1]));
  }
  CHECK(edge <= 1.5 * inner);
}

TEST_CASE("spectral slopes match central differences to O(dx^2)", "[sim][fields]") {
  SceneParams p;
  p.wind_speed_mps = 20.0;
  p.small_wave_m = 6.0;  // only well-resolved waves
  Ocean ocean(p);
  // Relative RMS error of the central difference at spacing dx = patch / n.
  const auto error = [&](int n) {
    Frame f;
    ocean.evaluate_band(42.0, n, n, f);
    const double dx = p.patch_x_m / n;
    double err = 0.0, ref = 0.0;
    for (int z = 0; z < n; ++z)
      for (int x = 0; x < n; ++x) {
        const auto h = [&](int xx, int zz) { return double(f.height[((zz + n) % n) * n + (xx + n) % n]); };
        const double cx = (h(x + 1, z) - h(x - 1, z)) / (2 * dx);
        const double cz = (h(x, z + 1) - h(x, z - 1)) / (2 * dx);
        const double sx = f.slope_x[z * n + x], sz = f.slope_z[z * n + x];
        err += (cx - sx) * (cx - sx) + (cz - sz) * (cz - sz);
        ref += sx * sx + sz * sz;
      }
    return std::sqrt(err / ref);
  };
  const double e256 = error(256), e128 = error(128), e64 = error(64);
  CAPTURE(e256, e128, e64);
  CHECK(e256 < 0.01);
  CHECK(e128 / e256 == Approx(4.0).epsilon(0.2));  // second order: halving dx quarters the error
  CHECK(e64 / e128 == Approx(4.0).epsilon(0.2));
}

TEST_CASE("choppiness 0 gives no displacement and J = 1, any choppiness keeps mean J = 1", "[sim][choppy]") {
  SceneParams p;
  p.size_x = p.size_z = 128;
  p.patch_x_m = p.patch_z_m = 128.0;
  p.wind_speed_mps = 14.0;
  p.small_wave_m = 3.0;  // well-resolved waves, so central differences are a fair reference
  Frame f;
  {
    Ocean flat(p);  // choppiness 0
    flat.evaluate(5.0, f, FrameRequest{true, true});
    REQUIRE(f.disp_x.size() == f.height.size());
    CHECK(max_abs(f.disp_x) == 0.0);
    CHECK(max_abs(f.disp_z) == 0.0);
    CHECK(std::all_of(f.jacobian.begin(), f.jacobian.end(), [](float j) { return j == 1.0f; }));
  }
  for (double lambda : {0.5, 1.5, 3.0}) {
    p.choppiness = lambda;
    Ocean choppy(p);
    choppy.evaluate(5.0, f, FrameRequest{true, true});
    const auto [lo, hi] = std::minmax_element(f.jacobian.begin(), f.jacobian.end());
    CAPTURE(lambda);
    CHECK(*lo < 0.95f);
    CHECK(*hi > 1.05f);
    CHECK(mean(f.jacobian) == Approx(1.0).epsilon(2e-6));
    // J against central differences of the displacement itself.
    const int n = p.size_x;
    const double dx = p.patch_x_m / n;
    double err = 0.0, dev = 0.0;
    for (int z = 0; z < n; ++z)
      for (int x = 0; x < n; ++x) {
        const auto at = [&](const std::vector<float>& v, int xx, int zz) {
          return double(v[((zz + n) % n) * n + (xx + n) % n]);
        };
        const double dxx = (at(f.disp_x, x + 1, z) - at(f.disp_x, x - 1, z)) / (2 * dx);
        const double dzz = (at(f.disp_z, x, z + 1) - at(f.disp_z, x, z - 1)) / (2 * dx);
        const double dxz = (at(f.disp_x, x, z + 1) - at(f.disp_x, x, z - 1)) / (2 * dx);
        const double dzx = (at(f.disp_z, x + 1, z) - at(f.disp_z, x - 1, z)) / (2 * dx);
        const double j = (1 + dxx) * (1 + dzz) - dxz * dzx;
        err += (j - f.jacobian[z * n + x]) * (j - f.jacobian[z * n + x]);
        dev += (f.jacobian[z * n + x] - 1.0) * (f.jacobian[z * n + x] - 1.0);
      }
    CHECK(std::sqrt(err / dev) < 0.05);
  }
}
