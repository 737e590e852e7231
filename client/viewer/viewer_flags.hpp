// The command-line flags both viewers take (ocean-viewer and ocean-viewer-local), added to a
// CLI11 app in one place: output (--headless, --frames, --size, --screenshot, --json, --hud) and
// camera (--view-distance, --lod0, --eye-height, --pitch, --yaw); and --size's WIDTHxHEIGHT parse.
#pragma once

#include <string>

#include "client/render/renderer.hpp"
#include "client/viewer/view_scene.hpp"

namespace CLI {
class App;
}

namespace ocean::viewer {

struct CommonViewerOptions {
  bool headless = false;
  int frames = 0;  // 0: until closed (window) / the front end's headless default
  int width = 1280, height = 720;
  std::string size = "1280x720";  // --size as typed; parse_size fills width and height
  std::string screenshot;
  bool json = false;
  bool hud = false;  // headless only; the window toggles it with H
  bool foam_only = false;
  std::string sky_dir;  // empty: the built or installed sky (render::default_sky_dirs)
  float view_distance_m = 0.0f;
  float lod0_distance_m = 0.0f;
  float eye_height_m = 10.0f;
  float pitch_deg = -6.0f;
  float yaw_deg = 0.0f;
  float camera_x_m = 0.0f, camera_z_m = 0.0f;

  render::RendererDesc renderer_desc() const;
  CameraPose camera_pose() const;
};

// What differs between the front ends in the output flags' help.
struct OutputFlagsHelp {
  int headless_default_frames = 120;
  int max_frames = 1000000;
  const char* json = "print a JSON summary";
};

void add_output_flags(CLI::App& app, CommonViewerOptions& options, const OutputFlagsHelp& help);
void add_camera_flags(CLI::App& app, CommonViewerOptions& options);

// "1280x720" -> 1280, 720; each 1..16384.
bool parse_size(const std::string& text, int& width, int& height, std::string& error);

}  // namespace ocean::viewer
