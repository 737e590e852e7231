// The generated sky: the sun disc is the one brightest spot (the renderer finds the sun by it),
// the zenith is bluer and darker than the horizon.
#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>

#include "assets/skygen/sky_model.hpp"
#include "assets/skygen/value_noise.hpp"

using namespace ocean::assets;

TEST_CASE("only the sun disc reaches full brightness") {
  SkyModel sky;
  sky.cloud_cover = 0.6f;
  CHECK(glm::all(glm::equal(sky_colour(sky, sky.sun_direction), glm::vec3(1.0f))));
  int checked = 0;
  for (float az = 0.0f; az < 6.28f; az += 0.05f) {
    for (float el = -0.5f; el < 1.5f; el += 0.05f) {
      const glm::vec3 d{std::cos(az) * std::cos(el), std::sin(el), std::sin(az) * std::cos(el)};
      if (glm::dot(d, sky.sun_direction) > std::cos(sky.sun_radius_rad)) continue;
      const glm::vec3 c = sky_colour(sky, d);
      REQUIRE(std::max({c.r, c.g, c.b}) < 0.95f);
      ++checked;
    }
  }
  CHECK(checked > 1000);
}

TEST_CASE("the clear-sky zenith is darker and bluer than the horizon") {
  SkyModel sky;
  sky.cloud_cover = 0.0f;
  const glm::vec3 away = -glm::normalize(glm::vec3(sky.sun_direction.x, 0.0f, sky.sun_direction.z));
  const glm::vec3 zenith = sky_colour(sky, {0.0f, 1.0f, 0.0f});
  const glm::vec3 horizon = sky_colour(sky, glm::normalize(away + glm::vec3(0.0f, 0.01f, 0.0f)));
  CHECK(zenith.b > zenith.r + 0.3f);
  CHECK(horizon.r + horizon.g + horizon.b > zenith.r + zenith.g + zenith.b + 0.5f);
}

TEST_CASE("value noise stays in [0, 1], is continuous and depends on the seed") {
  float previous = value_noise(0.0f, 0.3f, 1);
  bool differs = false;
  for (float x = 0.0f; x < 20.0f; x += 0.01f) {
    const float v = value_noise(x, 0.3f, 1);
    REQUIRE(v >= 0.0f);
    REQUIRE(v <= 1.0f);
    REQUIRE(std::abs(v - previous) < 0.05f);
    previous = v;
    differs = differs || std::abs(v - value_noise(x, 0.3f, 2)) > 0.1f;
  }
  CHECK(differs);
}

TEST_CASE("a sun at the default 12 degrees paints the default sky; a low one reddens round it", "[sun]") {
  const float degree = 3.14159265f / 180.0f;
  const SkyModel noon_ish = sky_for_sun(20.0f * degree, 12.0f * degree);
  const SkyModel plain;
  CHECK(noon_ish.sunset == 0.0f);
  CHECK(noon_ish.glow_colour == plain.glow_colour);
  CHECK(noon_ish.glow_strength == plain.glow_strength);
  CHECK(glm::length(noon_ish.sun_direction - plain.sun_direction) < 0.01f);

  SkyModel low = sky_for_sun(0.0f, 3.0f * degree);
  SkyModel high = sky_for_sun(0.0f, 12.0f * degree);
  low.cloud_cover = high.cloud_cover = 0.0f;
  CHECK(low.sunset > 0.5f);
  // Just above the horizon, 10 degrees to the side of the sun: warmer under the low sun.
  const glm::vec3 beside = glm::normalize(glm::vec3(std::sin(10.0f * degree), 0.05f, -std::cos(10.0f * degree)));
  const glm::vec3 a = sky_colour(low, beside), b = sky_colour(high, beside);
  CHECK(a.b / a.r < b.b / b.r - 0.2f);
  // The disc is still the one brightest spot, so the renderer finds the low sun.
  CHECK(glm::all(glm::equal(sky_colour(low, low.sun_direction), glm::vec3(1.0f))));
  CHECK(std::max({a.r, a.g, a.b}) < 0.95f);
}
