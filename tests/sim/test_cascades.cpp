// Cascades (common/cascade.hpp): a band keeps exactly its waves; a storm's fine and coarse cascades
// hold the scene's energy once (no wave in both, none in neither); and their sum no longer repeats
// at the fine patch, its correlation at that lag being the one sea's of a single large lattice.
#include "cascade_scene.hpp"
#include "ocean.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace ocean::sim;
using ocean::model::SpectrumKind;
using ocean::model::SpreadingKind;

namespace {

SceneParams storm() {
  SceneParams p;
  p.spectrum = SpectrumKind::jonswap;
  p.wind_speed_mps = 20.0;
  p.wind_dir_deg = 20.0;
  p.seed = 9;
  return p;
}

// A storm at 256 m / 256 samples split at 16 cycles of the fine patch (16 m waves) = 128 of the coarse.
const ocean::Cascade kFine{1, 256, {16, 0}};
const ocean::Cascade kCoarse{8, 256, {0, 128}};

// Correlation between h(x) and h(x + lag) along x, over every row.
double lag_correlation(const std::vector<double>& h, int n, int lag) {
  double mean = 0.0;
  for (double v : h) mean += v;
  mean /= static_cast<double>(h.size());
  double cov = 0.0, var = 0.0;
  for (int z = 0; z < n; ++z)
    for (int x = 0; x < n; ++x) {
      const double a = h[z * n + x] - mean, b = h[z * n + (x + lag) % n] - mean;
      cov += a * b;
      var += a * a;
    }
  return cov / var;
}

}  // namespace

TEST_CASE("a band keeps exactly the waves inside its radii", "[cascade]") {
  SceneParams whole;
  whole.size_x = whole.size_z = 64;
  SceneParams banded = whole;
  banded.band = {4, 20};
  const Ocean a(whole), b(banded);
  int kept = 0;
  for (int kz = -31; kz < 32; ++kz)
    for (int kx = -31; kx < 32; ++kx) {
      const int r2 = kx * kx + kz * kz;
      const bool inside = r2 >= 16 && r2 < 400;
      INFO("wave (" << kx << ", " << kz << ")");
      if (inside) {
        CHECK(b.mode_amplitude(2.5, kx, kz) == a.mode_amplitude(2.5, kx, kz));
        kept += a.mode_amplitude(2.5, kx, kz) != std::complex<double>{};
      } else {
        CHECK(b.mode_amplitude(2.5, kx, kz) == std::complex<double>{});
      }
    }
  CHECK(kept > 1000);
  CHECK(b.expected_variance() < a.expected_variance());
  SceneParams bad = whole;
  bad.band = {20, 4};
  CHECK_THROWS_WITH(Ocean(bad), Catch::Contains("band"));
}

TEST_CASE("a storm's cascades hold its energy once", "[cascade]") {
  const SceneParams scene = storm();
  const Ocean fine(cascade_scene(scene, kFine, 0));
  const Ocean coarse(cascade_scene(scene, kCoarse, 1));
  // The one lattice both approximate: 2048 m at 1 m spacing, the scene's suppression length.
  SceneParams whole = scene;
  whole.patch_x_m = whole.patch_z_m = 2048.0;
  whole.size_x = whole.size_z = 2048;
  whole.small_wave_m = 0.5;
  const double v_fine = fine.expected_variance(), v_coarse = coarse.expected_variance();
  const double v_whole = Ocean(whole).expected_variance();
  std::printf("storm cascades: variance fine %.4f + coarse %.4f = %.4f m^2, one 2048 m lattice %.4f m^2\n", v_fine,
              v_coarse, v_fine + v_coarse, v_whole);
  CHECK(v_coarse > 10 * v_fine);  // a storm's energy is in its long waves
  CHECK(std::fabs(v_fine + v_coarse - v_whole) < 0.02 * v_whole);

  // No wave in both: a coarse wave at a multiple of 8 cycles is the fine lattice's wave / 8.
  int shared = 0, coarse_waves = 0;
  for (int kz = -127; kz < 128; ++kz)
    for (int kx = -127; kx < 128; ++kx) {
      if (coarse.mode_amplitude(0.0, kx, kz) == std::complex<double>{}) continue;
      ++coarse_waves;
      if (kx % 8 == 0 && kz % 8 == 0 && fine.mode_amplitude(0.0, kx / 8, kz / 8) != std::complex<double>{}) ++shared;
    }
  CHECK(coarse_waves > 40000);
  CHECK(shared == 0);
  // Separate draws: the cascades' waves at the same integer wavenumber are not copies.
  CHECK(std::abs(coarse.mode_amplitude(0.0, 3, 2)) / coarse.expected_variance() !=
        Approx(std::abs(Ocean(cascade_scene(scene, kCoarse, 0)).mode_amplitude(0.0, 3, 2)) / coarse.expected_variance()));
}

TEST_CASE("summed cascades repeat no sooner than the coarse patch", "[cascade]") {
  const SceneParams scene = storm();
  Ocean fine(cascade_scene(scene, kFine, 0));
  Ocean coarse(cascade_scene(scene, kCoarse, 1));
  Frame f, c;
  fine.evaluate(10.0, f, {false, false});
  coarse.evaluate(10.0, c, {false, false});
  // The sum on the coarse lattice's 8 m samples: fine repeats every 256 m = 32 samples.
  const int n = 256, step = 8;
  std::vector<double> fine_only(n * n), sum(n * n);
  for (int z = 0; z < n; ++z)
    for (int x = 0; x < n; ++x) {
      const double h_fine = f.height[((z * step) % 256) * 256 + (x * step) % 256];
      fine_only[z * n + x] = h_fine;
      sum[z * n + x] = h_fine + c.height[z * n + x];
    }
  SceneParams whole = scene;
  whole.patch_x_m = whole.patch_z_m = 2048.0;
  whole.size_x = whole.size_z = 2048;
  whole.small_wave_m = 0.5;
  Ocean one(whole);
  Frame w;
  one.evaluate(10.0, w, {false, false});
  std::vector<double> truth(n * n);
  for (int z = 0; z < n; ++z)
    for (int x = 0; x < n; ++x) truth[z * n + x] = w.height[(z * step) * 2048 + x * step];

  const double r_fine = lag_correlation(fine_only, n, 32), r_sum = lag_correlation(sum, n, 32);
  const double r_truth = lag_correlation(truth, n, 32);
  std::printf("correlation of h(x) and h(x + 256 m): one 256 m tile %.3f, cascades %.3f, one 2048 m lattice %.3f\n",
              r_fine, r_sum, r_truth);
  CHECK(r_fine == Approx(1.0));
  CHECK(std::fabs(r_sum) < 0.3);
  CHECK(std::fabs(r_sum - r_truth) < 0.15);
}
