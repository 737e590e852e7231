// The synthetic sea stands in for the server stream, so it must keep the stream's promises:
// periodic, zero-mean, slopes matching the heights, and a Jacobian averaging to one.
#include <cmath>

#include <catch2/catch.hpp>

#include "client/viewer/synthetic_sea.hpp"

using namespace ocean::viewer;

TEST_CASE("synthetic sea is periodic on its patch: a finer grid samples the same field") {
  SyntheticSeaParams p;
  p.n = 64;
  const SyntheticSea coarse(p);
  p.n = 128;
  const SyntheticSea fine(p);
  SeaFrame a, b;
  coarse.evaluate(12.5, a);
  fine.evaluate(12.5, b);
  for (int r = 0; r < 64; ++r)
    for (int c = 0; c < 64; ++c) REQUIRE(a.height[r * 64 + c] == Approx(b.height[(2 * r) * 128 + 2 * c]).margin(1e-4));
}

TEST_CASE("synthetic sea heights are zero-mean and bounded, slopes match central differences") {
  SyntheticSeaParams p;
  p.n = 128;
  const SyntheticSea sea(p);
  SeaFrame f;
  sea.evaluate(3.0, f);
  const int n = p.n;
  const float dx = p.patch_m / n;
  double mean = 0.0, max_err = 0.0, max_slope = 0.0;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      const float h = f.height[r * n + c];
      mean += h;
      REQUIRE(std::abs(h) <= sea.max_amplitude_m() + 1e-4f);
      const float cd = (f.height[r * n + (c + 1) % n] - f.height[r * n + (c + n - 1) % n]) / (2 * dx);
      max_err = std::max(max_err, double(std::abs(cd - f.slope_x[r * n + c])));
      max_slope = std::max(max_slope, double(std::abs(f.slope_x[r * n + c])));
    }
  }
  CHECK(std::abs(mean / (n * n)) < 1e-4);
  CHECK(max_slope > 0.05);
  CHECK(max_err < 0.05 * max_slope);  // O((k dx)^2) at 1 m spacing
}

TEST_CASE("synthetic sea Jacobian averages to one and folds somewhere at high steepness") {
  SyntheticSeaParams p;
  p.steepness = 1.1f;
  const SyntheticSea sea(p);
  SeaFrame f;
  sea.evaluate(7.0, f);
  double mean = 0.0;
  float min_j = 10.0f;
  for (float j : f.jacobian) {
    mean += j;
    min_j = std::min(min_j, j);
  }
  CHECK(mean / f.jacobian.size() == Approx(1.0).margin(1e-3));
  CHECK(min_j < 0.45f);
}

TEST_CASE("synthetic sea without chop streams heights and slopes only") {
  SyntheticSeaParams p;
  p.choppy = false;
  SeaFrame f;
  SyntheticSea(p).evaluate(0.0, f);
  CHECK(f.disp_x.empty());
  CHECK(f.jacobian.empty());
  CHECK(f.height.size() == std::size_t(p.n) * p.n);
}

TEST_CASE("synthetic sea rejects out-of-range parameters by name") {
  SyntheticSeaParams p;
  p.n = 2;
  CHECK_THROWS_WITH(SyntheticSea(p), Catch::Contains("n must be"));
  p = {};
  p.patch_m = -1.0f;
  CHECK_THROWS_WITH(SyntheticSea(p), Catch::Contains("patch_m"));
}
