// ViewScene: one renderer + HUD + camera setup for both viewers.
#include "client/viewer/view_scene.hpp"

#include <algorithm>

namespace ocean::viewer {

bool ViewScene::init(const render::RendererDesc& desc, const CameraPose& pose, std::string& error) {
  if (!renderer.init(desc)) {
    error = renderer.error();
    return false;
  }
  if (!hud.init(error)) return false;
  constexpr float kRadPerDeg = 3.14159265f / 180.0f;
  camera.position = {0.0, pose.eye_height_m, 0.0};
  camera.pitch_rad = pose.pitch_deg * kRadPerDeg;
  camera.yaw_rad = pose.yaw_deg * kRadPerDeg;
  camera.far_m = std::max(camera.far_m, renderer.desc().view_distance_m * 1.6f);
  return true;
}

void ViewScene::release_gl() {
  renderer.shutdown();
  hud.shutdown();
}

}  // namespace ocean::viewer
