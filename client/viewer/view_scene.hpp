// ViewScene: the renderer, HUD and camera every viewer front end draws with, set up the same way
// from the same options (renderer distances, camera pose). Its GL objects belong to the context
// current at init; release_gl() frees them while that context is still current.
#pragma once

#include <string>

#include "client/render/camera.hpp"
#include "client/render/hud_overlay.hpp"
#include "client/render/hull_renderer.hpp"
#include "client/render/renderer.hpp"

#include <vector>

namespace ocean::viewer {

// Where the camera starts: above (x_m, z_m) at eye_height_m, looking along -z turned by yaw.
struct CameraPose {
  float eye_height_m = 10.0f, pitch_deg = -6.0f, yaw_deg = 0.0f;
  float x_m = 0.0f, z_m = 0.0f;
};

struct ViewScene {
  render::Renderer renderer;
  render::HudOverlay hud;
  render::Camera camera;
  render::HullRenderer hull_renderer;
  std::vector<render::HullInstance> hulls;  // this frame's vessels, posed by the source
  std::vector<std::size_t> hulls_in_view;   // indices into hulls drawn by the last draw

  // Needs a current GL context. Inits the renderer and HUD and places the camera, its far plane
  // beyond the renderer's view distance. False with a reason.
  bool init(const render::RendererDesc& desc, const CameraPose& pose, std::string& error);
  // The water and sky, then the hulls on it, into the bound framebuffer.
  void draw(int width, int height, double t_s);
  void release_gl();
};

}  // namespace ocean::viewer
