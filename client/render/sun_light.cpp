#include "client/render/sun_light.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::render {
namespace {

// Optical depths at the zenith: red's fitted so that the reference colour's channel ratios come
// out of a 12 degree sun; green and blue in Rayleigh's (680/550)^4 and (680/450)^4. Smaller than
// the air's true Rayleigh depths (0.04 at 680 nm): the reference colour was chosen by eye, and the
// ratios are what make a sunset.
constexpr float kRedDepth = 0.0157f;
constexpr glm::vec3 kDepth{kRedDepth, kRedDepth * 2.337f, kRedDepth * 5.213f};
constexpr float kDegreesPerRadian = 57.29578f;

}  // namespace

float air_mass(float elevation_rad) {
  const float h = std::max(elevation_rad, 0.0f);
  return 1.0f / (std::sin(h) + 0.50572f * std::pow(h * kDegreesPerRadian + 6.07995f, -1.6364f));
}

glm::vec3 transmittance(float elevation_rad) {
  const float m = air_mass(elevation_rad);
  return {std::exp(-kDepth.r * m), std::exp(-kDepth.g * m), std::exp(-kDepth.b * m)};
}

glm::vec3 sunlight(float elevation_rad) {
  const float set = std::clamp((elevation_rad * kDegreesPerRadian + 1.0f) / 2.0f, 0.0f, 1.0f);
  return kReferenceSunColour * transmittance(elevation_rad) / transmittance(kReferenceElevationRad) * set;
}

}  // namespace ocean::render
