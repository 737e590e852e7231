// SunLight: the reference sun is the default sky's; a lower sun is redder and dimmer, a higher one
// whiter, a set one dark; the air mass is Kasten and Young's.
#include "client/render/sun_light.hpp"

#include <cmath>

#include <catch2/catch.hpp>

using namespace ocean::render;

namespace {
constexpr float kDegree = 3.14159265f / 180.0f;
float blue_over_red(glm::vec3 c) { return c.b / c.r; }
}  // namespace

TEST_CASE("the air mass is one at the zenith and about 38 at the horizon", "[sun]") {
  CHECK(air_mass(90.0f * kDegree) == Approx(1.0f).margin(1e-3));
  CHECK(air_mass(30.0f * kDegree) == Approx(2.0f).margin(0.01));  // 1 / sin 30, the plane-parallel value
  CHECK(air_mass(0.0f) == Approx(37.9f).margin(0.3));
  CHECK(air_mass(-5.0f * kDegree) == air_mass(0.0f));
}

TEST_CASE("the sunlight at 12 degrees is the reference colour; lower is redder and dimmer", "[sun]") {
  const glm::vec3 reference = sunlight(kReferenceElevationRad);
  CHECK(reference.r == Approx(kReferenceSunColour.r));
  CHECK(reference.g == Approx(kReferenceSunColour.g));
  CHECK(reference.b == Approx(kReferenceSunColour.b));
  const glm::vec3 noon = sunlight(70.0f * kDegree), low = sunlight(4.0f * kDegree), setting = sunlight(0.5f * kDegree);
  CHECK(blue_over_red(noon) > blue_over_red(reference));
  CHECK(blue_over_red(noon) > 0.9f);  // a high sun is nearly white
  CHECK(blue_over_red(low) < 0.5f);   // golden
  CHECK(blue_over_red(setting) < blue_over_red(low));
  CHECK(low.r + low.g + low.b < reference.r + reference.g + reference.b);
  CHECK(glm::all(glm::equal(sunlight(-1.5f * kDegree), glm::vec3(0.0f))));
  for (float e = -2.0f; e < 89.0f; e += 0.1f) {  // continuous and rising with the sun
    const glm::vec3 a = sunlight(e * kDegree), b = sunlight((e + 0.1f) * kDegree);
    REQUIRE(a.r <= b.r + 1e-6f);
    REQUIRE(b.r - a.r < 0.15f);
  }
}
