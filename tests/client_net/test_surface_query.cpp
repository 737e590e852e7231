// SurfaceQuery: the height and normal of the water a client decoded, at any world point - against
// waves written here whose surface is known in closed form: a plain wave, the wake's square, and a
// choppy (Gerstner) wave whose water drawn at x came from elsewhere.
#include "frame_channels.hpp"
#include "surface_query.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace ocean;
using ocean::client::FrameChannels;
using ocean::codec::SurfaceQuery;
using std::numbers::pi;

namespace {

codec::StreamConfig one_lattice(int n, double patch_m) {
  codec::StreamConfig c;
  c.grid = n;
  c.patch_x_m = c.patch_z_m = patch_m;
  return c;
}

// A wave along x: height a cos(k x) and its slope, and (choppy) the displacement -lambda a sin(k x)
// that turns it into a Gerstner wave; sampled on the lattice at `samples_at`.
void wave(const codec::StreamConfig& c, FrameChannels& f, double a, double k, double lambda) {
  const std::size_t total = c.samples(), n = static_cast<std::size_t>(c.grid);
  for (auto* v : {&f.height, &f.slope_x, &f.slope_z}) v->assign(total, 0.0f);
  if (lambda > 0.0)
    for (auto* v : {&f.disp_x, &f.disp_z}) v->assign(total, 0.0f);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const double x = static_cast<double>(i) * c.patch_x_m / static_cast<double>(n);
      f.height[j * n + i] = static_cast<float>(a * std::cos(k * x));
      f.slope_x[j * n + i] = static_cast<float>(-a * k * std::sin(k * x));
      if (lambda > 0.0) f.disp_x[j * n + i] = static_cast<float>(-lambda * a * std::sin(k * x));
    }
}

}  // namespace

TEST_CASE("the surface between samples: heights and normals of a wave, repeating with the tile", "[surface]") {
  const codec::StreamConfig c = one_lattice(64, 64.0);
  FrameChannels f;
  const double a = 0.8, k = 2.0 * pi * 3.0 / 64.0;
  wave(c, f, a, k, 0.0);
  const SurfaceQuery query(c);
  for (double x = -200.0; x < 200.0; x += 7.3) {
    const double z = 0.37 * x;
    INFO("x " << x);
    // Linear interpolation of a cosine misses by at most a (k dx)^2 / 8 (dx = 1 m).
    CHECK(query.height_at(f, x, z) == Approx(a * std::cos(k * x)).margin(1.02 * a * k * k / 8.0));
    CHECK(query.height_at(f, x + 64.0, z - 128.0) == Approx(query.height_at(f, x, z)).margin(1e-9));
    const auto n = query.normal_at(f, x, z);
    const double s = -a * k * std::sin(k * x), length = std::sqrt(1.0 + s * s);
    CHECK(n[0] == Approx(-s / length).margin(0.01));
    CHECK(n[1] == Approx(1.0 / length).margin(0.01));
    CHECK(n[2] == Approx(0.0).margin(1e-12));
  }
}

TEST_CASE("the wake adds on its own square only, once", "[surface]") {
  codec::StreamConfig c = one_lattice(16, 64.0);
  c.wake = {16, 128.0, -64.0, -32.0, 0.05, 1e-6, 1800};
  FrameChannels f;
  f.height.assign(c.samples(), 0.0f);
  f.slope_x.assign(c.samples(), 0.0f);
  f.slope_z.assign(c.samples(), 0.0f);
  for (std::size_t s = 16 * 16; s < c.samples(); ++s) f.height[s] = 0.5f;  // the wake's lattice
  const SurfaceQuery query(c);
  CHECK(query.height_at(f, 0.0, 0.0) == Approx(0.5));
  CHECK(query.height_at(f, -63.9, -31.9) == Approx(0.5));
  CHECK(query.height_at(f, 63.9, 95.9) == Approx(0.5));
  CHECK(query.height_at(f, -64.1, 0.0) == 0.0);
  CHECK(query.height_at(f, 64.1, 0.0) == 0.0);
  CHECK(query.height_at(f, 0.0, 96.1) == 0.0);
  CHECK(query.height_at(f, 128.0 + 1.0, 0.0) == 0.0);  // not repeated
}

TEST_CASE("on a choppy stream the height at x is the water displaced there, not the sample at x", "[surface]") {
  const codec::StreamConfig c = one_lattice(128, 128.0);
  FrameChannels f;
  const double a = 1.0, k = 2.0 * pi * 4.0 / 128.0, lambda = 1.0;  // k a lambda = 0.2: steep, no fold
  wave(c, f, a, k, lambda);
  const SurfaceQuery query(c);
  double worst = 0.0, worst_unshifted = 0.0;
  for (double x = 0.0; x < 128.0; x += 1.37) {
    // The Gerstner surface: the point p with p - lambda a sin(k p) = x, by Newton to the last bit.
    double p = x;
    for (int i = 0; i < 50; ++i) p -= (p - lambda * a * std::sin(k * p) - x) / (1.0 - lambda * a * k * std::cos(k * p));
    const double truth = a * std::cos(k * p);
    worst = std::max(worst, std::fabs(query.height_at(f, x, 3.0) - truth));
    worst_unshifted = std::max(worst_unshifted, std::fabs(a * std::cos(k * x) - truth));
    CHECK(query.at(f, x, 3.0).source_x_m == Approx(p).margin(0.05));
  }
  std::printf("choppy query: worst height error %.4f m (reading the sample under x instead: %.3f m)\n", worst,
              worst_unshifted);
  CHECK(worst < 0.01 * a);
  CHECK(worst_unshifted > 0.1 * a);  // the inversion matters
}
