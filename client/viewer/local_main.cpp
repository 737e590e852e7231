// ocean-viewer-local: renders the synthetic sea with no server, in a window or headless.
//   ocean-viewer-local                                  window (W/S/A/D, drag, F, H, Q/Esc)
//   ocean-viewer-local --headless --frames 120 --size 1280x720 --screenshot out.png --json
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include <sys/resource.h>

#include <CLI/CLI.hpp>

#include "fps_meter.hpp"
#include "client/render/camera_controls.hpp"
#include "client/render/framebuffer_readback.hpp"
#include "client/render/hud_overlay.hpp"
#include "client/render/offscreen_target.hpp"
#include "client/render/renderer.hpp"
#include "client/viewer/app_window.hpp"
#include "client/viewer/headless_context.hpp"
#include "client/viewer/png_file.hpp"
#include "client/viewer/synthetic_sea.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// CPU time of the whole process (all llvmpipe threads included), milliseconds. On a shared
// machine this says what a frame costs even when the wall clock says how busy the machine was.
double process_cpu_ms() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto ms = [](const timeval& t) { return t.tv_sec * 1e3 + t.tv_usec / 1e3; };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

struct Options {
  bool headless = false;
  int frames = 0;  // 0: run until closed (window) / 120 (headless)
  std::string size = "1280x720";
  int width = 1280, height = 720;
  std::string screenshot;
  bool json = false;
  bool hud = false;  // headless only; the window toggles it with H
  int grid = 64;
  float patch_m = 128.0f;
  bool flat = false;  // no choppy displacement / foam
  double time_step_s = 1.0 / 30.0;
  float view_distance_m = 0.0f;
  float lod0_distance_m = 0.0f;
  float eye_height_m = 10.0f;
  float pitch_deg = -6.0f;
  float yaw_deg = 0.0f;
};

struct Scene {
  ocean::viewer::SyntheticSea sea;
  ocean::viewer::SeaFrame frame;
  ocean::render::Renderer renderer;
  ocean::render::HudOverlay hud;
  ocean::render::Camera camera;
  double upload_ms_total = 0.0, synth_ms_total = 0.0;

  explicit Scene(const ocean::viewer::SyntheticSeaParams& p) : sea(p) {}

  void step(double time_s) {
    auto t0 = Clock::now();
    sea.evaluate(time_s, frame);
    synth_ms_total += ms_since(t0);
    t0 = Clock::now();
    const bool choppy = !frame.disp_x.empty();
    renderer.upload_frame(frame.height.data(), frame.slope_x.data(), frame.slope_z.data(),
                          choppy ? frame.disp_x.data() : nullptr, choppy ? frame.disp_z.data() : nullptr,
                          choppy ? frame.jacobian.data() : nullptr);
    upload_ms_total += ms_since(t0);
  }
};

bool setup(Scene& scene, const Options& o, std::string& error) {
  ocean::render::RendererDesc desc;
  desc.view_distance_m = o.view_distance_m;
  desc.lod0_distance_m = o.lod0_distance_m;
  if (!scene.renderer.init(desc) || !scene.renderer.set_grid(o.grid, o.patch_m, o.patch_m)) {
    error = scene.renderer.error();
    return false;
  }
  if (!scene.hud.init(error)) return false;
  scene.camera.position = {0.0, o.eye_height_m, 0.0};
  scene.camera.pitch_rad = o.pitch_deg * 3.14159265f / 180.0f;
  scene.camera.yaw_rad = o.yaw_deg * 3.14159265f / 180.0f;
  scene.camera.far_m = std::max(scene.camera.far_m, scene.renderer.desc().view_distance_m * 1.6f);
  return true;
}

std::string tiles_text(const ocean::render::DrawStats& s) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "tiles %d (lod %d/%d/%d/%d/%d/%d) tris %lld", s.tiles_drawn, s.tiles_per_level[0],
                s.tiles_per_level[1], s.tiles_per_level[2], s.tiles_per_level[3], s.tiles_per_level[4],
                s.tiles_per_level[5], static_cast<long long>(s.triangles));
  return buf;
}

