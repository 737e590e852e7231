#include "assets/skygen/sky_model.hpp"

#include <algorithm>
#include <cmath>

#include "assets/skygen/value_noise.hpp"
#include "client/render/sun_light.hpp"

namespace ocean::assets {

namespace {

float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace

SkyModel sky_for_sun(float azimuth_rad, float elevation_rad) {
  SkyModel sky;
  sky.sun_direction = {std::sin(azimuth_rad) * std::cos(elevation_rad), std::sin(elevation_rad),
                       -std::cos(azimuth_rad) * std::cos(elevation_rad)};
  const float low = smoothstep(render::kReferenceElevationRad, 0.0f, elevation_rad);
  if (low > 1e-3f) {  // the default 12 degrees exactly, whatever its rounding
    const glm::vec3 t = render::transmittance(elevation_rad) / render::transmittance(render::kReferenceElevationRad);
    const glm::vec3 glow = sky.glow_colour * t;
    sky.glow_colour = glow / std::max({glow.r, glow.g, glow.b});
    sky.glow_strength = 0.30f + 0.2f * low;
    sky.glow_power = 8.0f - 4.0f * low;
    sky.sunset = low;
  }
  return sky;
}

glm::vec3 sky_colour(const SkyModel& sky, const glm::vec3& direction) {
  const glm::vec3 d = glm::normalize(direction);
  const float y = d.y;
  glm::vec3 c;
  if (y >= 0.0f) {
    c = glm::mix(sky.zenith_colour, sky.horizon_colour, std::pow(1.0f - y, 4.0f));
  } else {
    c = glm::mix(sky.horizon_colour, sky.below_horizon_colour, smoothstep(0.0f, 0.25f, -y));
  }

  const float cos_sun = glm::dot(d, sky.sun_direction);
  const float toward_sun = std::max(cos_sun, 0.0f);
  const float horizon_band = 1.0f - std::min(std::abs(y), 1.0f);
  // Round a low sun the sky takes the glow's colour (mixed, not added: added, it whitens at the clamp).
  c = glm::mix(c, sky.glow_colour * 0.9f, sky.sunset * 0.8f * std::pow(toward_sun, 3.0f) * horizon_band);
  c += sky.glow_colour * (sky.glow_strength * std::pow(toward_sun, sky.glow_power) * horizon_band + 0.35f * std::pow(toward_sun, 600.0f));

  if (y > 0.03f) {  // the band just above the horizon stays cloud-free: it is the fog colour
    // Clouds on a plane: coordinates grow toward the horizon, so clouds shrink into the distance.
    const glm::vec2 p = glm::vec2(d.x, d.z) / (y + 0.08f) * 1.6f;
    const float n = fractal_noise(p.x + 3.0f, p.y - 5.0f, 5, sky.seed);
    const float cover = smoothstep(1.0f - sky.cloud_cover - 0.1f, 1.0f - sky.cloud_cover + 0.25f, n);
    const float fade = smoothstep(0.03f, 0.2f, y);
    const float lit = 0.80f + 0.15f * std::pow(toward_sun, 4.0f) + 0.08f * (n - 0.5f);
    const glm::vec3 cloud = glm::vec3(lit, lit, lit * 1.02f) *
                            glm::mix(glm::vec3(1.0f), sky.glow_colour, sky.sunset * std::pow(toward_sun, 2.0f));
    c = glm::mix(c, cloud, cover * fade * 0.9f);
  }
  c = glm::min(c, glm::vec3(0.94f));

  const float angle = std::acos(std::clamp(cos_sun, -1.0f, 1.0f));
  const float disc = 1.0f - smoothstep(sky.sun_radius_rad * 0.8f, sky.sun_radius_rad, angle);
  return glm::mix(c, glm::vec3(1.0f), disc);
}

}  // namespace ocean::assets
