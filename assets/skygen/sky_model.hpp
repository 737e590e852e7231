// The procedural daytime sky painted into the cube map: a zenith-to-horizon gradient, a sun disc
// with its glow, and value-noise clouds on a virtual cloud plane. Pure: direction in, colour out.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace ocean::assets {

struct SkyModel {
  glm::vec3 sun_direction = glm::normalize(glm::vec3(0.34f, 0.21f, -0.92f));
  glm::vec3 zenith_colour{0.16f, 0.36f, 0.70f};
  glm::vec3 horizon_colour{0.74f, 0.83f, 0.91f};
  glm::vec3 below_horizon_colour{0.50f, 0.60f, 0.68f};
  glm::vec3 glow_colour{1.00f, 0.80f, 0.55f};
  float glow_strength = 0.30f;  // the glow along the horizon toward the sun
  float glow_power = 8.0f;      // how closely it gathers round the sun
  float sunset = 0.0f;          // 0 .. 1: how much the glow colours the sky and clouds round a low sun
  float sun_radius_rad = 0.012f;
  float cloud_cover = 0.45f;  // 0 clear .. 1 overcast
  std::uint32_t seed = 7;
};

// The default sky with its sun at azimuth (clockwise from -z toward +x) and elevation, radians. A
// sun lower than the default's 12 degrees reddens its glow as its light does (render::sunlight),
// and the glow grows and spreads along the horizon; at 12 degrees and above the sky is the default's.
SkyModel sky_for_sun(float azimuth_rad, float elevation_rad);

// Display colour in [0, 1]. Only the sun disc reaches 1.0; everything else stays below 0.95 so a
// reader can find the sun as the brightest spot (see ocean::render::estimate_sun_direction).
glm::vec3 sky_colour(const SkyModel& sky, const glm::vec3& direction);

}  // namespace ocean::assets