int run_headless(const Options& o, const ocean::viewer::SyntheticSeaParams& sea_params) {
  ocean::viewer::HeadlessContext context;
  std::string error;
  if (!context.create(error)) {
    std::fprintf(stderr, "ocean-viewer-local: headless GL context: %s\n", error.c_str());
    return 1;
  }
  auto scene = std::make_unique<Scene>(sea_params);
  ocean::render::OffscreenTarget target;
  if (!setup(*scene, o, error) || !target.create(o.width, o.height, error)) {
    std::fprintf(stderr, "ocean-viewer-local: %s\n", error.c_str());
    return 1;
  }
  const int frames = o.frames > 0 ? o.frames : 120;
  const auto start = Clock::now();
  const double cpu_start = process_cpu_ms();
  for (int i = 0; i < frames; ++i) {
    scene->step(i * o.time_step_s);
    target.bind();
    scene->renderer.draw(scene->camera, o.width, o.height, i * o.time_step_s);
    if (o.hud) {
      const double elapsed = ms_since(start) / 1000.0;
      scene->hud.draw({elapsed > 0 ? (i + 1) / elapsed : 0.0, 0.0, 0.0, 0.0, "local-synthetic",
                       tiles_text(scene->renderer.last_stats())},
                      o.width, o.height);
    }
    glFinish();  // count the rasterisation in the frame time, as a swap would
  }
  const double seconds = ms_since(start) / 1000.0;
  const double process_ms_per_frame = (process_cpu_ms() - cpu_start) / frames;
  if (!o.screenshot.empty()) {
    const auto pixels = ocean::render::read_framebuffer_rgba(o.width, o.height);
    if (!ocean::viewer::write_png(o.screenshot, o.width, o.height, pixels, error)) {
      std::fprintf(stderr, "ocean-viewer-local: %s\n", error.c_str());
      return 1;
    }
  }
  const ocean::render::DrawStats& s = scene->renderer.last_stats();
  if (o.json) {
    std::printf("{\"frames\": %d, \"fps\": %.2f, \"cpu_ms_per_frame\": %.4f, \"synth_ms_per_frame\": %.4f, "
                "\"process_cpu_ms_per_frame\": %.2f, "
                "\"width\": %d, \"height\": %d, \"grid\": %d, \"patch_m\": %.1f, \"tiles_drawn\": %d, "
                "\"far_blocks\": %d, \"tiles_culled\": %d, \"draw_calls\": %d, \"triangles\": %lld, \"tiles_per_lod\": [%d, %d, %d, %d, %d, %d], "
                "\"gl\": \"%s\"}\n",
                frames, frames / seconds, scene->upload_ms_total / frames, scene->synth_ms_total / frames,
                process_ms_per_frame, o.width,
                o.height, o.grid, o.patch_m, s.tiles_drawn, s.far_blocks, s.tiles_culled, s.draw_calls,
                static_cast<long long>(s.triangles), s.tiles_per_level[0], s.tiles_per_level[1], s.tiles_per_level[2],
                s.tiles_per_level[3], s.tiles_per_level[4], s.tiles_per_level[5], context.description().c_str());
  }
  return 0;
}

