// evaluate_band(n) must be the exact low-pass of the full frame (central n modes) sampled every
// size/n-th point, and must use the same h0 whatever the grid it is cut from.
#include "direct_fourier.hpp"
#include "field_stats.hpp"
#include "ocean.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <cstring>
#include <vector>

using namespace ocean::sim;

namespace {

using ocean::sim::test::max_abs;

// Low-pass of a full N_x x N_z real field to the modes |kx| < n_x/2, |kz| < n_z/2, sampled on n_x x n_z.
std::vector<double> low_pass(const std::vector<float>& full, int big_x, int big_z, int n_x, int n_z) {
  std::vector<std::complex<double>> grid(full.begin(), full.end());
  grid = testing::dft_axis(testing::dft_axis(grid, big_x, big_z, true, -1), big_x, big_z, false, -1);
  std::vector<std::complex<double>> kept(static_cast<std::size_t>(n_x) * n_z, 0.0);
  for (int kz = -n_z / 2 + 1; kz < n_z / 2; ++kz)
    for (int kx = -n_x / 2 + 1; kx < n_x / 2; ++kx)
      kept[((kz + n_z) % n_z) * n_x + (kx + n_x) % n_x] = grid[((kz + big_z) % big_z) * big_x + (kx + big_x) % big_x];
  kept = testing::dft_axis(testing::dft_axis(kept, n_x, n_z, true, +1), n_x, n_z, false, +1);
  std::vector<double> out(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) out[i] = kept[i].real();
  return out;
}

void check_low_pass(const std::vector<float>& full, const std::vector<float>& band, int big_x, int big_z, int n_x,
                    int n_z) {
  REQUIRE(band.size() == static_cast<std::size_t>(n_x) * n_z);
  const std::vector<double> expected = low_pass(full, big_x, big_z, n_x, n_z);
  double err = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < band.size(); ++i) {
    err = std::max(err, std::fabs(expected[i] - band[i]));
    scale = std::max(scale, std::fabs(expected[i]));
  }
  REQUIRE(scale > 0.0);
  CHECK(err < 2e-6 * max_abs(full));
}

}  // namespace

TEST_CASE("a band is the low-pass of the full frame", "[sim][band]") {
  SceneParams p;
  p.size_x = 128;
  p.size_z = 64;
  p.patch_x_m = 100.0;
  p.patch_z_m = 60.0;
  p.wind_speed_mps = 7.0;
  p.wind_dir_deg = -40.0;
  p.choppiness = 1.1;
  Ocean ocean(p);
  Frame full, band;
  const double t = 19.25;
  ocean.evaluate(t, full, FrameRequest{true, true});
  for (auto [n_x, n_z] : {std::pair{32, 16}, std::pair{16, 64}, std::pair{64, 32}}) {
    CAPTURE(n_x, n_z);
    ocean.evaluate_band(t, n_x, n_z, band, FrameRequest{true, true});
    CHECK(band.n_x == n_x);
    CHECK(band.n_z == n_z);
    CHECK(band.patch_x_m == p.patch_x_m);
    check_low_pass(full.height, band.height, p.size_x, p.size_z, n_x, n_z);
    check_low_pass(full.slope_x, band.slope_x, p.size_x, p.size_z, n_x, n_z);
    check_low_pass(full.slope_z, band.slope_z, p.size_x, p.size_z, n_x, n_z);
    check_low_pass(full.disp_x, band.disp_x, p.size_x, p.size_z, n_x, n_z);
    check_low_pass(full.disp_z, band.disp_z, p.size_x, p.size_z, n_x, n_z);
  }
}

TEST_CASE("the band of the grid's own size is the full frame, bit for bit", "[sim][band]") {
  SceneParams p;
  p.size_x = p.size_z = 64;
  p.choppiness = 0.7;
  Ocean ocean(p);
  Frame full, band;
  ocean.evaluate(2.5, full, FrameRequest{true, true});
  ocean.evaluate_band(2.5, 64, 64, band, FrameRequest{true, true});
  CHECK(std::memcmp(full.height.data(), band.height.data(), full.height.size() * sizeof(float)) == 0);
  CHECK(std::memcmp(full.jacobian.data(), band.jacobian.data(), full.jacobian.size() * sizeof(float)) == 0);
}

TEST_CASE("h0 does not depend on the grid: a 64 band is the same from a 128 and a 256 grid", "[sim][band]") {
  SceneParams p;
  p.small_wave_m = 0.5;  // the default follows the grid spacing; fix it to compare spectra
  SceneParams q = p;
  q.size_x = q.size_z = 128;
  Ocean big(p), small(q);
  Frame a, b;
  big.evaluate_band(8.0, 64, 64, a);
  small.evaluate_band(8.0, 64, 64, b);
  REQUIRE(a.height.size() == b.height.size());
  CHECK(std::memcmp(a.height.data(), b.height.data(), a.height.size() * sizeof(float)) == 0);
  CHECK(std::memcmp(a.slope_z.data(), b.slope_z.data(), a.slope_z.size() * sizeof(float)) == 0);
  // And the modes they share have the same amplitude.
  CHECK(big.mode_amplitude(3.0, 5, -9) == small.mode_amplitude(3.0, 5, -9));
  CHECK(small.mode_amplitude(3.0, 64, 0) == std::complex<double>(0.0));  // Nyquist of the small grid
  CHECK(big.mode_amplitude(3.0, 64, 0) != std::complex<double>(0.0));
}
