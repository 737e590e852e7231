// Preparing streamed samples for the grid: the wrap that makes tiles seamless, and slopes for
// streams that carry heights only.
#include <cmath>

#include <catch2/catch.hpp>

#include "client/render/periodic_field.hpp"

using namespace ocean::render;

TEST_CASE("expand_periodic wraps the last row and column onto the first and interleaves fields") {
  const int n = 3;
  const float a[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  const float b[9] = {10, 11, 12, 13, 14, 15, 16, 17, 18};
  std::vector<float> out;
  expand_periodic(n, {a, b}, out);
  REQUIRE(out.size() == 4u * 4u * 2u);
  const auto at = [&](int row, int col, int k) { return out[(row * 4 + col) * 2 + k]; };
  CHECK(at(1, 2, 0) == 5.0f);
  CHECK(at(1, 2, 1) == 15.0f);
  CHECK(at(0, 3, 0) == at(0, 0, 0));  // last column repeats the first
  CHECK(at(3, 1, 0) == at(0, 1, 0));  // last row repeats the first
  CHECK(at(3, 3, 1) == at(0, 0, 1));
}

TEST_CASE("central difference slopes of a lattice sine are exact for the discrete derivative") {
  const int n = 64;
  const float patch = 100.0f, k = 2.0f * 3.14159265f * 3.0f / patch;  // three waves per patch along x
  std::vector<float> h(n * n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) h[r * n + c] = 0.5f * std::sin(k * c * patch / n);
  std::vector<float> sx, sz;
  central_difference_slopes(n, patch, patch, h.data(), sx, sz);
  // The central difference of sin(k x) is exactly cos(k x) sin(k dx) / dx.
  const float dx = patch / n;
  for (int c = 0; c < n; ++c) {
    CHECK(sx[5 * n + c] == Approx(0.5f * std::sin(k * dx) / dx * std::cos(k * c * dx)).margin(1e-5));
    CHECK(sz[5 * n + c] == Approx(0.0f).margin(1e-6));
  }
}
