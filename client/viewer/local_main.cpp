// ocean-viewer-local: renders the synthetic sea with no server, in a window or headless.
//   ocean-viewer-local                                  window (W/S/A/D, drag, F, H, Q/Esc)
//   ocean-viewer-local --headless --frames 120 --size 1280x720 --screenshot out.png --json
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "client/viewer/synthetic_source.hpp"
#include "client/viewer/viewer_flags.hpp"
#include "client/viewer/viewer_loops.hpp"
#include "common/json_writer.hpp"

namespace {

using ocean::common::JsonWriter;
using namespace ocean::viewer;

constexpr int kHeadlessDefaultFrames = 120;

struct LocalOptions : CommonViewerOptions {
  int grid = 64;
  float patch_m = 128.0f;
  bool flat = false;  // no choppy displacement / foam
  double time_step_s = 1.0 / 30.0;
};

SyntheticSourceConfig source_config(const LocalOptions& o) {
  SyntheticSourceConfig config;
  config.sea.n = o.grid;
  config.sea.patch_m = o.patch_m;
  config.sea.choppy = !o.flat;
  config.renderer = o.renderer_desc();
  config.pose = o.camera_pose();
  if (o.headless) config.time_step_s = o.time_step_s;
  return config;
}

std::string headless_json(const LocalOptions& o, const SyntheticSource& source, const LoopResult& r) {
  const ocean::render::DrawStats& s = source.last_stats();
  JsonWriter json;
  json.integer("frames", r.frames).fixed("fps", r.frames / r.seconds, 2);
  json.fixed("cpu_ms_per_frame", source.upload_ms_total() / r.frames, 4);
  json.fixed("synth_ms_per_frame", source.synth_ms_total() / r.frames, 4);
  json.fixed("process_cpu_ms_per_frame", r.process_cpu_ms / r.frames, 2);
  json.integer("width", o.width).integer("height", o.height).integer("grid", o.grid).fixed("patch_m", o.patch_m, 1);
  json.integer("tiles_drawn", s.tiles_drawn).integer("far_blocks", s.far_blocks).integer("tiles_culled", s.tiles_culled);
  json.integer("draw_calls", s.draw_calls).integer("triangles", s.triangles).integers("tiles_per_lod", s.tiles_per_level);
  json.text("gl", r.gl);
  return json.str();
}

std::string window_json(const SyntheticSource& source, const LoopResult& r) {
  JsonWriter json;
  json.integer("frames", r.frames).fixed("fps", r.frames / r.seconds, 2);
  json.fixed("cpu_ms_per_frame", r.frames ? source.upload_ms_total() / r.frames : 0.0, 4);
  return json.str();
}

int run(const LocalOptions& o) {
  auto source = std::make_unique<SyntheticSource>(source_config(o));
  const LoopSettings settings{"ocean-viewer-local", o.width, o.height,
                              o.headless && o.frames <= 0 ? kHeadlessDefaultFrames : o.frames, o.screenshot, o.hud};
  LoopResult result;
  std::string error;
  const int code = o.headless ? run_headless_loop(*source, settings, result, error)
                              : run_window_loop(*source, settings, result, error);
  if (code != 0) {
    std::fprintf(stderr, "ocean-viewer-local: %s\n", error.c_str());
    return code;
  }
  if (o.json) std::printf("%s\n", (o.headless ? headless_json(o, *source, result) : window_json(*source, result)).c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  LocalOptions o;
  CLI::App app{"Render a synthetic animated sea with the ocean GLES 2 renderer (no server)"};
  add_output_flags(app, o, {kHeadlessDefaultFrames, 1000000, "print a JSON summary {frames, fps, cpu_ms_per_frame, ...}"});
  app.add_option("--grid", o.grid, "samples per patch side")->check(CLI::Range(4, 1024));
  app.add_option("--patch", o.patch_m, "patch size, metres")->check(CLI::Range(1.0f, 100000.0f));
  app.add_flag("--flat", o.flat, "no choppy displacement or foam (heights and slopes only)");
  app.add_option("--time-step", o.time_step_s, "headless seconds per frame")->check(CLI::Range(0.0, 10.0));
  add_camera_flags(app, o);
  CLI11_PARSE(app, argc, argv);
  std::string error;
  if (!parse_size(o.size, o.width, o.height, error)) {
    std::fprintf(stderr, "ocean-viewer-local: %s\n", error.c_str());
    return 2;
  }
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ocean-viewer-local: %s\n", e.what());
    return 1;
  }
}
