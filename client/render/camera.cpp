#include "client/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace ocean::render {

void Camera::place(const glm::dvec3& at, double pitch_deg, double yaw_deg) {
  position = at;
  pitch_rad = static_cast<float>(glm::radians(std::clamp(pitch_deg, -89.0, 89.0)));
  yaw_rad = static_cast<float>(glm::radians(yaw_deg));
}

glm::vec3 Camera::forward() const {
  const float cp = std::cos(pitch_rad);
  return {-std::sin(yaw_rad) * cp, std::sin(pitch_rad), -std::cos(yaw_rad) * cp};
}

glm::vec3 Camera::right() const { return {std::cos(yaw_rad), 0.0f, -std::sin(yaw_rad)}; }

glm::mat4 Camera::rotation_view() const {
  // Up is derived from right x forward so lookAt stays defined even when looking straight down.
  const glm::vec3 f = forward();
  const glm::vec3 up = glm::cross(right(), f);
  return glm::lookAt(glm::vec3(0.0f), f, up);
}

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspective(fov_y_rad, aspect, near_m, far_m);
}

glm::mat4 Camera::clip_from_relative(float aspect) const {
  return projection(aspect) * rotation_view();
}

}  // namespace ocean::render
