// The viewers' shared flags and the WIDTHxHEIGHT parse.
#include "client/viewer/viewer_flags.hpp"

#include <cstdio>

#include <CLI/CLI.hpp>

namespace ocean::viewer {

render::RendererDesc CommonViewerOptions::renderer_desc() const {
  render::RendererDesc desc;
  desc.view_distance_m = view_distance_m;
  desc.lod0_distance_m = lod0_distance_m;
  desc.foam_only = foam_only;
  desc.sky_dir = sky_dir.empty() ? nullptr : sky_dir.c_str();
  return desc;
}

CameraPose CommonViewerOptions::camera_pose() const { return {eye_height_m, pitch_deg, yaw_deg, camera_x_m, camera_z_m}; }

void add_output_flags(CLI::App& app, CommonViewerOptions& o, const OutputFlagsHelp& help) {
  app.add_flag("--headless", o.headless, "render off-screen through EGL, no window");
  app.add_option("--frames", o.frames,
                 "frames to render, then exit (headless default " + std::to_string(help.headless_default_frames) + ")")
      ->check(CLI::Range(0, help.max_frames));
  app.add_option("--size", o.size, "WIDTHxHEIGHT in pixels");
  app.add_option("--screenshot", o.screenshot, "write the last rendered frame to this PNG");
  app.add_flag("--json", o.json, help.json);
  app.add_flag("--hud", o.hud, "draw the HUD in headless mode too");
  app.add_flag("--foam-only", o.foam_only,
               "draw the water's foam term alone (red: foam 0..1, green: water; no sky), to measure whitecap cover");
  app.add_option("--sky", o.sky_dir,
                 "folder with the sky's six faces (px.png .. nz.png, as ocean-skygen paints them): its sun lights the sea")
      ->check(CLI::ExistingDirectory);
}

void add_camera_flags(CLI::App& app, CommonViewerOptions& o) {
  app.add_option("--view-distance", o.view_distance_m, "metres to draw tiles out to (0 = renderer default)")
      ->check(CLI::Range(0.0f, 100000.0f));
  app.add_option("--lod0", o.lod0_distance_m, "full-detail radius, metres (0 = renderer default)")
      ->check(CLI::Range(0.0f, 100000.0f));
  app.add_option("--eye-height", o.eye_height_m, "camera height above sea level, metres")->check(CLI::Range(1.0f, 10000.0f));
  app.add_option("--pitch", o.pitch_deg, "camera pitch, degrees (negative looks down)")->check(CLI::Range(-89.0f, 89.0f));
  app.add_option("--yaw", o.yaw_deg, "camera yaw, degrees (positive turns left)");
  app.add_option("--camera-x", o.camera_x_m, "camera position along x, world metres (default 0)")->check(CLI::Range(-1e6f, 1e6f));
  app.add_option("--camera-z", o.camera_z_m, "camera position along z, world metres (default 0)")->check(CLI::Range(-1e6f, 1e6f));
}

bool parse_size(const std::string& text, int& width, int& height, std::string& error) {
  char tail = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &tail) != 2 || width <= 0 || height <= 0 ||
      width > 16384 || height > 16384) {
    error = "--size must be WIDTHxHEIGHT, each 1..16384, got '" + text + "'";
    return false;
  }
  return true;
}

}  // namespace ocean::viewer
