// WhitecapCover: Monahan's cover at each wind, reached on whatever Jacobians the frame has and over
// the foam already there.
#include "client/render/whitecap_cover.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using ocean::render::kFoamBand;
using ocean::render::WhitecapCover;

namespace {

// The mean of the shader's foam ramp over the samples.
double shaded_cover(const std::vector<float>& j, float threshold, float band = kFoamBand) {
  double sum = 0.0;
  for (float v : j) sum += std::clamp((threshold - v) / band, 0.0f, 1.0f);
  return sum / static_cast<double>(j.size());
}

// A sea's Jacobian: mostly near 1, with a skewed tail of folds; `depth` scales the tail (a finer
// grid or a choppier sea folds deeper).
std::vector<float> jacobians(std::size_t n, double depth, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<float> out(n);
  for (float& v : out) {
    const double x = g(rng);
    v = static_cast<float>(1.0 + 0.08 * x - depth * std::max(0.0, -x) * std::max(0.0, -x));
  }
  return out;
}

}  // namespace

TEST_CASE("whitecap cover: Monahan and O'Muircheartaigh's power law, none without wind", "[foam]") {
  CHECK(WhitecapCover::observed(0.0) == 0.0);
  CHECK(WhitecapCover::observed(-3.0) == 0.0);
  CHECK(WhitecapCover::observed(8.0) == Approx(0.0046).epsilon(0.02));
  CHECK(WhitecapCover::observed(12.0) == Approx(0.018).epsilon(0.03));
  CHECK(WhitecapCover::observed(15.0) == Approx(0.039).epsilon(0.03));
  CHECK(WhitecapCover::observed(20.0) == Approx(0.106).epsilon(0.02));
  CHECK(WhitecapCover::observed(200.0) == 0.5);  // bounded where the formula leaves its data
}

TEST_CASE("whitecap cover: the threshold covers the observed share on a shallow and a deep fold", "[foam]") {
  for (const double depth : {0.05, 0.3}) {  // a coarse mobile grid, a fine desktop one
    const std::vector<float> j = jacobians(64 * 64, depth, 7);
    for (const double wind : {8.0, 12.0, 15.0, 20.0}) {
      WhitecapCover cover;
      cover.set_wind_mps(wind);
      const auto shading = cover.update(j, {}, 0.033);
      INFO("depth " << depth << " wind " << wind << " threshold " << shading.threshold);
      const double want = WhitecapCover::observed(wind);
      CHECK(shaded_cover(j, shading.threshold, shading.band) == Approx(want).epsilon(0.02));
      CHECK(shading.cover == Approx(want).epsilon(0.02));  // the far field's mean, the same share
      CHECK(shading.threshold <= 1.0f);
    }
  }
}

TEST_CASE("whitecap cover: a sea that does not fold keeps its foam where it compresses", "[foam]") {
  WhitecapCover cover;
  cover.set_wind_mps(20.0);
  const std::vector<float> flat(4096, 1.0f);  // no choppiness: J is 1 everywhere
  const auto shading = cover.update(flat, {}, 0.033);
  CHECK(shading.threshold == 1.0f);
  CHECK(shading.cover == 0.0f);
  CHECK(shaded_cover(flat, shading.threshold, shading.band) == 0.0);
  cover.set_wind_mps(0.0);
  CHECK(cover.update(jacobians(4096, 0.3, 1), {}, 0.033).cover == 0.0f);  // no wind, no whitecaps
}

TEST_CASE("whitecap cover: the threshold follows a changing sea over about half a second", "[foam]") {
  WhitecapCover cover;
  cover.set_wind_mps(15.0);
  const std::vector<float> calm = jacobians(4096, 0.05, 3), deep = jacobians(4096, 0.3, 3);
  const float start = cover.update(calm, {}, 0.033).threshold;
  WhitecapCover reference;
  reference.set_wind_mps(15.0);
  const float deep_threshold = reference.update(deep, {}, 0.033).threshold;
  REQUIRE(std::fabs(deep_threshold - start) > 0.01f);
  const float after_frame = cover.update(deep, {}, 0.033).threshold;
  CHECK(std::fabs(after_frame - start) < 0.1f * std::fabs(deep_threshold - start));  // no jump in a frame
  for (int i = 0; i < 120; ++i) cover.update(deep, {}, 0.033);  // 4 s: e^-8 of the way left
  CHECK(cover.update(deep, {}, 0.033).threshold == Approx(deep_threshold).margin(1e-3));
  // A large grid is read through a strided subset; its share holds all the same.
  const std::vector<float> big = jacobians(256 * 256, 0.3, 11);
  WhitecapCover large;
  large.set_wind_mps(20.0);
  const auto big_shading = large.update(big, {}, 0.033);
  CHECK(shaded_cover(big, big_shading.threshold, big_shading.band) == Approx(WhitecapCover::observed(20.0)).epsilon(0.05));
}

TEST_CASE("whitecap cover: foam earlier folds left counts towards the share; new folds make up the rest",
          "[foam]") {
  const std::vector<float> j = jacobians(64 * 64, 0.3, 5);
  const double want = WhitecapCover::observed(15.0);
  for (const double left : {0.0, 0.5, 1.5}) {  // what is already there, as a share of the cover
    std::vector<float> past(j.size(), 0.0f);
    for (std::size_t i = 0; i < past.size(); i += 7) past[i] = static_cast<float>(std::min(1.0, 7.0 * want * left));
    WhitecapCover cover;
    cover.set_wind_mps(15.0);
    const auto shading = cover.update(j, past, 0.033);
    double drawn = 0.0;
    for (std::size_t i = 0; i < j.size(); ++i)
      drawn += std::max(std::clamp((shading.threshold - j[i]) / shading.band, 0.0f, 1.0f), past[i]);
    drawn /= static_cast<double>(j.size());
    INFO("left " << left << " threshold " << shading.threshold << " band " << shading.band);
    if (left < 1.0)
      CHECK(drawn == Approx(want).epsilon(0.05));
    else
      CHECK(drawn == Approx(left * want).epsilon(0.05));  // more than the cover already: no new foam
    CHECK(shading.cover == Approx(drawn).epsilon(0.05));
    CHECK(shading.band > 0.0f);
    CHECK(shading.band <= ocean::render::kFoamBand);
  }
}
