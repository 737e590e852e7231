#include "client/render/camera_controls.hpp"

#include <algorithm>

namespace ocean::render {

void apply_fly_input(Camera& camera, const FlyInput& in, double dt_s, const FlySettings& s) {
  // Dragging right turns right (yaw is positive to the left); dragging up looks up.
  camera.yaw_rad -= static_cast<float>(in.look_dx_px) * s.look_rad_per_px;
  camera.pitch_rad -= static_cast<float>(in.look_dy_px) * s.look_rad_per_px;
  camera.pitch_rad = std::clamp(camera.pitch_rad, -1.55f, 1.55f);

  glm::dvec3 move{0.0};
  const glm::dvec3 f = glm::dvec3(camera.forward()), r = glm::dvec3(camera.right());
  if (in.forward) move += f;
  if (in.back) move -= f;
  if (in.right) move += r;
  if (in.left) move -= r;
  if (in.up) move.y += 1.0;
  if (in.down) move.y -= 1.0;
  if (glm::length(move) > 0.0) {
    const double speed = s.speed_m_per_s * (in.fast ? 10.0 : 1.0);
    camera.position += glm::normalize(move) * speed * dt_s;
  }
  camera.position.y = std::max(camera.position.y, static_cast<double>(s.min_eye_height_m));
}

}  // namespace ocean::render
