// The viewer's eye: a position, a yaw/pitch orientation and a perspective lens.
// Pure math (glm, no GL): everything downstream works camera-relative (point - position), so the
// matrices here rotate and project only, and far-away tiles keep float precision.
#pragma once

#include <glm/glm.hpp>

namespace ocean::render {

struct Camera {
  glm::dvec3 position{0.0, 8.0, 0.0};  // metres, +y up, sea level at y = 0
  float yaw_rad = 0.0f;                 // about +y; 0 looks along -z, positive turns left
  float pitch_rad = 0.0f;               // positive looks up
  float fov_y_rad = 1.0471976f;         // 60 degrees
  float near_m = 0.5f;
  float far_m = 4000.0f;

  // At `position`, turned as the viewers' --pitch and --yaw say (degrees; pitch within +-89).
  void place(const glm::dvec3& at, double pitch_deg, double yaw_deg);

  glm::vec3 forward() const;  // unit view direction
  glm::vec3 right() const;    // unit, horizontal
  // World-to-eye rotation with the eye at the origin (camera-relative space).
  glm::mat4 rotation_view() const;
  glm::mat4 projection(float aspect) const;
  // Clip coordinates of a camera-relative point (world point minus position).
  glm::mat4 clip_from_relative(float aspect) const;
};

}  // namespace ocean::render
