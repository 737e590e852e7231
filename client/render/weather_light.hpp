// WeatherLight: how the wind changes the light. A storm's sky is a cloud deck that hides the sun
// and greys the sea; the scene states only its wind, so the look follows it - clear up to
// 10 m/s, heavily overcast by 20 m/s - and eases over a few seconds when a weather front
// changes the wind, rather than switching between two frames.
#pragma once

#include <glm/glm.hpp>

namespace ocean::render {

// The cloud deck's colour where it covers the sky fully (its own brightness varies with what it
// covers, so clouds still show through as light and dark).
inline constexpr glm::vec3 kOvercastDeck{0.50f, 0.54f, 0.58f};

// 0 (clear) .. 0.85 (the sky almost all deck), smooth in the wind speed.
float overcast_for_wind(double wind_mps);

// The sky colour c under an overcast share: what the sky and ocean shaders compute per pixel
// (weathered() in sky.frag.glsl and ocean.frag.glsl), for the colours the CPU keeps.
glm::vec3 weathered(glm::vec3 c, float overcast);

// The sun's glitter off ripples the grid does not resolve: a Phong lobe on the resolved normal's
// reflection whose width is their mean square slope, half of Cox and Munk's (1954) clean-surface
// 0.003 + 5.12e-3 U (the other half the grid resolves), and whose energy is the sharp lobe's
// (`sharp_exponent`) times the share by which it is wider: none on a calm, whose highlight stays a
// point; a gale's sun spreads into a long path of light.
struct GlitterLobe {
  float exponent = 0.0f;
  float weight = 0.0f;
};
GlitterLobe glitter_for_wind(double wind_mps, float sharp_exponent);

// Eases the shown overcast toward the wind's, time constant 3 s; the first value is taken at once.
class WeatherEase {
 public:
  float update(double wind_mps, double dt_s);

 private:
  bool started_ = false;
  float overcast_ = 0.0f;
};

}  // namespace ocean::render
