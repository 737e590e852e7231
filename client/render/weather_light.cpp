#include "client/render/weather_light.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::render {

float overcast_for_wind(double wind_mps) {
  const double t = std::clamp((wind_mps - 10.0) / 10.0, 0.0, 1.0);
  return static_cast<float>(0.85 * t * t * (3.0 - 2.0 * t));
}

glm::vec3 weathered(glm::vec3 c, float overcast) {
  const float light = glm::dot(c, glm::vec3(0.3f, 0.5f, 0.2f));
  return glm::mix(c, kOvercastDeck * (0.6f + 0.4f * light), overcast);
}

GlitterLobe glitter_for_wind(double wind_mps, float sharp_exponent) {
  const double unresolved = 0.5 * (0.003 + 5.12e-3 * std::max(0.0, wind_mps));
  const float exponent = std::min(sharp_exponent, static_cast<float>(2.0 / unresolved - 2.0));
  // The sharp lobe's energy times how much wider than it the ripples make the broad one: nothing
  // on a calm, where the two would be one lobe drawn twice.
  return {exponent, (exponent + 1.0f) / (sharp_exponent + 1.0f) * (1.0f - exponent / sharp_exponent)};
}

float WeatherEase::update(double wind_mps, double dt_s) {
  const float target = overcast_for_wind(wind_mps);
  if (!started_) {
    started_ = true;
    overcast_ = target;
  } else {
    const double k = 1.0 - std::exp(-std::max(0.0, dt_s) / 3.0);
    overcast_ += static_cast<float>(k) * (target - overcast_);
  }
  return overcast_;
}

}  // namespace ocean::render