int run_window(const Options& o, const ocean::viewer::SyntheticSeaParams& sea_params) {
  ocean::viewer::AppWindow window;
  std::string error;
  if (!window.open({o.width, o.height, "ocean-viewer-local", true}, error)) {
    std::fprintf(stderr, "ocean-viewer-local: %s\n", error.c_str());
    return 1;
  }
  auto scene = std::make_unique<Scene>(sea_params);
  if (!setup(*scene, o, error)) {
    std::fprintf(stderr, "ocean-viewer-local: %s\n", error.c_str());
    return 1;
  }
  const auto start = Clock::now();
  auto last = start;
  ocean::viewer::FpsMeter fps_meter;
  int frame = 0;
  while (!window.should_close() && (o.frames <= 0 || frame < o.frames)) {
    const auto now = Clock::now();
    const double dt = std::chrono::duration<double>(now - last).count();
    last = now;
    const double fps = fps_meter.tick(std::chrono::duration<double>(now - start).count());
    ocean::render::apply_fly_input(scene->camera, window.poll(), dt);
    const double t = std::chrono::duration<double>(now - start).count();
    scene->step(t);
    int w = 0, h = 0;
    window.framebuffer_size(w, h);
    scene->renderer.draw(scene->camera, w, h, t);
    if (window.hud_visible())
      scene->hud.draw({fps, 0.0, 0.0, 0.0, "local-synthetic", tiles_text(scene->renderer.last_stats())}, w, h);
    ++frame;
    if (!o.screenshot.empty() && o.frames > 0 && frame == o.frames) {
      if (!ocean::viewer::write_png(o.screenshot, w, h, ocean::render::read_framebuffer_rgba(w, h), error))
        std::fprintf(stderr, "ocean-viewer-local: %s\n", error.c_str());
    }
    window.swap();
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (o.json)
    std::printf("{\"frames\": %d, \"fps\": %.2f, \"cpu_ms_per_frame\": %.4f}\n", frame, frame / seconds,
                frame ? scene->upload_ms_total / frame : 0.0);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"Render a synthetic animated sea with the ocean GLES 2 renderer (no server)"};
  app.add_flag("--headless", o.headless, "render off-screen through EGL, no window");
  app.add_option("--frames", o.frames, "frames to render, then exit (headless default 120)")->check(CLI::Range(0, 1000000));
  app.add_option("--size", o.size, "WIDTHxHEIGHT in pixels");
  app.add_option("--screenshot", o.screenshot, "write the last frame to this PNG");
  app.add_flag("--json", o.json, "print a JSON summary {frames, fps, cpu_ms_per_frame, ...}");
  app.add_flag("--hud", o.hud, "draw the HUD in headless mode too");
  app.add_option("--grid", o.grid, "samples per patch side")->check(CLI::Range(4, 1024));
  app.add_option("--patch", o.patch_m, "patch size, metres")->check(CLI::Range(1.0f, 100000.0f));
  app.add_flag("--flat", o.flat, "no choppy displacement or foam (heights and slopes only)");
  app.add_option("--time-step", o.time_step_s, "headless seconds per frame")->check(CLI::Range(0.0, 10.0));
  app.add_option("--view-distance", o.view_distance_m, "metres to draw tiles out to (0 = renderer default)")
      ->check(CLI::Range(0.0f, 100000.0f));
  app.add_option("--lod0", o.lod0_distance_m, "full-detail radius, metres (0 = renderer default)")
      ->check(CLI::Range(0.0f, 100000.0f));
  app.add_option("--eye-height", o.eye_height_m, "camera height above sea level, metres")->check(CLI::Range(1.0f, 10000.0f));
  app.add_option("--pitch", o.pitch_deg, "camera pitch, degrees (negative looks down)")->check(CLI::Range(-89.0f, 89.0f));
  app.add_option("--yaw", o.yaw_deg, "camera yaw, degrees (positive turns left)");
  CLI11_PARSE(app, argc, argv);
  if (std::sscanf(o.size.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width <= 0 || o.height <= 0 ||
      o.width > 16384 || o.height > 16384) {
    std::fprintf(stderr, "ocean-viewer-local: --size must be WIDTHxHEIGHT, each 1..16384, got '%s'\n", o.size.c_str());
    return 2;
  }
  ocean::viewer::SyntheticSeaParams sea;
  sea.n = o.grid;
  sea.patch_m = o.patch_m;
  sea.choppy = !o.flat;
  try {
    return o.headless ? run_headless(o, sea) : run_window(o, sea);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ocean-viewer-local: %s\n", e.what());
    return 1;
  }
}
