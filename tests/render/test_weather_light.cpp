// WeatherLight: calm seas keep today's clear sky, storms get a deck that hides the sun, and a
// change of wind eases in.
#include "client/render/weather_light.hpp"

#include <catch2/catch.hpp>

using namespace ocean::render;

TEST_CASE("the wind sets the overcast: clear up to 10 m/s, heavy by 20", "[weather]") {
  CHECK(overcast_for_wind(0.0) == 0.0f);
  CHECK(overcast_for_wind(10.0) == 0.0f);
  CHECK(overcast_for_wind(15.0) == Approx(0.425f));
  CHECK(overcast_for_wind(20.0) == Approx(0.85f));
  CHECK(overcast_for_wind(60.0) == Approx(0.85f));
  CHECK(overcast_for_wind(14.0) < overcast_for_wind(16.0));
}

TEST_CASE("a clear sky is untouched; under a deck the sun's white turns grey", "[weather]") {
  const glm::vec3 blue{0.3f, 0.5f, 0.9f};
  CHECK(weathered(blue, 0.0f) == blue);
  const glm::vec3 sun = weathered(glm::vec3(1.0f), 0.85f);
  CHECK(sun.r < 0.7f);
  CHECK(sun.b > sun.r);  // the deck is a cool grey
}

TEST_CASE("a weather front eases in over seconds", "[weather]") {
  WeatherEase ease;
  CHECK(ease.update(5.0, 0.0) == 0.0f);
  const float one_second = ease.update(20.0, 1.0);
  CHECK(one_second > 0.1f);
  CHECK(one_second < 0.5f);
  for (int i = 0; i < 30; ++i) ease.update(20.0, 1.0);
  CHECK(ease.update(20.0, 1.0) == Approx(0.85f).margin(1e-3));
}

TEST_CASE("the glitter spreads with the wind and keeps its energy", "[weather]") {
  const float sharp = 600.0f;
  const GlitterLobe calm = glitter_for_wind(0.0, sharp);
  CHECK(calm.exponent == sharp);  // no wind: the sharp highlight alone, not drawn twice
  CHECK(calm.weight == 0.0f);
  float previous = sharp;
  for (double wind = 2.0; wind <= 30.0; wind += 2.0) {
    const GlitterLobe lobe = glitter_for_wind(wind, sharp);
    REQUIRE(lobe.exponent < previous);
    REQUIRE(lobe.weight == Approx((lobe.exponent + 1.0f) / (sharp + 1.0f) * (1.0f - lobe.exponent / sharp)));
    REQUIRE(lobe.weight < 0.3f);  // the peak of a wider lobe is dimmer
    previous = lobe.exponent;
  }
  // Half of Cox and Munk's mean square slope at 10 and 20 m/s: 0.0271 and 0.0527.
  CHECK(glitter_for_wind(10.0, sharp).exponent == Approx(2.0 / 0.02710 - 2.0).epsilon(1e-3));
  CHECK(glitter_for_wind(20.0, sharp).exponent == Approx(2.0 / 0.05270 - 2.0).epsilon(1e-3));
}
