// ViewScene: one renderer + HUD + camera setup for both viewers.
#include "client/viewer/view_scene.hpp"

#include <algorithm>

namespace ocean::viewer {

bool ViewScene::init(const render::RendererDesc& desc, const CameraPose& pose, std::string& error) {
  if (!renderer.init(desc)) {
    error = renderer.error();
    return false;
  }
  if (!hud.init(error) || !hull_renderer.init(error)) return false;
  camera.place({pose.x_m, pose.eye_height_m, pose.z_m}, pose.pitch_deg, pose.yaw_deg);
  camera.far_m = std::max(camera.far_m, renderer.desc().view_distance_m * 1.6f);
  return true;
}

void ViewScene::draw(int width, int height, double t_s) {
  renderer.draw(camera, width, height, t_s);
  hulls_in_view = hull_renderer.draw(camera, width, height, hulls, render::hull_light(renderer));
}

void ViewScene::release_gl() {
  renderer.shutdown();
  hud.shutdown();
  hull_renderer.shutdown();
}

}  // namespace ocean::viewer
